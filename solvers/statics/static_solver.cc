#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/free_motions.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/stability/stability.h>
#include <solvers/state_guard.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace rodnet
{
  namespace
  {
    /// The residual, relative to the loads and reactions at the solution,
    /// within which the state a far start's Newton reached is accepted
    /// when the scene's tolerance cannot be reached from it (solve_at()):
    /// far below the loads, though not at the scene's tolerance.
    constexpr double far_start_relative_tolerance = 1e-4;

    /// Adds to the diagonal of @p tangent at each of the twist DoFs
    /// @p twists its own value (1 where that is 0): a spring as stiff as
    /// the twist's row, which fixes the twist in a Newton step along a
    /// motion the tangent does not resist.
    void
    hold_twists(MatrixType                          &tangent,
                const std::vector<global_dof_index> &twists)
    {
      if (twists.empty())
        return;
      for (const global_dof_index d : twists)
        {
          // On several processes each holds the twists of its own rows.
          if (!tangent.in_local_range(d))
            continue;
          const double diagonal = std::abs(tangent.diag_element(d));
          tangent.add(d, d, diagonal > 0 ? diagonal : 1.0);
        }
      tangent.compress(dealii::VectorOperation::add);
    }
  } // namespace

  StaticSolver::StaticSolver(SolvableModel    &model,
                             const Parameters &parameters,
                             std::ostream     *log)
      : model(model)
      , parameters(parameters)
      , log(log)
      , criterion(model)
      , strains(model, parameters.strain_limits)
  {
    if (parameters.n_steps < 1)
      throw std::invalid_argument("the number of load steps must be >= 1");
    if (model.has_internal_variables())
      // Load steps have no time: a history-dependent material would answer
      // with an arbitrary rate.
      throw std::invalid_argument(
        "static load stepping cannot solve a material with internal "
        "variables (a viscoelastic law): its response depends on time; "
        "use time stepping (quasi-static or dynamic, doc/dynamics.md)");
    if (!model.multiplier_dofs().empty() && parameters.newton.needs_potential())
      throw std::invalid_argument(
        "the " + parameters.newton.line_search +
        " globalization minimizes a potential, but a model with Lagrange "
        "multipliers (inextensible rods, ribbons, bonding constraints) is "
        "solved at a stationary point of its Lagrangian (a saddle of the "
        "energy and the constraints); use the full step or backtracking");
    model.initialize_matrix(tangent);
  }

  JudgedResult
  StaticSolver::solve_at(VectorType       &u,
                         const double      load_factor,
                         const VectorType *extra_force,
                         const VectorType *scale_state,
                         const bool        far_start)
  {
    model.apply_boundary_values(u, load_factor);
    NewtonSolver::Problem problem =
      equilibrium_problem(u, load_factor, extra_force);
    JudgedSolve solve(load_factor,
                      extra_force,
                      far_start,
                      parameters.relative_tolerance);
    // The noise is measured at the start (judge_start()), and again where
    // Newton stalls (ResidualCriterion::stall_aware_test()).
    problem.converged = criterion.stall_aware_test(solve.step, solve.reached);
    try
      {
        judge_start(u, scale_state, solve);
      }
    catch (const std::exception &e)
      {
        JudgedResult outcome;
        outcome.failure = e.what();
        return outcome;
      }
    return newton_rounds(problem, solve, u);
  }

  NewtonSolver::Problem
  StaticSolver::equilibrium_problem(const VectorType &u,
                                    const double      load_factor,
                                    const VectorType *extra_force)
  {
    NewtonSolver::Problem problem;
    const auto potential = [this, load_factor, extra_force](const VectorType &x,
                                                            VectorType *r) {
      return model.assemble(x, load_factor, r, nullptr, true, extra_force);
    };
    // With multipliers the assembled "energy" is the Lagrangian, whose
    // stationary point is a saddle: no potential for a line search.
    if (model.multiplier_dofs().empty())
      problem.set_potential(potential);
    else
      problem.residual = [potential](const VectorType &x, VectorType &r) {
        potential(x, &r);
      };
    // The common turn of an isotropic rod's frames changes no energy: the
    // tangent is singular along it, and a Newton step turns the frames by
    // whatever the rounding pivot there makes of the residual (tens of rad
    // on a loaded ring, until Newton fails; issue 33). A spring on one
    // twist of each such rod, in the tangent only, holds the turn where
    // it is; the residual, and so the equilibrium, is unchanged.
    problem.tangent =
      [this,
       load_factor,
       extra_force,
       turns = free_frame_turns(model, u, load_factor)](const VectorType &x,
                                                        MatrixType       &k) {
        model.assemble(x, load_factor, nullptr, &k, true, extra_force);
        hold_twists(k, turns);
      };
    return problem;
  }

  void
  StaticSolver::judge_start(const VectorType &u,
                            const VectorType *scale_state,
                            JudgedSolve      &solve)
  {
    VectorType start = scale_state != nullptr ? *scale_state : u;
    model.apply_boundary_values(start, solve.load_factor);
    solve.noise =
      criterion.roundoff_noise(u, solve.load_factor, solve.extra_force);
    solve.scale = criterion.judging_scale(start,
                                          solve.load_factor,
                                          solve.noise.floor,
                                          solve.extra_force);
    if (solve.far_start)
      {
        // Newton assembles its own tangent: the residual alone here.
        VectorType r = model.create_vector();
        model
          .assemble(u, solve.load_factor, &r, nullptr, true, solve.extra_force);
        const ResidualParts out_of_balance = criterion.norms(u, r);
        solve.scale.force = std::max(solve.scale.force, out_of_balance.force);
        solve.scale.moment =
          std::max(solve.scale.moment, out_of_balance.moment);
      }
  }

  JudgedResult
  StaticSolver::newton_rounds(const NewtonSolver::Problem &problem,
                              JudgedSolve                 &solve,
                              VectorType                  &u)
  {
    // A far start's first round meets a tolerance inflated by the start's
    // out-of-balance. Its state is kept as a fallback if it is within
    // far_start_relative_tolerance of the loads at the solution, and the
    // tighter rounds go on from it: near a bifurcation, where the tangent
    // is nearly singular, they can fail where the fallback is an
    // equilibrium to that tolerance (the elastica's branch switch).
    std::optional<std::pair<VectorType, JudgedResult>> fallback;
    JudgedResult                                       outcome;
    const auto                                         failed = [&]() {
      if (!fallback)
        return outcome;
      u = fallback->first;
      return fallback->second;
    };
    unsigned int iterations = 0;
    for (unsigned int round = 0; round < 3; ++round)
      {
        solve.tolerance =
          ResidualCriterion::tolerance(solve.scale,
                                       solve.noise.floor,
                                       parameters.relative_tolerance);
        solve.step.excess_before_last = solve.step.excess_last = 0;
        static_cast<NewtonSolver::Result &>(outcome) =
          NewtonSolver(parameters.newton)
            .solve(problem, u, tangent, &factorizations);
        iterations += outcome.iterations;
        outcome.iterations = iterations;
        outcome.residual   = solve.reached;
        outcome.noise      = solve.noise;
        if (!outcome.converged)
          {
            outcome.failure +=
              "; " +
              ResidualCriterion::describe(solve.reached, solve.tolerance);
            return failed();
          }
        if (judge_round(u, solve, outcome))
          return outcome;
        if (!outcome.converged)
          return failed();
        if (solve.far_start && !fallback &&
            within_relative(solve,
                            std::max(far_start_relative_tolerance,
                                     parameters.relative_tolerance)))
          fallback.emplace(u, outcome);
      }
    outcome.converged = false;
    outcome.failure   = "the reactions kept changing the tolerance";
    return failed();
  }

  bool
  StaticSolver::judge_round(const VectorType &u,
                            JudgedSolve      &solve,
                            JudgedResult     &outcome)
  {
    // The reactions in the scale were those of the start; the solution's
    // are what counts. Where they ask for a tighter tolerance, Newton goes
    // on from the solution.
    try
      {
        solve.scale = criterion.judging_scale(u,
                                              solve.load_factor,
                                              solve.noise.floor,
                                              solve.extra_force);
      }
    catch (const std::exception &e)
      {
        outcome.converged = false;
        outcome.failure   = e.what();
        return false;
      }
    outcome.scale = solve.scale;
    outcome.rounding_limited =
      ResidualCriterion::inconclusive(solve.noise.floor,
                                      solve.scale,
                                      parameters.rounding_floor_limit);
    return within_relative(solve, parameters.relative_tolerance);
  }

  bool
  StaticSolver::within_relative(const JudgedSolve &solve,
                                const double       relative_tolerance)
  {
    return ResidualCriterion::within(
      solve.reached,
      ResidualCriterion::tolerance(solve.scale,
                                   solve.noise.floor,
                                   relative_tolerance));
  }

  bool
  StaticSolver::linear_prediction(const VectorType &u,
                                  const double      load_factor,
                                  VectorType       &trial)
  {
    VectorType moved = u;
    model.apply_boundary_values(moved, load_factor);
    VectorType prescribed_change = moved;
    prescribed_change -= u;
    if (prescribed_change.linfty_norm() == 0)
      return false;
    try
      {
        if (unconstrained_tangent.m() == 0)
          model.initialize_matrix(unconstrained_tangent);
        VectorType r = model.create_vector();
        model.assemble(u, load_factor, &r, &unconstrained_tangent, false);
        // K_ff du_f = -r_f - K_fc du_c, with du_c the prescribed change.
        VectorType rhs = model.create_vector();
        unconstrained_tangent.vmult(rhs, prescribed_change);
        rhs += r;
        rhs *= -1.0;
        model.constraints().set_zero(rhs);
        model.assemble(u, load_factor, nullptr, &tangent, true);
        VectorType                             du = model.create_vector();
        dealii::SolverControl                  control(1, 0);
        dealii::TrilinosWrappers::SolverDirect direct(control);
        direct.solve(tangent, du, rhs);
        trial = moved;
        trial += du;
        return std::isfinite(trial.l2_norm());
      }
    catch (const std::exception &)
      {
        // A tangent that cannot be built or factored: start unpredicted.
        return false;
      }
  }

  void
  StaticSolver::refuse_unsolvable(const VectorType &u)
  {
    const std::string free_motions = describe_free_motions(model, u);
    if (!free_motions.empty())
      throw std::invalid_argument(free_motions);
  }

  unsigned int
  StaticSolver::negative_eigenvalues(const VectorType &u,
                                     const double      load_factor)
  {
    return rodnet::negative_eigenvalues(model,
                                        u,
                                        load_factor,
                                        tangent,
                                        &factorizations);
  }

  void
  StaticSolver::check_state(const VectorType   &u,
                            const JudgedResult &result,
                            StepInfo           &info)
  {
    info.check = check_equilibrium(model,
                                   criterion,
                                   u,
                                   info.load_factor,
                                   tangent,
                                   result,
                                   parameters.rounding_uncertainty_limit,
                                   &factorizations);
    refuse_undetermined_state(info.check,
                              parameters.rounding_failure_limit,
                              "load factor " +
                                std::to_string(info.load_factor));
    info.strain = strains.evaluate(u);
  }

  void
  StaticSolver::log_warnings(const StepInfo &info) const
  {
    if (!info.check.stable)
      *log << "warning: the equilibrium at load factor " << info.load_factor
           << " is unstable: its tangent has "
           << info.check.negative_eigenvalues
           << " negative eigenvalue(s); any imperfection leaves it (Solver/"
              "Branch switching amplitude follows a stable branch)"
           << std::endl;
    const std::string strain_warning = strains.warning(info.strain);
    if (!strain_warning.empty())
      *log << strain_warning << std::endl;
    if (!info.check.rounding_warning.empty())
      *log << "warning: rounding leaves the state at load factor "
           << info.load_factor << " uncertain by "
           << info.check.rounding_uncertainty
           << " of the model size (the Newton correction of its residual; "
           << parameters.rounding_uncertainty_limit
           << " allowed): " << info.check.rounding_warning << std::endl;
  }

  std::string
  StaticSolver::singular_tangent(const VectorType &u, const double load_factor)
  {
    Inertia inertia;
    try
      {
        model.assemble(u, load_factor, nullptr, &tangent, true);
        inertia = tangent_inertia(tangent,
                                  model.constraints(),
                                  model.multiplier_dofs());
      }
    catch (const std::exception &)
      {
        return "";
      }
    if (inertia.zero == 0)
      return "";
    char ratio[32];
    std::snprintf(ratio, sizeof(ratio), "%.1e", inertia.weakest_ratio);
    const std::string where =
      inertia.weakest_dof == dealii::numbers::invalid_unsigned_int ?
        "an exactly zero pivot" :
        "a pivot of " + std::string(ratio) + " times its diagonal, at " +
          criterion.roles().describe(inertia.weakest_dof);
    return "; the tangent at load factor " + std::to_string(load_factor) +
           " is singular (" + where +
           "): part of the structure can move without deforming (a "
           "mechanism); hold it with a support or stiffen its joints";
  }

  double
  StaticSolver::lowest_eigenvalue(const VectorType &u, const double load_factor)
  {
    model.assemble(u, load_factor, nullptr, &tangent);
    const std::vector<double> values =
      lowest_eigenpairs(tangent,
                        model.constraints(),
                        1,
                        model.multiplier_dofs())
        .values;
    return values.empty() ? std::nan("") : values[0];
  }

  bool
  StaticSolver::solve_along_mode(VectorType   &u,
                                 const double  mode_load_factor,
                                 const double  load_factor,
                                 const double  energy_bound,
                                 double       &eigenvalue,
                                 JudgedResult *solved)
  {
    model.assemble(u, mode_load_factor, nullptr, &tangent);
    const std::vector<double> mode = lowest_eigenpairs(tangent,
                                                       model.constraints(),
                                                       1,
                                                       model.multiplier_dofs())
                                       .vectors[0];
    // Displace the state along the mode so that its largest component
    // moves by the given fraction of the model size, and let Newton find
    // the equilibrium nearby, on both sides. Where Newton diverges from
    // both starts, they were too far for it (the classic kernel's windmill
    // of Fig. 3b past the shaft's torsional buckling): half the distance,
    // twice at most, before the branch counts as not found.
    ModeSearch search;
    search.best         = u;
    search.energy_bound = energy_bound;
    double distance = parameters.branch_switch_amplitude * model.length_scale();
    for (unsigned int attempt = 0; attempt < 3 && !search.any_converged;
         ++attempt, distance /= 2)
      search_both_ways(u, mode, distance, load_factor, search);
    if (!search.best_state)
      return false;
    model.set_state(*search.best_state);
    u          = search.best;
    eigenvalue = search.eigenvalue;
    if (solved != nullptr)
      *solved = search.best_result;
    return true;
  }

  void
  StaticSolver::search_both_ways(const VectorType          &u,
                                 const std::vector<double> &mode,
                                 const double               distance,
                                 const double               load_factor,
                                 ModeSearch                &search)
  {
    // The start's state returns after each solve and on return.
    const StateGuard start(model);
    for (const double sign : {1.0, -1.0})
      {
        model.set_state(start.saved_state());
        VectorType         trial = moved_along_mode(u, mode, sign * distance);
        const JudgedResult result =
          solve_at(trial, load_factor, nullptr, nullptr, true);
        if (!result.converged)
          continue;
        search.any_converged = true;
        model.reset_reference(trial);
        const double energy =
          model.assemble(trial, load_factor, nullptr, nullptr);
        const double mu = lowest_eigenvalue(trial, load_factor);
        if (mu > 0 && energy < search.energy_bound)
          {
            search.energy_bound = energy;
            search.eigenvalue   = mu;
            search.best         = trial;
            search.best_state   = model.state();
            search.best_result  = result;
          }
      }
  }

  void
  StaticSolver::bisect_critical_load(const VectorType &u_stable,
                                     const ModelState &stable_state,
                                     double            lambda_stable,
                                     double            lambda_unstable)
  {
    VectorType u_lo  = u_stable;
    ModelState state = stable_state;
    while (lambda_unstable - lambda_stable > parameters.critical_load_tolerance)
      {
        const double lambda_mid = 0.5 * (lambda_stable + lambda_unstable);
        model.set_state(state);
        VectorType                 u_mid  = u_lo;
        const NewtonSolver::Result result = solve_at(u_mid, lambda_mid);
        if (!result.converged)
          throw SolverFailure("bisection for the critical load failed at load "
                              "factor " +
                              std::to_string(lambda_mid) + ": " +
                              result.failure);
        model.reset_reference(u_mid);
        if (negative_eigenvalues(u_mid, lambda_mid) == 0)
          {
            lambda_stable = lambda_mid;
            u_lo          = u_mid;
            state         = model.state();
          }
        else
          lambda_unstable = lambda_mid;
      }
    critical_load = 0.5 * (lambda_stable + lambda_unstable);
    if (log != nullptr)
      *log << "critical load factor " << critical_load
           << " (the tangent's lowest eigenvalue crosses zero)" << std::endl;
  }
} // namespace rodnet
