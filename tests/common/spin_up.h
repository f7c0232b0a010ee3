// The spin-up of a flexible beam clamped to a rigid hub whose angle is
// prescribed (Kane, Ryan & Banerjee 1987, J. Guidance 10(2); the same
// problem in Simo & Vu-Quoc 1986, part II): L = 10 m, rho A = 1.2 kg/m,
// EI = 1.4e4 N m^2, EA = 2.8e7 N, spun up to omega_s = 6 rad/s in T_s =
// 15 s,
//   theta(t) = (omega_s / T_s) [t^2/2 + (T_s/(2 pi))^2 (cos(2 pi t/T_s) - 1)],
//   t < T_s, and omega_s (t - T_s/2) after.
// omega_s lies above the first bending frequency of the beam at rest
// (3.80 rad/s), where a linear model without the centrifugal stiffening
// diverges (KRB's point). Shared by tests/validation/moving_supports.cc and
// bench/spin_up.cc.
//
// The reference is an independent reduced model, KRB's method: the
// Euler-Bernoulli beam in the frame turning with the hub, its chordwise
// deflection v(x, t) in a few clamped-free modes (assumed modes), with
// the centrifugal tension T(x) = rho A thetadot^2 [r (L - x) + (L^2 -
// x^2)/2] (hub radius r) that stiffens it:
//   rho A (vddot - thetadot^2 v) + EI v'''' - (T v')' = -rho A thetaddot
//   (r + x),
// integrated by RK4.
#ifndef RODNET_TESTS_COMMON_SPIN_UP_H
#define RODNET_TESTS_COMMON_SPIN_UP_H

#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <string>
#include <tests/common/cantilever_modes.h>
#include <vector>

namespace rodnet
{
  namespace testing
  {
    namespace spin_up
    {
      inline constexpr double L = 10, rho_A = 1.2, EI = 1.4e4, EA = 2.8e7,
                              GJ = 1.4e4, rho_J = 1.2e-3, omega_s = 6, T_s = 15;

      /// The prescribed hub angle (rad) and its first two derivatives.
      inline double
      theta(const double t)
      {
        const double c = T_s / (2 * M_PI);
        return t < T_s ?
                 omega_s / T_s *
                   (t * t / 2 + c * c * (std::cos(2 * M_PI * t / T_s) - 1)) :
                 omega_s * (t - T_s / 2);
      }

      inline double
      theta_dot(const double t)
      {
        return t < T_s ?
                 omega_s / T_s *
                   (t - T_s / (2 * M_PI) * std::sin(2 * M_PI * t / T_s)) :
                 omega_s;
      }

      inline double
      theta_ddot(const double t)
      {
        return t < T_s ? omega_s / T_s * (1 - std::cos(2 * M_PI * t / T_s)) :
                         0.0;
      }

      /// theta(t) as a muparser expression of t, for the scene entry.
      inline std::string
      theta_expression()
      {
        return "if(t < 15, 6/15*(t^2/2 + (15/(2*pi))^2*(cos(2*pi*t/15) - "
               "1)), 6*(t - 7.5))";
      }

      /// The tip deflection v(L, t) of the reduced model (in the frame of
      /// the hub, positive ahead of the beam) at the times @p times, with
      /// @p n_modes modes, hub radius @p r, RK4 steps of @p dt; without the
      /// centrifugal tension if not @p stiffening (KRB's linear model).
      inline std::vector<double>
      reduced_tip_deflection(const std::vector<double> &times,
                             const double               r,
                             const bool                 stiffening,
                             const unsigned int         n_modes = 5,
                             const double               dt      = 2e-4)
      {
        const std::vector<CantileverMode> modes = cantilever_modes(n_modes, L);
        const unsigned int                n     = modes.size();
        // Galerkin matrices by composite Simpson on 4000 intervals.
        Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n, n), stiffness = mass,
                        tension      = mass;
        Eigen::VectorXd    load      = Eigen::VectorXd::Zero(n);
        const unsigned int intervals = 4000;
        for (unsigned int q = 0; q <= intervals; ++q)
          {
            const double x = L * q / intervals;
            const double w = L / intervals / 3 *
                             (q == 0 || q == intervals ? 1 : (q % 2 ? 4 : 2));
            const double t1 = rho_A * (r * (L - x) + (L * L - x * x) / 2);
            for (unsigned int i = 0; i < n; ++i)
              {
                load[i] -= w * rho_A * (r + x) * modes[i].value(x);
                for (unsigned int j = 0; j < n; ++j)
                  {
                    mass(i, j) +=
                      w * rho_A * modes[i].value(x) * modes[j].value(x);
                    stiffness(i, j) +=
                      w * EI * modes[i].curvature(x) * modes[j].curvature(x);
                    tension(i, j) +=
                      w * t1 * modes[i].slope(x) * modes[j].slope(x);
                  }
              }
          }
        const Eigen::MatrixXd inverse = mass.inverse();
        // y = (q, qdot); M qddot = -(K + thetadot^2 (G - M)) q + thetaddot f.
        const auto rate = [&](const double t, const Eigen::VectorXd &y) {
          const double    w2 = std::pow(theta_dot(t), 2);
          Eigen::VectorXd dy(2 * n);
          dy.head(n) = y.tail(n);
          const Eigen::MatrixXd k =
            stiffness + w2 * ((stiffening ? tension : 0 * tension) - mass);
          dy.tail(n) = inverse * (-k * y.head(n) + theta_ddot(t) * load);
          return dy;
        };
        Eigen::VectorXd     y = Eigen::VectorXd::Zero(2 * n);
        std::vector<double> tip;
        double              t = 0;
        for (const double target : times)
          {
            while (t < target - 1e-12)
              {
                const double          h  = std::min(dt, target - t);
                const Eigen::VectorXd k1 = rate(t, y);
                const Eigen::VectorXd k2 = rate(t + h / 2, y + h / 2 * k1);
                const Eigen::VectorXd k3 = rate(t + h / 2, y + h / 2 * k2);
                const Eigen::VectorXd k4 = rate(t + h, y + h * k3);
                y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
                t += h;
              }
            double v = 0;
            for (unsigned int i = 0; i < n; ++i)
              v += modes[i].value(L) * y[i];
            tip.push_back(v);
          }
        return tip;
      }

      /// The spin-up history of the rod: times and tip deflection in the
      /// frame of the hub, total energy and the work done on the rod
      /// (TimeIntegrator::StepInfo); the solver's message if it stopped
      /// early.
      struct RodHistory
      {
        std::vector<double> time, tip, energy, work;
        std::string         failure;
        double              hub_radius = 0;
      };

      /**
       * The beam as a rod of @p n segments (midpoint clamp: free length L),
       * its clamp turned about e_z through its end vertex by theta(t) (a
       * support moving in time), integrated with @p method in steps @p h
       * to @p end_time. The end vertex lies l/2 behind the clamped
       * section: the hub radius of the reference is l/2 (the midpoint
       * clamp's first segment, l = L / (n - 1/2)). @p spectral_radius is
       * the generalized-alpha scheme's rho_inf.
       */
      inline RodHistory
      rod_spin_up(const unsigned int n,
                  const std::string &method,
                  const double       h,
                  const double       end_time,
                  const double       spectral_radius = 0.8)
      {
        auto network = std::make_unique<RodNetwork>();
        network->add_rod(
          generators::straight(Vector3(0, 0, 0), Vector3(L, 0, 0), n, true),
          false,
          Vector3::UnitZ(),
          "simple");
        RodModel model(std::move(network),
                       {std::make_shared<LinearElasticRod>(
                         RodStiffness{EA, EI, EI, GJ})});
        model.clamp_end("hub", 0, true);
        model.rotate_clamp(
          "hub",
          Vector3::UnitZ(),
          1.0,
          {"theta(t)",
           std::make_shared<const std::function<double(double)>>(theta)});
        model.finalize();
        TimeIntegrator::Parameters p;
        p.integrator                  = method;
        p.time_step                   = h;
        p.end_time                    = end_time;
        p.load_factor                 = [](double) { return 0.0; };
        p.relative_tolerance          = 1e-10;
        p.spectral_radius_at_infinity = spectral_radius;
        TimeIntegrator integrator(model, {{rho_A, rho_J}}, p);
        const auto    &vertices = model.network().rods()[0].vertices;
        const Vector3  pivot    = model.network().vertex(vertices[0]);
        RodHistory     history;
        history.hub_radius = 0.5 * L / (n - 0.5);
        VectorType u = model.create_vector(), v = model.create_vector();
        try
          {
            integrator.run(u,
                           v,
                           [&](const TimeIntegrator::StepInfo &info,
                               const VectorType               &x,
                               const VectorType &) {
                             const Vector3 arm =
                               model.configuration().position(x,
                                                              vertices.back()) -
                               pivot;
                             const double a = theta(info.time);
                             history.time.push_back(info.time);
                             history.tip.push_back(-std::sin(a) * arm[0] +
                                                   std::cos(a) * arm[1]);
                             history.energy.push_back(info.kinetic_energy +
                                                      info.potential_energy);
                             history.work.push_back(info.external_work);
                           });
          }
        catch (const SolverFailure &e)
          {
            history.failure = e.what();
          }
        return history;
      }
    } // namespace spin_up
  }   // namespace testing
} // namespace rodnet

#endif
