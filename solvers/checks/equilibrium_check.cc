#include <base/phase_times.h>
#include <core/every_entry.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/equilibrium_factorization.h>
#include <solvers/checks/free_motions.h>
#include <solvers/solver_failure.h>
#include <solvers/stability/stability.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <sstream>

namespace rodnet
{
  namespace
  {
    /// The symmetry modes M of a model at a state (symmetry_modes()),
    /// K^-1 M and S = M^T K^-1 M from a factorization of its tangent K.
    struct SymmetryBorder
    {
      std::vector<VectorType> modes;
      std::vector<VectorType> solved;
      Eigen::MatrixXd         s;
    };

    SymmetryBorder
    symmetry_border(const SolvableModel            &model,
                    const VectorType               &u,
                    const double                    load_factor,
                    const EquilibriumFactorization &factorization)
    {
      SymmetryBorder border;
      border.modes = symmetry_modes(model, u, load_factor);
      for (const VectorType &mode : border.modes)
        {
          border.solved.push_back(model.create_vector());
          factorization.solve(mode, border.solved.back());
        }
      const unsigned int k = border.modes.size();
      border.s.resize(k, k);
      for (unsigned int a = 0; a < k; ++a)
        for (unsigned int b = 0; b < k; ++b)
          border.s(a, b) = border.modes[a] * border.solved[b];
      border.s = (border.s + border.s.transpose()) / 2;
      return border;
    }

    /**
     * The negative eigenvalues of the tangent of @p factorization (with
     * @p inertia) on the complement of the symmetry modes of @p model at
     * (@p u, @p load_factor). For the bordered matrix B = [K M; M^T 0]
     * with the k modes M, Haynsworth's inertia additivity gives
     * In(B) = In(K) + In(-M^T K^-1 M), and B has the inertia of K on the
     * complement of M plus k positive and k negative eigenvalues: so
     * n_-(K on M-perp) = n_-(K) + n_+(M^T K^-1 M) - k. A mode's own
     * eigenvalue is rounding of either sign; this count is free of it.
     * Only where the plain count has a negative eigenvalue to remove, and
     * no zero pivot (where K^-1 M does not exist).
     */
    unsigned int
    negative_beside_symmetries(const SolvableModel            &model,
                               const VectorType               &u,
                               const double                    load_factor,
                               const EquilibriumFactorization &factorization,
                               const Inertia                  &inertia)
    {
      if (inertia.negative == 0 || inertia.zero > 0)
        return inertia.negative;
      const SymmetryBorder border =
        symmetry_border(model, u, load_factor, factorization);
      if (border.modes.empty() || !border.s.allFinite())
        return inertia.negative;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(border.s);
      const unsigned int positive = (eigen.eigenvalues().array() > 0).count();
      return inertia.negative + positive - border.modes.size();
    }

    /**
     * The Newton correction of the residual @p r on the complement of the
     * symmetry modes M of @p model at (@p u, @p load_factor): the c of the
     * bordered system [K M; M^T 0] (c, mu) = (r, 0), c = K^-1 (r - M mu)
     * with mu = S^-1 M^T K^-1 r. Along a symmetry every state is an
     * equilibrium and K has a pivot of rounding size, which gives K^-1 r
     * any component there (0.59 rad of the common turn of the frames of an
     * isotropic ring, issue 33); off the modes it is the distance to the
     * exact discrete equilibrium. Every entry, on every process.
     */
    std::vector<double>
    correction_beside_symmetries(const SolvableModel            &model,
                                 const VectorType               &u,
                                 const double                    load_factor,
                                 const EquilibriumFactorization &factorization,
                                 const VectorType               &r)
    {
      VectorType correction = model.create_vector();
      factorization.solve(r, correction);
      const SymmetryBorder border =
        symmetry_border(model, u, load_factor, factorization);
      const unsigned int k = border.modes.size();
      if (k > 0 && border.s.allFinite())
        {
          Eigen::VectorXd along(k);
          for (unsigned int a = 0; a < k; ++a)
            along[a] = border.modes[a] * correction;
          const Eigen::VectorXd mu = border.s.fullPivLu().solve(along);
          for (unsigned int a = 0; a < k; ++a)
            correction.add(-mu[a], border.solved[a]);
        }
      const EveryEntry every_entry(correction);
      const double    *values = (*every_entry).trilinos_vector()[0];
      return std::vector<double>(values, values + correction.size());
    }

    /// @p residual over @p loads, 0 where there are no loads.
    double
    out_of_balance(const double residual, const double loads)
    {
      return loads > 0 ? residual / loads : 0;
    }

    /// Says that the residual of @p result, @p ratio times its loads, does
    /// not resolve them.
    std::string
    unresolved_loads_text(const JudgedResult &result, const double ratio)
    {
      std::ostringstream text;
      text << "the residual (" << result.residual.force << " N, "
           << result.residual.moment << " N m) is " << ratio
           << " of the loads, which this model's rounding does not resolve "
              "(the response to them is at the rounding of the positions; "
              "stiffnesses and loads in other units may resolve them); ";
      return text.str();
    }
  } // namespace

  unsigned int
  negative_eigenvalues(const SolvableModel       &model,
                       const VectorType          &u,
                       const double               load_factor,
                       MatrixType                &tangent,
                       TangentFactorizationCache *factorizations)
  {
    model.assemble(u, load_factor, nullptr, &tangent, true);
    const auto factorization =
      EquilibriumFactorization::create(model, tangent, factorizations);
    return negative_beside_symmetries(model,
                                      u,
                                      load_factor,
                                      *factorization,
                                      factorization->inertia());
  }

  EquilibriumCheck
  check_equilibrium(const SolvableModel       &model,
                    const ResidualCriterion   &criterion,
                    const VectorType          &u,
                    const double               load_factor,
                    MatrixType                &tangent,
                    const JudgedResult        &result,
                    const double               uncertainty_limit,
                    TangentFactorizationCache *factorizations)
  {
    const phase_times::Scope phase(phase_times::Phase::checks);
    VectorType               r = model.create_vector();
    model.assemble(u, load_factor, &r, &tangent, true);
    const auto factorization =
      EquilibriumFactorization::create(model, tangent, factorizations);
    EquilibriumCheck check;
    check.negative_eigenvalues =
      negative_beside_symmetries(model,
                                 u,
                                 load_factor,
                                 *factorization,
                                 factorization->inertia());
    check.stable = check.negative_eigenvalues == 0;
    if (!result.rounding_limited)
      return check;
    // Where the residual sits on its round-off floor it cannot show
    // equilibrium alone; the Newton step it calls for can.
    try
      {
        check.rounding_uncertainty =
          criterion.state_change(correction_beside_symmetries(model,
                                                              u,
                                                              load_factor,
                                                              *factorization,
                                                              r));
      }
    catch (const std::exception &)
      {
        check.rounding_uncertainty = std::numeric_limits<double>::infinity();
      }
    // A residual at the floor but not below the loads: the loads are too
    // small for this model's rounding, however small the correction.
    const double unbalanced =
      std::max(out_of_balance(result.residual.force, result.scale.force),
               out_of_balance(result.residual.moment, result.scale.moment));
    if (!(check.rounding_uncertainty <= uncertainty_limit) || unbalanced > 1e-3)
      check.rounding_warning =
        (unbalanced > 1e-3 ? unresolved_loads_text(result, unbalanced) : "") +
        criterion.rounding_hint(tangent, result.noise, result.scale);
    return check;
  }

  void
  refuse_undetermined_state(const EquilibriumCheck &check,
                            const double            failure_limit,
                            const std::string      &where)
  {
    if (check.rounding_uncertainty <= failure_limit)
      return;
    std::ostringstream message;
    message << "the state at " << where
            << " is not determined: its residual is at the round-off floor, "
               "and the Newton correction of that residual is "
            << check.rounding_uncertainty << " of the model size (at most "
            << failure_limit
            << " for a converged step): " << check.rounding_warning;
    throw SolverFailure(message.str());
  }
} // namespace rodnet
