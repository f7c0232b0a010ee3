#include <solvers/newton/tangent_factorization.h>
#include <solvers/time/generalized_alpha_scheme.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  GeneralizedAlphaScheme::GeneralizedAlphaScheme(const StepSystem &system)
      : IntegrationScheme(system)
  {
    const double rho = system.spectral_radius_at_infinity;
    if (!(rho >= 0 && rho <= 1))
      {
        std::ostringstream message;
        message << "time stepping (generalized alpha): the spectral radius at "
                   "infinity must lie in [0, 1], got "
                << rho;
        throw std::invalid_argument(message.str());
      }
    // Chung & Hulbert (1993), eqs. (25) and (17)-(18): second order,
    // high-frequency dissipation maximal for the given rho_inf.
    alpha_m = (2 * rho - 1) / (rho + 1);
    alpha_f = rho / (rho + 1);
    gamma   = 0.5 - alpha_m + alpha_f;
    beta    = 0.25 * std::pow(1 - alpha_m + alpha_f, 2);
    for (VectorType *v :
         {&inertial_force, &acceleration, &inertial_extra, &extra_force})
      *v = system.model.create_vector();
  }

  void
  GeneralizedAlphaScheme::start(const VectorType &u,
                                const VectorType &v,
                                const double      load_factor)
  {
    initial_inertial_force(u, v, load_factor, inertial_force);
    acceleration = 0;
    if (inertial_force.linfty_norm() > 0)
      solve_acceleration(inertial_force, acceleration);
    update_inertial_extra();
  }

  void
  GeneralizedAlphaScheme::solve_acceleration(const VectorType &force,
                                             VectorType       &a) const
  {
    // M_ff a_f = p_f on the free rows with mass; the held rows start at
    // a = 0 (their own recursion in finish() then follows the prescribed
    // motion, its start error decaying by rho_inf per step), the massless
    // rows have none. Those rows get a unit diagonal and a zero right-hand
    // side.
    MatrixType matrix;
    matrix.copy_from(system.constrained_mass);
    VectorType right_hand_side = force;
    system.model.constraints().set_zero(right_hand_side);
    const auto [first, end] = matrix.local_range();
    for (global_dof_index i = first; i < end; ++i)
      if (matrix.diag_element(i) == 0.0)
        {
          matrix.set(i, i, 1.0);
          right_hand_side[i] = 0;
        }
    matrix.compress(dealii::VectorOperation::insert);
    right_hand_side.compress(dealii::VectorOperation::insert);
    const std::unique_ptr<TangentFactorization> solver =
      TangentFactorization::create(matrix, "auto");
    solver->factorize();
    solver->solve(right_hand_side, a);
  }

  void
  GeneralizedAlphaScheme::update_inertial_extra()
  {
    // e_n = [((1 - alpha_m)(1/2 - beta)/beta - alpha_m) M a_n + alpha_f p_n]
    //       / (1 - alpha_f), the terms of c M (u - u_n - h v_n) - p that
    // do not depend on u (see the class documentation).
    system.mass.vmult(inertial_extra, acceleration);
    inertial_extra *= ((1 - alpha_m) * (0.5 - beta) / beta - alpha_m);
    inertial_extra.add(alpha_f, inertial_force);
    inertial_extra /= 1 - alpha_f;
  }

  void
  GeneralizedAlphaScheme::set_up(const StepStart       &step,
                                 NewtonSolver::Problem &problem)
  {
    extra_force = inertial_extra;
    if (system.damping.m() != 0)
      {
        // The part h (1 - gamma/(2 beta)) a_n of v_{n+1}, which
        // damping_velocity() cannot express.
        VectorType damping_force = acceleration;
        system.damping.vmult(damping_force, acceleration);
        extra_force.add(-step.h * (1 - gamma / (2 * beta)), damping_force);
      }
    IntegrationScheme::set_up(step, problem);
  }

  void
  GeneralizedAlphaScheme::finish(const StepStart  &step,
                                 const VectorType &x,
                                 VectorType       &v)
  {
    const double h      = step.h;
    VectorType   change = x;
    change -= step.base;
    // p_{n+1} = c M (u - u_n - h v_n) - e_n: the equation of motion.
    system.mass.vmult(inertial_force, change);
    inertial_force *= mass_coefficient(h);
    inertial_force -= inertial_extra;
    // v_{n+1} = v_n + h ((1 - gamma) a_n + gamma a_{n+1}), with
    // a_{n+1} = (u - u_n - h v_n) / (beta h^2) - (1/(2 beta) - 1) a_n.
    v.add(h * (1 - gamma / (2 * beta)), acceleration);
    v.add(gamma / (beta * h), change);
    acceleration *= 1 - 1 / (2 * beta);
    acceleration.add(1 / (beta * h * h), change);
    system.zero_massless_rows(acceleration);
    update_inertial_extra();
  }
} // namespace rodnet
