#include <core/every_entry.h>
#include <elements/junction_moment.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/stability/stability.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>

namespace rodnet
{
  namespace
  {
    using Kind = DofRoles::Kind;

    std::string
    scientific(const double value)
    {
      char text[32];
      std::snprintf(text, sizeof(text), "%.2g", value);
      return text;
    }

    /// Local values of a (serial) Trilinos vector.
    const double *
    values_of(const VectorType &v)
    {
      return v.trilinos_vector()[0];
    }
  } // namespace

  ResidualCriterion::ResidualCriterion(const SolvableModel &model)
      : model(model)
      , dof_roles(model)
  {
    for (global_dof_index d = 0; d < dof_roles.n_dofs(); ++d)
      if (dof_roles.kind(d) == Kind::twist &&
          model.constraints().is_constrained(d))
        fixed_twists.push_back(d);
  }

  Eigen::Vector4d
  ResidualCriterion::junction_quaternion(const VectorType  &u,
                                         const unsigned int junction) const
  {
    // Quaternion DoFs store q - (1, 0, 0, 0).
    Eigen::Vector4d q;
    for (unsigned int c = 0; c < 4; ++c)
      q[c] = u[model.layout().rotation_dof(junction, c)] + (c == 0);
    return q;
  }

  Vector3
  ResidualCriterion::junction_moment(const VectorType      &u,
                                     const unsigned int     junction,
                                     const Eigen::Vector4d &g) const
  {
    const Eigen::Vector4d q = junction_quaternion(u, junction);
    // Functions of q / |q| have g . q = 0: the gauge row, fixed (and so
    // zero in a constrained residual), follows from the other three.
    Eigen::Vector4d complete = g;
    complete[0]              = -q.tail<3>().dot(g.tail<3>()) / q[0];
    return spatial_moment(q, complete);
  }

  ResidualParts
  ResidualCriterion::norms(const VectorType &state,
                           const VectorType &residual) const
  {
    const EveryEntry u(state), r(residual);
    const auto      &constraints = model.constraints();
    const double    *values      = values_of(*r);
    double           force2 = 0, moment2 = 0;
    for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
      if (!constraints.is_constrained(i))
        {
          // A multiplier's row is its constraint scaled to a force
          // (InextensibilityFamily).
          if (dof_roles.kind(i) == Kind::position ||
              dof_roles.kind(i) == Kind::multiplier)
            force2 += values[i] * values[i];
          else if (dof_roles.kind(i) == Kind::twist ||
                   dof_roles.kind(i) == Kind::shape)
            // A shape DoF's row, like a twist's, is an energy per radian.
            moment2 += values[i] * values[i];
        }
    const DofLayout &layout = model.layout();
    for (unsigned int j = 0; j < model.network().junctions().size(); ++j)
      if (layout.has_rotation_dofs(j))
        {
          Eigen::Vector4d g = Eigen::Vector4d::Zero();
          for (unsigned int c = 1; c < 4; ++c)
            if (!constraints.is_constrained(layout.rotation_dof(j, c)))
              g[c] = values[layout.rotation_dof(j, c)];
          if (g.squaredNorm() > 0)
            moment2 += junction_moment(*u, j, g).squaredNorm();
        }
    return {std::sqrt(force2), std::sqrt(moment2)};
  }

  ResidualCriterion::LoadParts
  ResidualCriterion::load_parts(const VectorType &u,
                                const double      load_factor,
                                const VectorType *extra_force,
                                const VectorType *known_loaded) const
  {
    // Unconstrained residuals: at fixed DoFs they are the reactions, and
    // their change with the loads is the applied generalized force (dead
    // forces and the moments' -lambda M grad theta alike).
    VectorType loaded  = model.create_vector();
    VectorType applied = model.create_vector();
    if (known_loaded != nullptr)
      loaded = *known_loaded;
    else
      model.assemble(u, load_factor, &loaded, nullptr, false, extra_force);
    // At a zero load factor, or one that no load follows, without extra
    // force both are one assembly (a free vibration's every step): its
    // copy gives the same difference.
    if ((load_factor == 0 || !model.potential_follows_load_factor()) &&
        extra_force == nullptr)
      applied = loaded;
    else
      model.assemble(u, 0.0, &applied, nullptr, false);
    applied -= loaded;
    return parts_of(u, *EveryEntry(applied), *EveryEntry(loaded));
  }

  ResidualCriterion::LoadParts
  ResidualCriterion::parts_of(const VectorType &state,
                              const VectorType &applied,
                              const VectorType &loaded) const
  {
    const EveryEntry  every_entry(state);
    const VectorType &u              = *every_entry;
    double            applied_force2 = 0, applied_moment2 = 0;
    for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
      if (dof_roles.kind(i) == Kind::position)
        applied_force2 += applied[i] * applied[i];
      else if (dof_roles.kind(i) == Kind::twist)
        applied_moment2 += applied[i] * applied[i];

    double reaction_force2 = 0, reaction_moment2 = 0;
    add_support_reactions(u, loaded, reaction_force2, reaction_moment2);
    for (const global_dof_index d : fixed_twists)
      reaction_moment2 += loaded[d] * loaded[d];
    add_junction_moments(u, applied, loaded, applied_moment2, reaction_moment2);

    return {{std::sqrt(applied_force2), std::sqrt(applied_moment2)},
            {std::sqrt(reaction_force2), std::sqrt(reaction_moment2)}};
  }

  void
  ResidualCriterion::add_support_reactions(const VectorType &u,
                                           const VectorType &loaded,
                                           double           &force2,
                                           double           &moment2) const
  {
    const DofLayout &layout = model.layout();
    for (const Support &s : model.supports())
      {
        // Net force and moment about the first vertex: a clamp's couple
        // of vertex forces is a moment, not two large forces.
        Vector3       force  = Vector3::Zero();
        Vector3       moment = Vector3::Zero();
        const Vector3 origin =
          model.configuration().position(u, s.vertices.front());
        for (unsigned int k = 0; k < s.vertices.size(); ++k)
          {
            Vector3 f = Vector3::Zero();
            for (unsigned int c = 0; c < 3; ++c)
              if (s.fixed[k][c])
                f[c] = loaded[layout.vertex_dof(s.vertices[k], c)];
            force += f;
            moment +=
              (model.configuration().position(u, s.vertices[k]) - origin)
                .cross(f);
          }
        force2 += force.squaredNorm();
        moment2 += moment.squaredNorm();
      }
  }

  void
  ResidualCriterion::add_junction_moments(const VectorType &u,
                                          const VectorType &applied,
                                          const VectorType &loaded,
                                          double           &applied_moment2,
                                          double &reaction_moment2) const
  {
    const DofLayout &layout    = model.layout();
    const auto      &junctions = model.network().junctions();
    for (unsigned int j = 0; j < junctions.size(); ++j)
      if (layout.has_rotation_dofs(j))
        {
          Eigen::Vector4d g_applied, g_reaction;
          for (unsigned int c = 0; c < 4; ++c)
            {
              g_applied[c]  = applied[layout.rotation_dof(j, c)];
              g_reaction[c] = loaded[layout.rotation_dof(j, c)];
            }
          applied_moment2 += junction_moment(u, j, g_applied).squaredNorm();
          if (junctions[j].kind == JunctionKind::clamped)
            reaction_moment2 += junction_moment(u, j, g_reaction).squaredNorm();
        }
  }

  ResidualParts
  ResidualCriterion::combined(const double force, const double moment) const
  {
    const double length = model.length_scale();
    const double scale  = std::max(force, moment / length);
    return {scale, scale * length};
  }

  ResidualParts
  ResidualCriterion::load_scale(const VectorType &u,
                                const double      load_factor,
                                const VectorType *extra_force) const
  {
    return scale_of(load_parts(u, load_factor, extra_force));
  }

  ResidualParts
  ResidualCriterion::scale_of(const LoadParts &loads) const
  {
    return combined(std::max(loads.applied.force, loads.reactions.force),
                    std::max(loads.applied.moment, loads.reactions.moment));
  }

  ResidualParts
  ResidualCriterion::internal_scale(const VectorType &u,
                                    const double      load_factor) const
  {
    // What each row balances: the stencils' generalized forces on it,
    // without their signs (junction rotations: the moments they stand for).
    std::vector<double> row(dof_roles.n_dofs(), 0.0);
    std::vector<double> junction(model.network().junctions().size(), 0.0);
    const EveryEntry    every_entry(u);
    const StencilState  state{*every_entry,
                             model.configuration(),
                             model.internal_variables(),
                             model.time_step(),
                             model.applied_load_factor(load_factor)};
    const auto         &constraints = model.constraints();
    LocalContribution   local;
    std::map<unsigned int, Eigen::Vector4d> rotations;
    for (const auto &family : model.element_families())
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, local.dofs);
          family->evaluate(s, state, Derivatives::gradient, local);
          rotations.clear();
          for (unsigned int a = 0; a < local.dofs.size(); ++a)
            {
              const global_dof_index d = local.dofs[a];
              if (constraints.is_constrained(d))
                continue;
              if (dof_roles.kind(d) != Kind::quaternion)
                row[d] += std::abs(local.vector[a]);
              else
                {
                  auto [place, added] =
                    rotations.try_emplace(dof_roles.owner(d),
                                          Eigen::Vector4d::Zero());
                  place->second[dof_roles.component(d)] = local.vector[a];
                }
            }
          for (const auto &[j, g] : rotations)
            junction[j] += junction_moment(*every_entry, j, g).norm();
        }
    double force = 0, moment = 0;
    for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
      if (dof_roles.kind(i) == Kind::position ||
          dof_roles.kind(i) == Kind::multiplier)
        force = std::max(force, row[i]);
      else if (dof_roles.kind(i) == Kind::twist ||
               dof_roles.kind(i) == Kind::shape)
        moment = std::max(moment, row[i]);
    for (const double m : junction)
      moment = std::max(moment, m);
    return combined(force, moment);
  }

  ResidualParts
  ResidualCriterion::judging_scale(const VectorType    &u,
                                   const double         load_factor,
                                   const ResidualParts &floor,
                                   const VectorType    *extra_force,
                                   const VectorType    *loaded) const
  {
    const LoadParts     loads = load_parts(u, load_factor, extra_force, loaded);
    const ResidualParts scale = scale_of(loads);
    // Reactions are residuals at fixed rows: within the floor they are
    // rounding, however the supports are placed.
    const bool vanish =
      loads.applied.force == 0 && loads.applied.moment == 0 &&
      combined(loads.reactions.force, loads.reactions.moment).force <=
        combined(floor.force, floor.moment).force;
    if (!vanish)
      return scale;
    const ResidualParts internal = internal_scale(u, load_factor);
    return {std::max(scale.force, internal.force),
            std::max(scale.moment, internal.moment)};
  }

  ResidualParts
  ResidualCriterion::tolerance(const ResidualParts &scale,
                               const ResidualParts &floor,
                               const double         rtol)
  {
    const double tiny = std::numeric_limits<double>::min();
    return {std::max({rtol * scale.force, floor.force, tiny}),
            std::max({rtol * scale.moment, floor.moment, tiny})};
  }

  std::string
  ResidualCriterion::describe(const ResidualParts &norms,
                              const ResidualParts &tolerance)
  {
    char text[160];
    std::snprintf(text,
                  sizeof(text),
                  "force residual %.2e N against a tolerance of %.2e N, "
                  "moment residual %.2e N m against %.2e N m",
                  norms.force,
                  tolerance.force,
                  norms.moment,
                  tolerance.moment);
    return text;
  }

  std::function<bool(const VectorType &, const VectorType &)>
  ResidualCriterion::stall_aware_test(StepTolerance &step,
                                      ResidualParts &reached) const
  {
    return [this, &step, &reached](const VectorType &x, const VectorType &r) {
      reached = norms(x, r);
      if (within(reached, step.tolerance))
        return true;
      const double excess = std::max(reached.force / step.tolerance.force,
                                     reached.moment / step.tolerance.moment);
      // Quadratic convergence more than halves the excess at every
      // iteration; an excess kept over two iterations is a stall.
      const bool stalled =
        step.excess_before_last > 0 && excess > 0.5 * step.excess_before_last;
      step.excess_before_last = step.excess_last;
      step.excess_last        = excess;
      if (!stalled || step.measured_again || excess > 1e3)
        return false;
      step.measured_again = true;
      const RoundoffNoise here =
        roundoff_noise(x, step.load_factor, step.extra_force);
      step.noise.floor.force =
        std::max(step.noise.floor.force, here.floor.force);
      step.noise.floor.moment =
        std::max(step.noise.floor.moment, here.floor.moment);
      step.noise.rows = here.rows;
      step.tolerance  = tolerance(step.scale, step.noise.floor, step.rtol);
      return within(reached, step.tolerance);
    };
  }

  RoundoffNoise
  ResidualCriterion::roundoff_noise(const VectorType &u,
                                    const double      load_factor,
                                    const VectorType *extra_force) const
  {
    // Every DoF is known to eps |x_j| at best: a position's DoF is the
    // displacement u from X, rounded to |u|, and X + u to |X + u| (a rod
    // that rolls back to where it started knows its tip to eps |u|, not
    // to eps |X + u|); angles and quaternions are of order one. Newton's
    // iterates carry that rounding, and the residual moves with it (through
    // the tangent, and through the rounding of the strains computed from
    // the positions, eps |x| / l per segment, which the tangent does not
    // see at a straight rod's twist). Two random perturbations of that size
    // measure what residual Newton can reach.
    VectorType reference = model.create_vector();
    VectorType perturbed = model.create_vector();
    model.assemble(u, load_factor, &reference, nullptr, true, extra_force);
    const EveryEntry every_entry(u);
    const double    *values = values_of(*every_entry);
    std::mt19937     random(1); // a fixed sequence, so that runs repeat
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    RoundoffNoise                          noise;
    for (unsigned int realization = 0; realization < 2; ++realization)
      {
        VectorType moved = *every_entry;
        for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
          {
            // Per coordinate: an exact zero (a rod along an axis) rounds
            // to nothing, and a floor from the vertex's distance would
            // accept a real transverse residual as noise.
            // A multiplier is a force over a large scale (its value is
            // small, and known relative to itself).
            const double magnitude =
              dof_roles.kind(i) == Kind::position ?
                std::max(std::abs(values[i]),
                         std::abs(model.network().vertex(dof_roles.owner(
                                    i))[dof_roles.component(i)] +
                                  values[i])) :
              dof_roles.kind(i) == Kind::multiplier ? std::abs(values[i]) :
                                                      1 + std::abs(values[i]);
            if (dof_roles.kind(i) != Kind::inert)
              moved[i] += std::numeric_limits<double>::epsilon() * magnitude *
                          unit(random);
          }
        moved.compress(dealii::VectorOperation::add);
        model
          .assemble(moved, load_factor, &perturbed, nullptr, true, extra_force);
        perturbed -= reference;
        const ResidualParts measured = norms(u, perturbed);
        noise.floor.force  = std::max(noise.floor.force, 2 * measured.force);
        noise.floor.moment = std::max(noise.floor.moment, 2 * measured.moment);
        if (noise.rows.empty())
          {
            const EveryEntry rows(perturbed);
            noise.rows.assign(values_of(*rows),
                              values_of(*rows) + dof_roles.n_dofs());
          }
      }
    return noise;
  }

  double
  ResidualCriterion::state_change(const std::vector<double> &change) const
  {
    double largest = 0;
    for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
      switch (dof_roles.kind(i))
        {
          case Kind::position:
            largest =
              std::max(largest, std::abs(change[i]) / model.length_scale());
            break;
          case Kind::twist:
          case Kind::shape:
            largest = std::max(largest, std::abs(change[i]));
            break;
          case Kind::quaternion:
            // q = (1, v) turns by 2 |v| for small v.
            largest = std::max(largest, 2 * std::abs(change[i]));
            break;
          case Kind::multiplier:
          case Kind::inert:
            break;
        }
    return largest;
  }

  std::string
  ResidualCriterion::rounding_hint(const MatrixType    &tangent,
                                   const RoundoffNoise &noise,
                                   const ResidualParts &scale) const
  {
    // The part whose floor weighs most against its loads, and its row
    // where the noise is largest.
    const auto ratio = [](const double floor, const double loads) {
      return loads > 0 ? floor / loads : floor;
    };
    const bool force = ratio(noise.floor.force, scale.force) >=
                       ratio(noise.floor.moment, scale.moment);
    global_dof_index worst = 0;
    for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
      {
        const bool in_part = force ? dof_roles.kind(i) == Kind::position :
                                     (dof_roles.kind(i) == Kind::twist ||
                                      dof_roles.kind(i) == Kind::shape ||
                                      dof_roles.kind(i) == Kind::quaternion);
        if (in_part && std::abs(noise.rows[i]) > std::abs(noise.rows[worst]))
          worst = i;
      }
    VectorType owned_diagonal = model.create_vector();
    for (const global_dof_index i : owned_diagonal.locally_owned_elements())
      owned_diagonal[i] = tangent.diag_element(i);
    owned_diagonal.compress(dealii::VectorOperation::insert);
    const EveryEntry    every_entry(owned_diagonal);
    const VectorType   &tangent_diagonal = *every_entry;
    std::vector<double> diagonal;
    for (global_dof_index i = 0; i < dof_roles.n_dofs(); ++i)
      if (dof_roles.kind(i) != Kind::inert &&
          !model.constraints().is_constrained(i))
        diagonal.push_back(std::abs(tangent_diagonal[i]));
    std::nth_element(diagonal.begin(),
                     diagonal.begin() + diagonal.size() / 2,
                     diagonal.end());
    const double median    = diagonal[diagonal.size() / 2];
    const double stiffness = std::abs(tangent_diagonal[worst]);

    const std::string unit = force ? " N" : " N m";
    return std::string("rounding limits the ") + (force ? "force" : "moment") +
           " residual to " +
           scientific(force ? noise.floor.force : noise.floor.moment) + unit +
           " against loads of " +
           scientific(force ? scale.force : scale.moment) + unit +
           "; the noisiest rows, at " + dof_roles.describe(worst) +
           ", have a stiffness K_ii = " + scientific(stiffness) +
           (dof_roles.kind(worst) == Kind::position ? " N/m" : " N m") + ", " +
           scientific(stiffness / median) +
           " times the median of the tangent's diagonal: use fewer, longer "
           "segments there or a smaller EA";
  }
} // namespace rodnet
