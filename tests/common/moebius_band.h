// The elastic Moebius band of Wunderlich's developable ribbon model, as
// tests/validation/moebius_band.cc and bench/moebius_free_band.cc build it:
// - the clamped band of scenes/moebius_band.prm (the paper's closure: an open
//   strip whose last segment lies on its first, one clamp turned by pi);
// - the free band: a closed ring with a half turn of its frame, held
//   against rigid motions only, started from the clamped band's state;
// - a damped Newton for the free band (no load to continue in) and the
//   stability count on its constraint manifold.
#ifndef RODNET_TESTS_COMMON_MOEBIUS_BAND_H
#define RODNET_TESTS_COMMON_MOEBIUS_BAND_H

#include <deal.II/base/parameter_handler.h>

#include <core/rod_model.h>
#include <io/scene.h>
#include <materials/wunderlich_ribbon.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/newton/tangent_factorization.h>
#include <solvers/stability/stability.h>

#include "ribbon_dofs.h"
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet::moebius
{
  /// A band's state: centreline, strains, generatrix slopes, frames.
  struct Band
  {
    double               energy = 0;
    std::vector<Vector3> centreline; ///< one vertex per segment
    /// Per hinge (s = i l): the integrated strains and eta.
    std::vector<Vector3> strains;
    std::vector<double>  etas;
    double               length_error = 0;
    double               segment      = 0; ///< l
    /// Per segment: the material frame's d1.
    std::vector<Vector3> d1;
    /// The hinge that closes a band with a half turn (eta changes sign
    /// between it and the next hinge), or none.
    unsigned int flipped_hinge = static_cast<unsigned int>(-1);
  };

  /// The shipped scene with @p segments segments (@p segments - 1 of them
  /// around the circle, the last one on the first) and the ribbon's
  /// entries @p material (empty: the scene's).
  inline std::string
  scene_text(const unsigned int segments, const std::string &material = "")
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/moebius_band.prm");
    std::stringstream text;
    text << file.rdbuf();
    const double       delta = 360. / (segments - 1);
    std::ostringstream geometry;
    geometry.precision(17);
    geometry << "\nsubsection Geometry\n  set Segments = " << segments
             << "\n  set Start angle = " << -delta / 2
             << "\n  set End angle = " << 360 + delta / 2 << "\nend\n";
    if (!material.empty())
      geometry << "subsection Material\n  subsection wunderlich ribbon\n"
               << material << "  end\nend\n";
    return text.str() + geometry.str();
  }

  /// The strains, etas, multipliers, frames and energy of @p model's
  /// state @p u; the centreline from its first @p vertices vertices.
  inline Band
  band_state(const RodModel    &model,
             const VectorType  &u,
             const unsigned int vertices)
  {
    Band                 band;
    const Configuration &config = model.configuration();
    const DofLayout     &layout = model.layout();
    const Rod           &rod    = model.network().rods()[0];
    band.energy                 = model.elastic_energy(u, 1.0);
    for (unsigned int k = 0; k < vertices; ++k)
      band.centreline.push_back(model.position(u, rod.vertices[k]));
    for (const unsigned int cell : rod.segments)
      band.length_error =
        std::max(band.length_error,
                 std::abs(config.segment_length(DofValues(u), cell) /
                            config.rest_length(cell) -
                          1));
    band.segment = config.rest_length(rod.segments[0]);
    for (unsigned int h = 0; h < layout.hinges().size(); ++h)
      {
        band.strains.push_back(model.hinge_kernel(0).strains(
          config.hinge_dofs(DofValues(u), layout.hinges()[h]),
          config.hinge_reference(h)));
        band.etas.push_back(u[rodnet::testing::ribbon_dof(model, h, 0)]);
        if (config.closes_with_a_flip(layout.hinges()[h]))
          band.flipped_hinge = h;
      }
    for (const unsigned int cell : rod.segments)
      band.d1.push_back(
        config.director_frame(u, cell)._transformVector(Vector3::UnitX()));
    return band;
  }

  /// The clamped band of the shipped scene with @p segments segments at the
  /// end of its continuation (the clamp turned by pi); throws if the
  /// continuation stops before.
  inline Band
  solve_clamped(const unsigned int segments, const std::string &material = "")
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(scene_text(segments, material));
    const Scene           scene(prm);
    const auto            model = scene.build_model();
    ArclengthContinuation solver(*model, scene.continuation);
    VectorType            u = model->create_vector();
    VectorType            last;
    double                last_lambda = 0;
    solver.run(u,
               [&](const ArclengthContinuation::StepInfo &info,
                   const VectorType                      &solution) {
                 last        = solution;
                 last_lambda = info.load_factor;
               });
    if (last_lambda != 1.0)
      throw std::runtime_error("the clamped Moebius band's continuation "
                               "stopped at load factor " +
                               std::to_string(last_lambda));
    // Vertex N - 1 lies on vertex 0, vertex N on vertex 1; the last segment
    // is the first one again.
    const Rod &rod  = model->network().rods()[0];
    Band       band = band_state(*model, last, rod.vertices.size() - 2);
    band.d1.pop_back();
    return band;
  }

  /// The closed ring of full width @p width and plate modulus @p modulus
  /// through the centreline @p points, with a half turn of its frame, held
  /// against rigid motions by a statically determinate support (vertex 0
  /// whole, a third of the way in y and z, two thirds in z): the free band.
  /// eta' is coupled across the closure by @p coupling
  /// (Rod::closure_coupling).
  inline std::unique_ptr<RodModel>
  free_band(const std::vector<Vector3> &points,
            const double                width,
            const double                modulus  = 1,
            const double                coupling = 1)
  {
    const unsigned int m       = points.size();
    auto               network = std::make_unique<RodNetwork>();
    network->add_rod(points,
                     true,
                     Vector3::UnitZ(),
                     "simple",
                     NaturalShape::straight);
    network->create_triangulation();
    network->set_frame_half_turns(0, 1);
    network->set_closure_coupling(0, coupling);
    // D = Y h^3 / 12 with nu = 0 and h = w / 2.
    const double thickness = width / 2;
    auto         model     = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
                    std::make_shared<WunderlichRibbon>(
          RibbonConstants{12 * modulus / std::pow(thickness, 3),
                          0.0,
                          width,
                          thickness})});
    const Rod &rod = model->network().rods()[0];
    model->fix_components("origin", rod.vertices[0], {{true, true, true}});
    model->fix_components("axis", rod.vertices[m / 3], {{false, true, true}});
    model->fix_components("turn",
                          rod.vertices[2 * m / 3],
                          {{false, false, true}});
    model->finalize();
    return model;
  }

  /// The free band's DoF vector for @p model (built by free_band() through
  /// the clamped band @p band's centreline) in @p band's state: its frames
  /// by the twists, its etas (the ring's hinge k sits at vertex k, the
  /// clamped band's hinge k - 1 at its vertex k, its last at vertex 0).
  inline VectorType
  free_state(const RodModel &model, const Band &band)
  {
    VectorType           u      = model.create_vector();
    const unsigned int   m      = band.centreline.size();
    const Configuration &config = model.configuration();
    const DofLayout     &layout = model.layout();
    const Rod           &rod    = model.network().rods()[0];
    for (unsigned int j = 0; j < m; ++j)
      {
        const unsigned int cell  = rod.segments[j];
        const Quaternion   frame = config.director_frame(u, cell);
        const Vector3      t     = frame._transformVector(Vector3::UnitZ());
        const Vector3      d1    = frame._transformVector(Vector3::UnitX());
        u[layout.twist_dof(cell)] =
          std::atan2(d1.cross(band.d1[j]).dot(t), d1.dot(band.d1[j]));
      }
    for (unsigned int h = 0; h < m; ++h)
      u[rodnet::testing::ribbon_dof(model, h, 0)] = band.etas[(h + m - 1) % m];
    return u;
  }

  /// What newton() reached.
  struct NewtonResult
  {
    bool         converged  = false;
    unsigned int iterations = 0;
    double       residual   = 0;
    /// Negative eigenvalues on the constraint manifold (when converged).
    unsigned int negative_eigenvalues = 0;
  };

  /// Newton on the free band's Lagrangian from @p u, the step halved where
  /// the residual does not fall (or the state leaves the model), until
  /// |r| < @p relative |r_0| or |r| < @p absolute, in at most
  /// @p max_iterations iterations.
  inline NewtonResult
  newton(const RodModel    &model,
         VectorType        &u,
         const double       relative,
         const double       absolute,
         const unsigned int max_iterations = 100)
  {
    VectorType r = model.create_vector(), du = model.create_vector();
    MatrixType k;
    model.initialize_matrix(k);
    auto         solver = TangentFactorization::create(k, "auto");
    double       norm   = std::numeric_limits<double>::infinity();
    double       first  = 0;
    NewtonResult result;
    for (; result.iterations <= max_iterations; ++result.iterations)
      {
        try
          {
            model.assemble(u, 1.0, &r, &k, true);
          }
        catch (const std::runtime_error &)
          {
            return result; // the start lies outside the model
          }
        result.residual = r.l2_norm();
        if (result.iterations == 0)
          first = result.residual;
        if (result.residual < relative * first || result.residual < absolute)
          {
            const ConstrainedFactorization
              factorization(k, model.constraints(), 0, model.multiplier_dofs());
            result.converged            = true;
            result.negative_eigenvalues = factorization.inertia().negative;
            return result;
          }
        if (result.iterations == max_iterations)
          break;
        solver->factorize();
        solver->solve(r, du);
        bool moved = false;
        for (double step = 1; step > 1e-9 && !moved; step /= 2)
          {
            VectorType trial = u;
            trial.add(-step, du);
            try
              {
                VectorType rt = model.create_vector();
                model.assemble(trial, 1.0, &rt, nullptr, true);
                if (rt.l2_norm() < norm)
                  {
                    u     = trial;
                    norm  = rt.l2_norm();
                    moved = true;
                  }
              }
            catch (const std::runtime_error &)
              {
                // Past the edge singularity or a flipped tangent: shorter.
              }
          }
        if (!moved)
          break;
      }
    return result;
  }

  /// The largest |eta' w / 2| over the free band @p band of full width
  /// @p width (central differences, eta's sign change after the closing
  /// hinge): 1 on the edge singularity, where two generatrices meet on the
  /// strip's edge.
  inline double
  edge_ratio(const Band &band, const double width)
  {
    const unsigned int m = band.etas.size();
    // eta of hinge k as its neighbour h measures it.
    const auto eta = [&](const unsigned int k, const unsigned int h) {
      const bool across = (h == band.flipped_hinge && k == (h + 1) % m) ||
                          (k == band.flipped_hinge && h == (k + 1) % m);
      return across ? -band.etas[k] : band.etas[k];
    };
    double largest = 0;
    for (unsigned int h = 0; h < m; ++h)
      largest =
        std::max(largest,
                 std::abs(eta((h + 1) % m, h) - eta((h + m - 1) % m, h)) /
                   (2 * band.segment) * width / 2);
    return largest;
  }
} // namespace rodnet::moebius

#endif
