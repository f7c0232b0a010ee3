#include <base/phase_times.h>
#include <core/every_entry.h>
#include <elements/stretch_kernel.h>
#include <solvers/checks/strain_range.h>

#include <algorithm>
#include <cstdio>

namespace rodnet
{
  namespace
  {
    /// Position of @p value in @p list (rod vertices or segments).
    unsigned int
    index_of(const std::vector<unsigned int> &list, const unsigned int value)
    {
      return std::find(list.begin(), list.end(), value) - list.begin();
    }
  } // namespace

  StrainMonitor::StrainMonitor(const SolvableModel &model,
                               const StrainLimits  &limits)
      : model(model)
      , limits(limits)
  {
    const VectorType zero = model.create_vector();
    const EveryEntry undeformed(zero);
    const auto      &hinges = model.layout().hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      undeformed_curvature.push_back(
        model.hinge_kernel(hinges[h].rod)
          .strains(model.configuration().hinge_dofs(*undeformed, hinges[h]),
                   model.configuration().hinge_reference(h)));
  }

  StrainRange
  StrainMonitor::evaluate(const VectorType &state) const
  {
    const phase_times::Scope phase(phase_times::Phase::checks);
    const EveryEntry         every_entry(state);
    const VectorType        &u             = *every_entry;
    const Configuration     &configuration = model.configuration();
    StrainRange              range;
    for (const SegmentStencil &s : model.layout().segments())
      {
        StretchStrain stretch;
        evaluate_stretch(configuration.segment_dofs(u, s),
                         configuration.rest_length(s.cell),
                         stretch,
                         false);
        // NaN compares false: a non-finite strain is kept, and out of range.
        if (!(std::abs(stretch.strain) <= std::abs(range.axial)))
          {
            range.axial     = stretch.strain;
            range.axial_rod = s.rod;
            range.axial_segment =
              index_of(model.network().rods()[s.rod].segments, s.cell);
          }
      }

    const auto &hinges = model.layout().hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      {
        const unsigned int rod = hinges[h].rod;
        if (rod >= limits.fiber_distance.size() ||
            !std::isfinite(limits.fiber_distance[rod][0]))
          continue;
        const Vector3 kappa =
          model.hinge_kernel(rod).strains(configuration.hinge_dofs(u,
                                                                   hinges[h]),
                                          configuration.hinge_reference(h));
        const Vector3 change = kappa - undeformed_curvature[h];
        const double  strain =
          std::hypot(limits.fiber_distance[rod][0] * change[0],
                     limits.fiber_distance[rod][1] * change[1]) /
          configuration.voronoi_length(h);
        if (std::isnan(range.bending) || !(strain <= range.bending))
          {
            range.bending     = strain;
            range.bending_rod = rod;
            range.bending_vertex =
              index_of(model.network().rods()[rod].vertices,
                       hinges[h].vertices[1]);
          }
      }
    range.in_range =
      std::abs(range.axial) <= limits.axial &&
      (std::isnan(range.bending) || range.bending <= limits.bending);
    return range;
  }

  std::string
  StrainMonitor::warning(const StrainRange &range) const
  {
    if (range.in_range)
      return "";
    char        text[200];
    std::string line = "warning: strain past the range of the rod model:";
    if (!(std::abs(range.axial) <= limits.axial))
      {
        std::snprintf(text,
                      sizeof(text),
                      " axial strain %.3g at rod %u segment %u (limit %g);",
                      range.axial,
                      range.axial_rod,
                      range.axial_segment,
                      limits.axial);
        line += text;
      }
    if (!std::isnan(range.bending) && !(range.bending <= limits.bending))
      {
        std::snprintf(text,
                      sizeof(text),
                      " bending strain %.3g at rod %u vertex %u (limit %g);",
                      range.bending,
                      range.bending_rod,
                      range.bending_vertex,
                      limits.bending);
        line += text;
      }
    line.back() = '.';
    return line + " Small strains are what the model is meant for: check the "
                  "loads, prescribed displacements and units";
  }
} // namespace rodnet
