// Configuration: activation fields, natural strains given along the rods.
#include <core/configuration.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    /// The bending and twisting part of an integral of an activation field.
    Vector3
    bending_part(const Eigen::Vector4d &integral)
    {
      return integral.head<3>();
    }
  } // namespace

  void
  Configuration::start_activation()
  {
    const auto &rods           = network->rods();
    activation.hinge_geometric = hinge_natural_strains;
    activation.hinge_fixed.assign(hinge_refs.size(), Vector3::Zero());
    activation.hinge_ramped = activation.hinge_fixed;
    activation.junction_fixed.assign(junction_refs.size(), Vector3::Zero());
    activation.junction_ramped = activation.junction_fixed;
    activation.junction_now    = activation.junction_fixed;
    activation.segment_fixed.assign(rest_lengths.size(), 0.);
    activation.segment_ramped = activation.segment_fixed;
    activation.segment_now    = activation.segment_fixed;
    activation.rod_hinges.assign(rods.size(), {});
    activation.rod_junctions.assign(rods.size(), {});
    activation.cell_position.assign(rest_lengths.size(), 0);
    for (unsigned int h = 0; h < layout->hinges().size(); ++h)
      activation.rod_hinges[layout->hinges()[h].rod].push_back(h);
    for (unsigned int e = 0; e < layout->junctions().size(); ++e)
      activation.rod_junctions[layout->junctions()[e].rod].push_back(e);
    for (const Rod &rod : rods)
      for (unsigned int j = 0; j < rod.segments.size(); ++j)
        activation.cell_position[rod.segments[j]] = j;
  }


  std::vector<double>
  Configuration::vertex_arc_lengths(const unsigned int rod) const
  {
    const std::vector<unsigned int> &cells = network->rods()[rod].segments;
    std::vector<double>              t(cells.size() + 1, 0.);
    for (unsigned int j = 0; j < cells.size(); ++j)
      t[j + 1] = t[j] + rest_lengths[cells[j]];
    return t;
  }


  void
  Configuration::add_activation(const unsigned int     rod,
                                const ActivationField &field,
                                const bool             ramped)
  {
    if (network->rods()[rod].developable)
      throw std::invalid_argument(
        "rod " + std::to_string(rod) +
        " is a developable ribbon, straight and flat when unstressed: it "
        "takes no activation field");
    if (activation.empty())
      start_activation();
    const std::vector<double> t = vertex_arc_lengths(rod);
    const auto &p = activation.cell_position; // a cell's place in its rod
    std::vector<Vector3> &hinges =
      ramped ? activation.hinge_ramped : activation.hinge_fixed;
    std::vector<Vector3> &junctions =
      ramped ? activation.junction_ramped : activation.junction_fixed;
    std::vector<double> &segments =
      ramped ? activation.segment_ramped : activation.segment_fixed;

    // A hinge's Voronoi cell: the second half of its previous segment and
    // the first half of its next one (across the closure of a ring too).
    for (const unsigned int h : activation.rod_hinges[rod])
      {
        const HingeStencil &hinge = layout->hinges()[h];
        const unsigned int  prev  = p[hinge.segment_prev] + 1;
        const unsigned int  next  = p[hinge.segment_next];
        hinges[h] += bending_part(
          field(t[prev] - 0.5 * rest_lengths[hinge.segment_prev], t[prev]) +
          field(t[next], t[next] + 0.5 * rest_lengths[hinge.segment_next]));
      }
    // A junction element covers the half of its segment next to the
    // junction (junction_voronoi_length()).
    for (const unsigned int e : activation.rod_junctions[rod])
      {
        const JunctionStencil &element = layout->junctions()[e];
        const unsigned int     j       = p[element.segment];
        const double           half    = 0.5 * rest_lengths[element.segment];
        junctions[e] +=
          bending_part(element.ghost_first ? field(t[j], t[j] + half) :
                                             field(t[j + 1] - half, t[j + 1]));
      }
    const Rod &whole = network->rods()[rod];
    for (unsigned int j = 0; j < whole.segments.size(); ++j)
      {
        const unsigned int cell = whole.segments[j];
        const double       eigenstrain =
          field(t[j], t[j + 1])[3] / rest_lengths[cell];
        // The length constraint of an inextensible segment (and the
        // ribbon's) would ignore it: refused, not dropped.
        if (eigenstrain != 0. && whole.inextensible)
          throw std::invalid_argument(
            "rod " + std::to_string(rod) +
            " is inextensible: an axial eigenstrain cannot change its length");
        segments[cell] += eigenstrain;
      }

    const double factor = activation.factor;
    activation.factor   = std::nan("");
    follow_activation(factor);
  }


  void
  Configuration::follow_activation(const double factor)
  {
    if (activation.empty() || factor == activation.factor)
      return;
    for (unsigned int h = 0; h < hinge_natural_strains.size(); ++h)
      hinge_natural_strains[h] = activation.hinge_geometric[h] +
                                 activation.hinge_fixed[h] +
                                 factor * activation.hinge_ramped[h];
    for (unsigned int e = 0; e < activation.junction_now.size(); ++e)
      activation.junction_now[e] =
        activation.junction_fixed[e] + factor * activation.junction_ramped[e];
    for (unsigned int c = 0; c < activation.segment_now.size(); ++c)
      activation.segment_now[c] =
        activation.segment_fixed[c] + factor * activation.segment_ramped[c];
    activation.factor = factor;
  }
} // namespace rodnet
