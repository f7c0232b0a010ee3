#include <deal.II/base/mpi.h>

#include <core/same_entries.h>
#include <solvers/time/midpoint_scheme.h>

#include <cmath>

namespace rodnet
{
  MidpointScheme::MidpointScheme(const StepSystem &system)
      : IntegrationScheme(system)
      , rigid_split(system.model, system.mass)
      , gyroscopic(system.model, system.mass)
      , body_rotation(system.model, system.mass)
  {
    point = system.model.create_vector();
    for (VectorType *v : {&gradient_m,
                          &gradient_point,
                          &end_point,
                          &residual_point,
                          &gradient_y,
                          &mass_difference,
                          &direction,
                          &rank_one_a,
                          &rank_one_b,
                          &difference,
                          &product,
                          &held_difference,
                          &held_product})
      v->reinit(point);
  }

  void
  MidpointScheme::set_up(const StepStart &step, NewtonSolver::Problem &problem)
  {
    start_energy =
      std::isnan(step.start_energy) ?
        system.model.assemble(step.u, step.load_factor, nullptr, nullptr) :
        step.start_energy;
    gradient_known   = false;
    end_known        = false;
    residual_known   = false;
    current_step     = &step;
    problem.residual = [this, &step](const VectorType &y, VectorType &r) {
      residual(step, y, r);
    };
    problem.tangent = [this, &step](const VectorType &y, MatrixType &k) {
      tangent(step, y, k);
    };
    problem.rank_one =
      [this](const VectorType &, VectorType &a, VectorType &b) {
        a = rank_one_a;
        b = rank_one_b;
      };
  }

  void
  MidpointScheme::set_midpoint(const StepStart &step, const VectorType &y)
  {
    point = y;
    point += step.u;
    point *= 0.5;
  }

  std::pair<double, double>
  MidpointScheme::correction_terms(const StepStart  &step,
                                   const VectorType &y,
                                   const VectorType &gradient,
                                   const double      energy)
  {
    // The discrete gradient gradbar = grad Pi(m) + c w, c = [Pi(u) -
    // Pi(u_n) - grad Pi(m).d] / (w.d), keeps gradbar.d = Pi(u) - Pi(u_n)
    // for any w with w.d != 0. w = M d_def, d_def the part of d_f that is
    // M-orthogonal to the rigid motions of the free parts at m
    // (RigidMotionSplit): the correction puts no resultant and no moment
    // on a free body, so the momenta change only by grad Pi(m), as in the
    // plain midpoint rule; and, as M d_f did, it acts where the inertia is,
    // never on massless quaternion rows, and w.d = |d_def|_M^2 > 0.
    difference = y;
    difference -= step.u;
    const double change = energy - start_energy - (gradient * difference);
    system.model.constraints().set_zero(difference);
    system.mass.vmult(mass_difference, difference);
    system.model.constraints().set_zero(mass_difference);
    const double full = difference * mass_difference;
    direction         = mass_difference;
    rigid_split.remove_rigid_part(point, direction);
    system.model.constraints().set_zero(direction);
    double norm2 = difference * direction;
    // A step that is a rigid motion to within rigid_step_limit of its
    // mass norm (a body in free translation or spin) has no deformation to
    // carry the correction: then w = M d_f, as Gonzalez's mass metric.
    if (!(norm2 > rigid_step_limit * full))
      {
        direction = mass_difference;
        norm2     = full;
      }
    return std::make_pair(norm2 > 0 ? change / norm2 : 0.0, norm2);
  }

  void
  MidpointScheme::residual(const StepStart  &step,
                           const VectorType &y,
                           VectorType       &r)
  {
    set_midpoint(step, y);
    // Unconstrained: grad Pi . d needs the fixed rows too, where prescribed
    // DoFs move.
    SolvableModel &model = system.model;
    model.assemble(point, step.load_factor, &r, nullptr, false);
    keep_gradient(r);
    // Pi(y) of the assembly of grad Pi(y) where there is one at y (the
    // first iterate's, shared_gradient()), else an energy-only assembly.
    const double energy =
      end_known && same_entries(y, end_point) ?
        end_energy :
        model.assemble(y, step.load_factor, nullptr, nullptr);
    residual_point           = y;
    residual_energy          = energy;
    residual_known           = true;
    const double coefficient = correction_terms(step, y, r, energy).first;
    model.constraints().set_zero(r);
    r.add(coefficient, direction);
    gyroscopic.add_force(step.u, y, step.h, r);
    body_rotation.add_force(step, y, r);
    add_inertia(step, y, &r);
  }

  void
  MidpointScheme::keep_gradient(const VectorType &gradient)
  {
    gradient_m     = gradient;
    gradient_point = point;
    gradient_known = true;
  }

  const VectorType *
  MidpointScheme::shared_gradient(const VectorType &x)
  {
    if (current_step == nullptr)
      return nullptr;
    assemble_end(*current_step, x);
    return &gradient_y;
  }

  void
  MidpointScheme::assemble_end(const StepStart &step, const VectorType &y)
  {
    if (end_known && same_entries(y, end_point))
      return;
    end_energy =
      system.model.assemble(y, step.load_factor, &gradient_y, nullptr, false);
    end_point = y;
    end_known = true;
  }

  void
  MidpointScheme::held_columns_product(const StepStart  &step,
                                       const VectorType &y,
                                       MatrixType       &k)
  {
    // d_h, the step of the held DoFs (a moving support). The
    // constrained tangent has no columns there, but grad Pi(m).d depends
    // on the free DoFs through K(m)_fh d_h / 2 as well: left out, grad c
    // was off by K_fh d_h / (2 w.d), which grows as 1 / |d| when the step
    // is cut (a support turning a rod about its own axis: no convergence).
    // (The junction copies' lines, with entries, are no stencil's DoFs.)
    // Each process its own rows; the assembly below is collective, so
    // all take part where a held DoF moves on any.
    held_difference              = 0;
    held_product                 = 0;
    unsigned int           moves = 0;
    const dealii::IndexSet owned = y.locally_owned_elements();
    for (const auto &line : system.model.constraints().get_lines())
      if (line.entries.empty() && owned.is_element(line.index) &&
          y[line.index] != step.u[line.index])
        {
          held_difference[line.index] = y[line.index] - step.u[line.index];
          moves                       = 1;
        }
    held_difference.compress(dealii::VectorOperation::insert);
    if (dealii::Utilities::MPI::max(moves, y.get_mpi_communicator()) == 0)
      return;
    system.model.assemble(point, step.load_factor, nullptr, &k, false);
    k.vmult(held_product, held_difference);
    held_product *= 0.5;
    system.model.constraints().set_zero(held_product);
  }

  void
  MidpointScheme::tangent(const StepStart  &step,
                          const VectorType &y,
                          MatrixType       &k)
  {
    // The Jacobian of the correction c w, w = M P d (P the M-orthogonal
    // projection off the rigid motions at m): c M P plus the dense
    // w (grad c)^T, with
    //   grad c = [grad Pi(u) - grad Pi(m) - K(m) d / 2 - 2 c w] / (w.d)
    // (free rows, K(m) d over the held DoFs' columns too; grad (w.d) =
    // 2 M P d = 2 w), which NewtonSolver takes as
    // a rank-one term. Without free parts P = I and c M is exact. With
    // them c M P is dense (its low-rank part -c M R (R^T M R)^+ R^T M) and
    // is left out whole, as is the change of the rigid motions R with m:
    // terms of the size of c (the error of the midpoint quadrature of
    // grad Pi along d, over |d_def|_M^2) against 2 M / h^2. Leaving out
    // c M as well keeps t^T J = 2 t^T M / h^2 for a translation t, the
    // exact derivative of the resultant of the residual, which is affine
    // in u (t^T grad Pi is minus the loads, t^T w = 0): every Newton step
    // then solves the momentum balance to round-off, not only to the
    // Newton tolerance.
    set_midpoint(step, y);
    SolvableModel &model = system.model;
    // Newton asks for the tangent where it has just evaluated the residual.
    if (!gradient_known || !same_entries(point, gradient_point))
      model.assemble(point, step.load_factor, &gradient_m, nullptr, false);
    assemble_end(step, y);
    const auto [coefficient, norm2] =
      correction_terms(step, y, gradient_m, end_energy);

    held_columns_product(step, y, k);
    model.assemble(point, step.load_factor, nullptr, &k, true);
    k *= 0.5;
    k.vmult(product, difference);
    product += held_product;
    k.add(mass_coefficient(step.h) +
            (rigid_split.has_free_parts() ? 0.0 : coefficient),
          system.constrained_mass);
    add_damping_tangent(step.h, k);
    gyroscopic.add_jacobian(step.u, y, step.h, k);
    body_rotation.add_jacobian(step, y, k);

    rank_one_b = gradient_y;
    rank_one_b -= gradient_m;
    rank_one_b -= product;
    rank_one_b.add(-2 * coefficient, direction);
    model.constraints().set_zero(rank_one_b);
    rank_one_b *= norm2 > 0 ? 1 / norm2 : 0.0;
    rank_one_a = direction;
  }
} // namespace rodnet
