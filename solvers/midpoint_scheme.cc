#include <solvers/midpoint_scheme.h>

namespace rodnet
{
  MidpointScheme::MidpointScheme(const StepSystem &system)
      : IntegrationScheme(system)
  {
    point = system.model.create_vector();
    for (VectorType *v : {&gradient_m,
                          &gradient_y,
                          &mass_difference,
                          &rank_one_a,
                          &rank_one_b,
                          &difference,
                          &product})
      v->reinit(point);
  }

  void
  MidpointScheme::set_up(const StepStart &step, NewtonSolver::Problem &problem)
  {
    start_energy =
      system.model.assemble(step.u, step.load_factor, nullptr, nullptr);
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
    // The discrete gradient in the metric of the mass matrix:
    // gradbar = grad Pi(m) + c M d_f, c = [Pi(u) - Pi(u_n) -
    // grad Pi(m).d] / (d_f.M d_f). Any metric keeps gradbar.d =
    // Pi(u) - Pi(u_n); the mass puts the correction where the inertia is,
    // instead of loading the stiff, nearly massless twist DoFs as much as
    // the positions (which made Newton stall at coarse steps), and never on
    // massless quaternion rows.
    difference = y;
    difference -= step.u;
    const double change = energy - start_energy - (gradient * difference);
    system.model.constraints().set_zero(difference);
    system.mass.vmult(mass_difference, difference);
    system.model.constraints().set_zero(mass_difference);
    const double norm2 = difference * mass_difference;
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
    RodModel &model = system.model;
    model.assemble(point, step.load_factor, &r, nullptr, false);
    const double energy = model.assemble(y, step.load_factor, nullptr, nullptr);
    const double coefficient = correction_terms(step, y, r, energy).first;
    model.constraints().set_zero(r);
    r.add(coefficient, mass_difference);
    add_inertia(step, y, &r);
  }

  void
  MidpointScheme::tangent(const StepStart  &step,
                          const VectorType &y,
                          MatrixType       &k)
  {
    // The exact Jacobian: the derivative of the correction c M d_f is
    // c M (sparse) plus the dense M d_f (grad c)^T, with
    //   grad c = [grad Pi(u) - grad Pi(m) - K(m) d / 2 - 2 c M d_f]
    //            / (d_f.M d_f)
    // (free rows), which NewtonSolver takes as a rank-one term.
    set_midpoint(step, y);
    RodModel &model = system.model;
    model.assemble(point, step.load_factor, &gradient_m, nullptr, false);
    const double energy =
      model.assemble(y, step.load_factor, &gradient_y, nullptr, false);
    const auto [coefficient, norm2] =
      correction_terms(step, y, gradient_m, energy);

    model.assemble(point, step.load_factor, nullptr, &k, true);
    k *= 0.5;
    k.vmult(product, difference);
    k.add(mass_coefficient(step.h) + coefficient, system.constrained_mass);
    add_damping_tangent(step.h, k);

    rank_one_b = gradient_y;
    rank_one_b -= gradient_m;
    rank_one_b -= product;
    rank_one_b.add(-2 * coefficient, mass_difference);
    model.constraints().set_zero(rank_one_b);
    rank_one_b *= norm2 > 0 ? 1 / norm2 : 0.0;
    rank_one_a = mass_difference;
  }
} // namespace rodnet
