// The cantilever of the dynamics validation (tests/validation/dynamics.cc)
// and of the time-step study (bench/time_steps.cc): a slender rod of unit
// length, EI = 1 and rho A = 1, clamped at the origin, held under a tip
// force and released at t = 0. Its first Euler-Bernoulli period is
// 2 pi / 1.8751^2.
#ifndef RODNET_TESTS_COMMON_CANTILEVER_SWING_H
#define RODNET_TESTS_COMMON_CANTILEVER_SWING_H

#include <core/mass_matrix.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  namespace testing
  {
    /// Circular section with A L^2 / I = 1e4 (radius 0.02), G = E / 2.6.
    inline const RodStiffness swing_stiffness{1e4, 1, 1, 1 / 1.3};
    inline const RodInertia   swing_inertia{1, 2e-4};

    /// The linear elastic rod of swing_stiffness.
    inline std::shared_ptr<const RodMaterial>
    swing_elastic_rod()
    {
      return std::make_shared<LinearElasticRod>(swing_stiffness);
    }

    /// First bending period of the Euler-Bernoulli cantilever (s).
    inline double
    cantilever_period()
    {
      return 2 * M_PI / (1.8751 * 1.8751);
    }

    /**
     * Cantilever along e_x of @p n segments, clamped at the origin (the
     * midpoint clamp: free length exactly 1), tip force (0, 0, @p P) at
     * load factor 1.
     */
    inline std::unique_ptr<RodModel>
    cantilever(const unsigned int                        n,
               const std::shared_ptr<const RodMaterial> &material,
               const double                              P)
    {
      auto network = std::make_unique<RodNetwork>();
      network->add_rod(
        generators::straight(Vector3(0, 0, 0), Vector3(1, 0, 0), n, true),
        false,
        Vector3::UnitY(),
        "simple");
      auto model = std::make_unique<RodModel>(
        std::move(network),
        std::vector<std::shared_ptr<const RodMaterial>>{material});
      model->clamp_end("clamp", 0, true);
      model->add_point_force(n, Vector3(0, 0, P));
      model->finalize();
      return model;
    }

    /// Per converged step after the release: time, tip deflection (z),
    /// total energy; and the solver's message if the run stopped early.
    struct SwingHistory
    {
      std::vector<double> time, tip, energy;
      std::string         failure;
    };

    /**
     * Runs @p integrator on @p model from @p u at rest and records the tip's
     * z, the time and the total energy of every step at t >= 0 (the preload
     * steps, before the release, are left out). A SolverFailure ends the
     * history early with its message.
     */
    inline SwingHistory
    record_swing(const RodModel &model,
                 TimeIntegrator &integrator,
                 VectorType     &u)
    {
      const unsigned int tip = model.network().rods()[0].vertices.back();
      VectorType         v   = model.create_vector();
      SwingHistory       history;
      try
        {
          integrator.run(u,
                         v,
                         [&](const TimeIntegrator::StepInfo &info,
                             const VectorType               &x,
                             const VectorType &) {
                           if (info.time < 0)
                             return;
                           history.time.push_back(info.time);
                           history.tip.push_back(
                             model.configuration().position(x, tip)[2]);
                           history.energy.push_back(info.kinetic_energy +
                                                    info.potential_energy);
                         });
        }
      catch (const SolverFailure &e)
        {
          history.failure = e.what();
        }
      return history;
    }

    /**
     * Holds @p model under its load (a quasi-static preload), releases it
     * at t = 0 and integrates with @p method to @p end_time in steps @p h.
     * A SolverFailure ends the history early with its message.
     */
    inline SwingHistory
    released_swing(RodModel          &model,
                   const std::string &method,
                   const double       h,
                   const double       end_time,
                   std::ostream      *log = nullptr)
    {
      TimeIntegrator::Parameters p;
      p.integrator         = method;
      p.time_step          = h;
      p.end_time           = end_time;
      p.preload_time       = 1;
      p.preload_steps      = 4;
      p.load_factor        = [](const double t) { return t < 0 ? 1.0 : 0.0; };
      p.relative_tolerance = 1e-11;
      TimeIntegrator integrator(model, {swing_inertia}, p, log);
      VectorType     u = model.create_vector();
      return record_swing(model, integrator, u);
    }

    /// Period from the zero crossings of the tip deflection (linear
    /// interpolation between steps) over all half-periods recorded; NaN
    /// with fewer than three crossings.
    inline double
    zero_crossing_period(const SwingHistory &h)
    {
      std::vector<double> crossings;
      for (unsigned int i = 1; i < h.tip.size(); ++i)
        if ((h.tip[i - 1] > 0) != (h.tip[i] > 0))
          crossings.push_back(h.time[i - 1] + (h.time[i] - h.time[i - 1]) *
                                                h.tip[i - 1] /
                                                (h.tip[i - 1] - h.tip[i]));
      if (crossings.size() < 3)
        return std::numeric_limits<double>::quiet_NaN();
      return 2 * (crossings.back() - crossings.front()) /
             (crossings.size() - 1);
    }

    /// Largest relative change of the energy from its first value.
    inline double
    energy_drift(const SwingHistory &h)
    {
      double drift = 0;
      for (const double e : h.energy)
        drift = std::max(drift, std::abs(e / h.energy.front() - 1));
      return drift;
    }

    /**
     * First mode of the discrete cantilever: omega_1 and its shape as a DoF
     * vector, from K phi = omega^2 M phi on the free DoFs (dense: N = 50 has
     * about 200). Starting from this shape the tip moves in one mode only,
     * so that its zero crossings measure the period without the shifts of
     * higher modes, whose phase errors differ with the step.
     */
    inline std::pair<double, VectorType>
    first_mode(const RodModel &model)
    {
      MatrixType stiffness, mass;
      model.initialize_matrix(stiffness);
      model.assemble(model.create_vector(), 0.0, nullptr, &stiffness, true);
      assemble_mass_matrix(model, {swing_inertia}, MassKind::consistent, mass);
      std::vector<unsigned int> free;
      for (unsigned int i = 0; i < stiffness.m(); ++i)
        if (!model.constraints().is_constrained(i))
          free.push_back(i);
      Eigen::MatrixXd k(free.size(), free.size()), m(free.size(), free.size());
      for (unsigned int i = 0; i < free.size(); ++i)
        for (unsigned int j = 0; j < free.size(); ++j)
          {
            k(i, j) = stiffness.el(free[i], free[j]);
            m(i, j) = mass.el(free[i], free[j]);
          }
      const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(k,
                                                                            m);
      VectorType shape = model.create_vector();
      for (unsigned int i = 0; i < free.size(); ++i)
        shape[free[i]] = modes.eigenvectors()(i, 0);
      return {std::sqrt(modes.eigenvalues()[0]), shape};
    }

    /// Free vibration of @p model from @p amplitude times @p shape, at rest,
    /// with @p method in steps @p h to @p end_time: the tip deflection and
    /// the energy; @p adjust may change the parameters (damping).
    inline SwingHistory
    free_vibration(
      RodModel                                                &model,
      const VectorType                                        &shape,
      const double                                             amplitude,
      const std::string                                       &method,
      const double                                             h,
      const double                                             end_time,
      const std::function<void(TimeIntegrator::Parameters &)> &adjust = {})
    {
      TimeIntegrator::Parameters p;
      p.integrator         = method;
      p.time_step          = h;
      p.end_time           = end_time;
      p.load_factor        = [](double) { return 0.0; };
      p.relative_tolerance = 1e-11;
      if (adjust)
        adjust(p);
      TimeIntegrator integrator(model, {swing_inertia}, p);
      VectorType     u = shape;
      u *= amplitude;
      return record_swing(model, integrator, u);
    }

  } // namespace testing
} // namespace rodnet

#endif
