// StandardLinearSolid: the condensed incremental energy against its own
// definition, its stress and tangent against central differences, the
// instantaneous and relaxed limits against LinearElasticRod, creep and
// relaxation integrated step by step against the exact SLS solutions, the
// default history interface of elastic materials, and errors.

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <materials/linear_elastic_rod.h>
#include <materials/standard_linear_solid.h>

#include <array>
#include <cctype>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace rodnet;

namespace
{
  // Relaxed rigidities of different magnitudes, so that a swapped mode
  // shows; ratio and relaxation time of Lestringant & Kochmann's Fig. 5.
  const RodStiffness relaxed{2.3e3, 0.7, 1.9, 0.45};
  constexpr double   ratio = 0.3;
  constexpr double   t_r   = 0.00334;

  /// Steps from 1e-6 t_r to 1e3 t_r.
  const std::array<double, 6> step_factors{{1e-6, 1e-4, 1e-2, 1., 1e1, 1e3}};

  /**
   * The incremental potential of a hinge written out from its definition
   * (doc/viscoelasticity.md): W(kappa, alpha) + dt Psi((alpha - alpha_prev)
   * / dt) with W = l/2 sum_m [k_m e_m^2 + r k_m (e_m - alpha_m)^2],
   * Psi = l/2 sum_m t_r r k_m alpha_dot_m^2 and e = kappa / l.
   */
  double
  hinge_potential(const Eigen::Vector3d &kappa,
                  const double           l,
                  const Eigen::Vector3d &alpha,
                  const Eigen::Vector3d &previous,
                  const double           dt)
  {
    const Eigen::Vector3d k(relaxed.EI1, relaxed.EI2, relaxed.GJ);
    double                potential = 0.;
    for (unsigned int m = 0; m < 3; ++m)
      {
        const double e    = kappa(m) / l;
        const double rate = (alpha(m) - previous(m)) / dt;
        potential +=
          l / 2. * (k(m) * e * e + ratio * k(m) * std::pow(e - alpha(m), 2)) +
          dt * l / 2. * t_r * ratio * k(m) * rate * rate;
      }
    return potential;
  }

  /**
   * Message of the exception thrown by @p f, or "" if none is, with every
   * run of white space made one blank: deal.II wraps its messages.
   */
  template <typename F>
  std::string
  flat_error_message(F f)
  {
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        std::string flat;
        for (const char c : std::string(e.what()))
          if (!std::isspace(static_cast<unsigned char>(c)))
            flat += c;
          else if (!flat.empty() && flat.back() != ' ')
            flat += ' ';
        return flat;
      }
    return "";
  }

  /**
   * Strain density of mode @p mode (0-2: kappa_m / l of a hinge of length
   * l; 3: the axial strain of a segment) of a virgin rod held at constant
   * stress @p load from t = 0, at the times @p t_c times @p at, by steps of
   * t_c / @p steps_per_creep_time: per step the scalar equation
   * stress(strain) = load is solved by Newton with the material's tangent
   * and the minimizing viscous strains are committed, as the assembly will.
   * For a segment, @p load is the axial force.
   */
  std::vector<double>
  creep(const StandardLinearSolid &material,
        const unsigned int         mode,
        const double               load,
        const unsigned int         steps_per_creep_time,
        const std::vector<double> &at)
  {
    const double l  = 0.04;
    const double dt = material.creep_time() / steps_per_creep_time;

    std::array<double, 3> committed{};
    std::array<double, 3> updated{};
    double                strain = 0.;
    std::vector<double>   densities;
    unsigned int          step = 0;
    for (const double t : at)
      {
        const unsigned int last =
          static_cast<unsigned int>(std::lround(t * steps_per_creep_time));
        for (; step < last; ++step)
          {
            // Stress and tangent of the one loaded mode.
            const auto evaluate = [&](const double x) -> std::array<double, 2> {
              if (mode == 3)
                {
                  const auto r = material.segment_increment(x,
                                                            l,
                                                            committed.data(),
                                                            dt,
                                                            updated.data());
                  return {{r.stress(0) / l, r.tangent(0) / l}};
                }
              const auto r =
                material.hinge_increment(l * x * Eigen::Vector3d::Unit(mode),
                                         l,
                                         committed.data(),
                                         dt,
                                         updated.data());
              return {{r.stress(mode), l * r.tangent(mode, mode)}};
            };

            for (unsigned int iteration = 0;; ++iteration)
              {
                const auto [stress, tangent] = evaluate(strain);
                if (std::abs(stress - load) <= 1e-13 * std::abs(load))
                  break;
                EXPECT_LT(iteration, 5u) << "Newton does not converge";
                strain -= (stress - load) / tangent;
              }
            committed = updated;
          }
        densities.push_back(strain);
      }
    return densities;
  }

  /// Exact creep strain sigma J(t) with the compliance of
  /// /work/shared/VALIDATION.md, in rigidities: J = 1/k (1 - r/(1+r)
  /// exp(-t/t_c)).
  double
  exact_creep(const double load,
              const double rigidity,
              const double r,
              const double t_over_tc)
  {
    return load / rigidity * (1. - r / (1. + r) * std::exp(-t_over_tc));
  }
} // namespace

namespace
{
  /**
   * Relative errors of the stress and tangent that @p increment (strain
   * vector -> MaterialResponse<n>) returns at @p strain, against central
   * differences of its energy and stress with step @p h. The condensed
   * energy is quadratic in the strain, so the differences have no
   * truncation error and h only balances round-off.
   */
  template <int n, typename Increment>
  std::array<double, 2>
  central_difference_errors(const Increment                   &increment,
                            const Eigen::Matrix<double, n, 1> &strain,
                            const double                       h)
  {
    const MaterialResponse<n>   response = increment(strain);
    Eigen::Matrix<double, n, 1> fd_stress;
    Eigen::Matrix<double, n, n> fd_tangent;
    for (unsigned int i = 0; i < n; ++i)
      {
        const Eigen::Matrix<double, n, 1> step =
          h * Eigen::Matrix<double, n, 1>::Unit(i);
        const MaterialResponse<n> plus  = increment(strain + step);
        const MaterialResponse<n> minus = increment(strain - step);
        fd_stress(i)      = (plus.energy - minus.energy) / (2. * h);
        fd_tangent.col(i) = (plus.stress - minus.stress) / (2. * h);
      }
    return {{(fd_stress - response.stress).norm() / response.stress.norm(),
             (fd_tangent - response.tangent).norm() / response.tangent.norm()}};
  }
} // namespace

TEST(StandardLinearSolid, StressAndTangentMatchCentralDifferences)
{
  const StandardLinearSolid material(relaxed, ratio, t_r);

  std::mt19937                           generator(20240917);
  std::uniform_real_distribution<double> bend(-0.3, 0.3);
  std::uniform_real_distribution<double> stretch(-0.1, 0.1);
  std::uniform_real_distribution<double> viscous(-20., 20.);
  std::uniform_real_distribution<double> length(0.01, 0.2);

  std::array<double, 2> hinge_max{}, segment_max{};
  for (const double factor : step_factors)
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        const double          dt = factor * t_r;
        const double          l  = length(generator);
        const Eigen::Vector3d kappa(bend(generator),
                                    bend(generator),
                                    bend(generator));
        const Eigen::Vector3d previous(viscous(generator),
                                       viscous(generator),
                                       viscous(generator));
        const auto            hinge = central_difference_errors<3>(
          [&](const Eigen::Vector3d &k) {
            Eigen::Vector3d updated;
            return material.hinge_increment(k,
                                            l,
                                            previous.data(),
                                            dt,
                                            updated.data());
          },
          kappa,
          1e-4);

        const double axial_previous = stretch(generator);
        const auto   segment        = central_difference_errors<1>(
          [&](const Eigen::Matrix<double, 1, 1> &eps) {
            double updated;
            return material.segment_increment(eps(0),
                                              l,
                                              &axial_previous,
                                              dt,
                                              &updated);
          },
          Eigen::Matrix<double, 1, 1>(stretch(generator)),
          1e-6);

        for (unsigned int k = 0; k < 2; ++k)
          {
            const char *what = k == 0 ? "stress" : "tangent";
            EXPECT_LE(hinge[k], 1e-6) << "hinge " << what << ", dt/t_r "
                                      << factor << ", sample " << sample;
            EXPECT_LE(segment[k], 1e-6) << "segment " << what << ", dt/t_r "
                                        << factor << ", sample " << sample;
            hinge_max[k]   = std::max(hinge_max[k], hinge[k]);
            segment_max[k] = std::max(segment_max[k], segment[k]);
          }
      }
  std::cout << "120 samples, dt/t_r 1e-6..1e3, max relative error: hinge "
            << "stress " << hinge_max[0] << ", tangent " << hinge_max[1]
            << "; segment stress " << segment_max[0] << ", tangent "
            << segment_max[1] << std::endl;
}

TEST(StandardLinearSolid, UpdateMinimizesTheIncrementalPotential)
{
  const StandardLinearSolid material(relaxed, ratio, t_r);

  std::mt19937                           generator(11);
  std::uniform_real_distribution<double> strain(-0.3, 0.3);
  std::uniform_real_distribution<double> viscous(-20., 20.);
  const double                           l = 0.05;

  for (const double factor : step_factors)
    for (unsigned int sample = 0; sample < 10; ++sample)
      {
        const double          dt = factor * t_r;
        const Eigen::Vector3d kappa(strain(generator),
                                    strain(generator),
                                    strain(generator));
        const Eigen::Vector3d previous(viscous(generator),
                                       viscous(generator),
                                       viscous(generator));
        Eigen::Vector3d       alpha;
        const auto            response =
          material.hinge_increment(kappa, l, previous.data(), dt, alpha.data());

        // The condensed energy is the potential at the returned minimizer...
        const double minimum = hinge_potential(kappa, l, alpha, previous, dt);
        EXPECT_NEAR(response.energy, minimum, 1e-12 * minimum)
          << "dt/t_r " << factor;

        // ... which satisfies the Maxwell branch's backward-Euler equation
        // eta alpha_dot = E2 (e - alpha), i.e. t_r alpha_dot = e - alpha ...
        for (unsigned int m = 0; m < 3; ++m)
          EXPECT_NEAR(t_r * (alpha(m) - previous(m)) / dt,
                      kappa(m) / l - alpha(m),
                      1e-8 * (std::abs(kappa(m) / l) + std::abs(previous(m))))
            << "dt/t_r " << factor << ", mode " << m;

        // ... and every other alpha does worse.
        for (unsigned int m = 0; m < 3; ++m)
          for (const double sign : {-1., 1.})
            {
              const Eigen::Vector3d other =
                alpha + sign * 1e-3 * (1. + std::abs(alpha(m))) *
                          Eigen::Vector3d::Unit(m);
              EXPECT_GT(hinge_potential(kappa, l, other, previous, dt), minimum)
                << "dt/t_r " << factor << ", mode " << m;
            }
      }
}

TEST(StandardLinearSolid, ShortAndLongStepLimits)
{
  const StandardLinearSolid material(relaxed, ratio, t_r);
  const RodStiffness        instantaneous{(1. + ratio) * relaxed.EA,
                                   (1. + ratio) * relaxed.EI1,
                                   (1. + ratio) * relaxed.EI2,
                                   (1. + ratio) * relaxed.GJ};
  const LinearElasticRod    glassy(instantaneous);
  const LinearElasticRod    rubbery(relaxed);

  const double          l = 0.06, l0 = 0.03, eps = 0.02;
  const Eigen::Vector3d kappa(0.01, -0.02, 0.015);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const double          none = 0.;

  // dt -> 0 from a virgin rod: both springs respond, E1 + E2, and the
  // viscous strain has no time to move.
  const double    short_step = 1e-10 * t_r;
  Eigen::Vector3d alpha;
  double          axial_alpha;
  const auto      hinge =
    material.hinge_increment(kappa, l, zero.data(), short_step, alpha.data());
  const auto segment =
    material.segment_increment(eps, l0, &none, short_step, &axial_alpha);
  const auto glassy_hinge   = glassy.hinge_energy(kappa, l);
  const auto glassy_segment = glassy.segment_energy(eps, l0);
  EXPECT_NEAR(hinge.energy, glassy_hinge.energy, 1e-9 * glassy_hinge.energy);
  EXPECT_LE((hinge.stress - glassy_hinge.stress).norm(),
            1e-9 * glassy_hinge.stress.norm());
  EXPECT_LE((hinge.tangent - glassy_hinge.tangent).norm(),
            1e-9 * glassy_hinge.tangent.norm());
  EXPECT_NEAR(segment.tangent(0),
              glassy_segment.tangent(0),
              1e-9 * glassy_segment.tangent(0));
  EXPECT_NEAR(segment.stress(0),
              glassy_segment.stress(0),
              1e-9 * glassy_segment.stress(0));
  EXPECT_LE(alpha.norm(), 1e-9 * kappa.norm() / l);
  EXPECT_LE(std::abs(axial_alpha), 1e-9 * eps);

  // Without history, hinge_energy() and segment_energy() are that
  // instantaneous response.
  EXPECT_NEAR(material.hinge_energy(kappa, l).energy,
              glassy_hinge.energy,
              1e-12 * glassy_hinge.energy);
  EXPECT_NEAR(material.segment_energy(eps, l0).tangent(0),
              glassy_segment.tangent(0),
              1e-12 * glassy_segment.tangent(0));

  // dt -> infinity: the dashpot has relaxed, alpha = e, only E1 remains,
  // whatever the history.
  const double          long_step = 1e10 * t_r;
  const Eigen::Vector3d previous(3., -1., 2.);
  const double          axial_previous  = -0.05;
  const auto            relaxed_hinge   = material.hinge_increment(kappa,
                                                      l,
                                                      previous.data(),
                                                      long_step,
                                                      alpha.data());
  const auto            relaxed_segment = material.segment_increment(eps,
                                                          l0,
                                                          &axial_previous,
                                                          long_step,
                                                          &axial_alpha);
  const auto            rubbery_hinge   = rubbery.hinge_energy(kappa, l);
  const auto            rubbery_segment = rubbery.segment_energy(eps, l0);
  EXPECT_NEAR(relaxed_hinge.energy,
              rubbery_hinge.energy,
              1e-8 * rubbery_hinge.energy);
  EXPECT_LE((relaxed_hinge.stress - rubbery_hinge.stress).norm(),
            1e-8 * rubbery_hinge.stress.norm());
  EXPECT_LE((relaxed_hinge.tangent - rubbery_hinge.tangent).norm(),
            1e-9 * rubbery_hinge.tangent.norm());
  EXPECT_NEAR(relaxed_segment.stress(0),
              rubbery_segment.stress(0),
              1e-8 * std::abs(rubbery_segment.stress(0)));
  EXPECT_NEAR(relaxed_segment.tangent(0),
              rubbery_segment.tangent(0),
              1e-9 * rubbery_segment.tangent(0));
  EXPECT_LE((alpha - kappa / l).norm(), 1e-9 * previous.norm());
  EXPECT_NEAR(axial_alpha, eps, 1e-9 * std::abs(axial_previous));
}

TEST(StandardLinearSolid, CreepMatchesExactComplianceInEveryMode)
{
  // E2 = 3 E1: the strain quadruples between t = 0 and t -> infinity, so
  // the creep is most of the response.
  const double                r = 3.;
  const StandardLinearSolid   material(relaxed, r, t_r);
  const std::array<double, 4> rigidity{
    {relaxed.EI1, relaxed.EI2, relaxed.GJ, relaxed.EA}};
  const std::array<double, 4> load{{0.8, -1.1, 0.3, 25.}};
  const std::vector<double>   at{1., 3., 10.};

  for (unsigned int mode = 0; mode < 4; ++mode)
    {
      const auto strain = creep(material, mode, load[mode], 100, at);
      for (unsigned int i = 0; i < at.size(); ++i)
        {
          const double exact =
            exact_creep(load[mode], rigidity[mode], r, at[i]);
          const double error = std::abs(strain[i] - exact) / std::abs(exact);
          std::cout << "mode " << mode << ", t/t_c = " << at[i]
                    << ", dt = t_c/100: strain " << strain[i] << ", exact "
                    << exact << ", relative error " << error << std::endl;
          EXPECT_LE(error, 0.01) << "mode " << mode << ", t/t_c " << at[i];
        }
    }
}

TEST(StandardLinearSolid, CreepConvergesWithFirstOrderInTheTimeStep)
{
  const double              r = 3.;
  const StandardLinearSolid material(relaxed, r, t_r);
  const double              exact = exact_creep(1., relaxed.EI1, r, 1.);

  double previous_error = 0.;
  for (const unsigned int steps : {10u, 20u, 40u, 80u, 160u, 320u})
    {
      const double error =
        std::abs(creep(material, 0, 1., steps, {1.})[0] - exact) / exact;
      std::cout << "creep at t_c, dt = t_c/" << steps << ": relative error "
                << error;
      if (previous_error > 0.)
        {
          const double order = std::log2(previous_error / error);
          std::cout << ", observed order " << order;
          EXPECT_NEAR(order, 1., 0.1) << "dt = t_c/" << steps;
        }
      std::cout << std::endl;
      previous_error = error;
    }
}

TEST(StandardLinearSolid, StressRelaxationAtConstantStrain)
{
  // Held strain: sigma(t) = E(t) eps with E(t) = E1 + E2 exp(-t/t_r)
  // (VALIDATION.md); backward Euler decays the Maxwell stress by
  // t_r / (t_r + dt) per step.
  const StandardLinearSolid material(relaxed, ratio, t_r);
  const double              eps = 0.01, l0 = 0.02;
  const unsigned int        steps_per_relaxation_time = 200;
  const double              dt = t_r / steps_per_relaxation_time;

  double committed = 0., updated;
  for (unsigned int step = 1; step <= 3 * steps_per_relaxation_time; ++step)
    {
      const auto response =
        material.segment_increment(eps, l0, &committed, dt, &updated);
      committed = updated;
      if (step % steps_per_relaxation_time == 0)
        {
          const double t = step * dt;
          const double exact =
            relaxed.EA * eps * (1. + ratio * std::exp(-t / t_r));
          const double force = response.stress(0) / l0;
          std::cout << "relaxation at t/t_r = " << t / t_r << ": force "
                    << force << ", exact " << exact << std::endl;
          EXPECT_NEAR(force, exact, 1e-3 * exact);
        }
    }
}

TEST(StandardLinearSolid, ElasticMaterialHasNoHistory)
{
  const LinearElasticRod elastic(relaxed, {3.1, -1.7, 0.8, 0.012});
  const RodMaterial     &material = elastic;

  EXPECT_EQ(material.n_hinge_internal_variables(), 0u);
  EXPECT_EQ(material.n_segment_internal_variables(), 0u);
  EXPECT_TRUE(material.hinge_internal_variable_names().empty());
  EXPECT_TRUE(material.segment_internal_variable_names().empty());

  const Eigen::Vector3d kappa(0.02, -0.01, 0.03);
  // The time step is ignored, even one a viscous material would refuse.
  for (const double dt : {0., 1e-3, 1e3})
    {
      const auto increment =
        material.hinge_increment(kappa, 0.05, nullptr, dt, nullptr);
      const auto energy = material.hinge_energy(kappa, 0.05);
      EXPECT_EQ(increment.energy, energy.energy);
      EXPECT_EQ(increment.stress, energy.stress);
      EXPECT_EQ(increment.tangent, energy.tangent);

      const auto segment_increment =
        material.segment_increment(0.03, 0.02, nullptr, dt, nullptr);
      const auto segment_energy = material.segment_energy(0.03, 0.02);
      EXPECT_EQ(segment_increment.energy, segment_energy.energy);
      EXPECT_EQ(segment_increment.stress, segment_energy.stress);
      EXPECT_EQ(segment_increment.tangent, segment_energy.tangent);
    }
}

TEST(StandardLinearSolid, InternalVariablesAreNamed)
{
  const StandardLinearSolid material(relaxed, ratio, t_r);
  EXPECT_EQ(material.n_hinge_internal_variables(), 3u);
  EXPECT_EQ(material.n_segment_internal_variables(), 1u);
  EXPECT_EQ(material.hinge_internal_variable_names().size(), 3u);
  EXPECT_EQ(material.segment_internal_variable_names().size(), 1u);
  EXPECT_DOUBLE_EQ(material.creep_time(), t_r * (1. + ratio));
}

// A step of zero length lets nothing flow: the stored energy
// l/2 [k e^2 + r k (e - alpha)^2] at the committed alpha, and alpha kept.
TEST(StandardLinearSolid, ZeroTimeStepIsStoredEnergy)
{
  const StandardLinearSolid material(relaxed, ratio, t_r);
  const double              l = 0.05;
  const Eigen::Vector3d     kappa(0.01, -0.02, 0.005), previous(0.1, 0.2, -0.3);
  Eigen::Vector3d           updated;
  const MaterialResponse<3> w =
    material.hinge_increment(kappa, l, previous.data(), 0.0, updated.data());
  const Eigen::Vector3d k(relaxed.EI1, relaxed.EI2, relaxed.GJ);
  double                expected = 0;
  for (unsigned int m = 0; m < 3; ++m)
    {
      const double e = kappa[m] / l;
      expected +=
        l / 2 * (k[m] * e * e + ratio * k[m] * std::pow(e - previous[m], 2));
      EXPECT_DOUBLE_EQ(updated[m], previous[m]);
    }
  EXPECT_NEAR(w.energy, expected, 1e-14 * expected);
}

TEST(StandardLinearSolid, RejectsNegativeTimeStep)
{
  const StandardLinearSolid material(relaxed, ratio, t_r);
  const Eigen::Vector3d     kappa(0.01, 0., 0.), previous(0., 0., 0.);
  Eigen::Vector3d           updated;
  double                    axial = 0., axial_updated;

  for (const double dt : {-1e-3, double(NAN), double(INFINITY)})
    {
      try
        {
          material.hinge_increment(kappa,
                                   0.05,
                                   previous.data(),
                                   dt,
                                   updated.data());
          ADD_FAILURE() << "hinge_increment accepted dt = " << dt;
        }
      catch (const std::invalid_argument &e)
        {
          EXPECT_NE(std::string(e.what()).find(
                      "time step must be finite and not negative"),
                    std::string::npos)
            << e.what();
        }
      EXPECT_THROW(
        material.segment_increment(0.01, 0.02, &axial, dt, &axial_updated),
        std::invalid_argument)
        << "dt = " << dt;
    }
}

TEST(StandardLinearSolid, RejectsInadmissibleConstantsByName)
{
  const auto message = [](const RodStiffness &k, double r, double t) {
    return flat_error_message([&] { StandardLinearSolid(k, r, t); });
  };
  const auto names = [](const std::string &text, const std::string &entry) {
    return text.find("standard linear solid: entry \"" + entry + "\"") !=
           std::string::npos;
  };

  EXPECT_TRUE(names(message({1., 0., 1., 1.}, ratio, t_r), "EI1"));
  EXPECT_TRUE(names(message({1., 1., 1., NAN}, ratio, t_r), "GJ"));
  EXPECT_TRUE(names(message({-1., 1., 1., 1.}, ratio, t_r), "EA"));

  // No Maxwell spring (E2 = 0, whatever eta), a negative or infinite one.
  for (const double r : {0., -0.5, double(NAN), double(INFINITY)})
    {
      const std::string text = message(relaxed, r, t_r);
      EXPECT_TRUE(names(text, "Modulus ratio E2/E1")) << text;
    }
  EXPECT_NE(message(relaxed, 0., t_r).find("use \"linear elastic\" with E1"),
            std::string::npos)
    << message(relaxed, 0., t_r);

  // No dashpot (eta = 0 with E2 > 0) or a rigid one.
  for (const double t : {0., -1., double(NAN), double(INFINITY)})
    {
      const std::string text = message(relaxed, ratio, t);
      EXPECT_TRUE(names(text, "Relaxation time")) << text;
    }
}

namespace
{
  /// Creates "standard linear solid" through the registry, as a scene does,
  /// and reads it from @p entries placed in its subsection.
  StandardLinearSolid
  parse_standard_linear_solid(const std::string &entries)
  {
    const std::unique_ptr<RodMaterial> material =
      MaterialRegistry::instance().create("standard linear solid");

    dealii::ParameterHandler prm;
    prm.enter_subsection("standard linear solid");
    material->declare_parameters(prm);
    prm.leave_subsection();

    prm.parse_input_from_string("subsection standard linear solid\n" + entries +
                                "\nend\n");
    prm.enter_subsection("standard linear solid");
    material->parse_parameters(prm);
    prm.leave_subsection();

    const auto *sls = dynamic_cast<const StandardLinearSolid *>(material.get());
    EXPECT_NE(sls, nullptr);
    return *sls;
  }
} // namespace

TEST(StandardLinearSolid, ParametersFromSection)
{
  const double E1 = 1e8, r = 5e-3, pi = dealii::numbers::PI;
  const auto  sls = parse_standard_linear_solid("set Young's modulus E1 = 1e8\n"
                                                "set Poisson's ratio = 0.5\n"
                                                "set Radius = 5e-3\n"
                                                "set Modulus ratio E2/E1 = 0.3\n"
                                                "set Relaxation time = 0.00334");
  const auto &k   = sls.relaxed_stiffness();
  EXPECT_DOUBLE_EQ(k.EA, E1 * pi * r * r);
  EXPECT_DOUBLE_EQ(k.EI1, E1 * pi * std::pow(r, 4) / 4.);
  EXPECT_DOUBLE_EQ(k.EI2, E1 * pi * std::pow(r, 4) / 4.);
  EXPECT_DOUBLE_EQ(k.GJ, E1 / 3. * pi * std::pow(r, 4) / 2.);
  EXPECT_EQ(sls.modulus_ratio(), 0.3);
  EXPECT_EQ(sls.relaxation_time(), 0.00334);
}

TEST(StandardLinearSolid, ParametersDirect)
{
  const auto sls =
    parse_standard_linear_solid("set Stiffness input = direct\n"
                                "set EA = 1e4\nset EI1 = 0.25\nset EI2 = 0.5\n"
                                "set GJ = 0.125\n"
                                "set Modulus ratio E2/E1 = 2\n"
                                "set Relaxation time = 1.5");
  EXPECT_EQ(sls.relaxed_stiffness().EA, 1e4);
  EXPECT_EQ(sls.relaxed_stiffness().EI1, 0.25);
  EXPECT_EQ(sls.relaxed_stiffness().EI2, 0.5);
  EXPECT_EQ(sls.relaxed_stiffness().GJ, 0.125);
  EXPECT_EQ(sls.creep_time(), 4.5);
  // The instantaneous bending rigidity is (1 + E2/E1) E1 I1.
  EXPECT_DOUBLE_EQ(sls.hinge_energy({0.1, 0., 0.}, 1.).tangent(0, 0), 0.75);
}

TEST(StandardLinearSolid, ParameterErrorsNameTheEntry)
{
  const auto message = [](const std::string &entries) {
    return flat_error_message([&] { parse_standard_linear_solid(entries); });
  };
  const std::string viscous = "set Modulus ratio E2/E1 = 0.3\n"
                              "set Relaxation time = 1\n";
  const std::string section = "set Young's modulus E1 = 1e8\n"
                              "set Radius = 1e-3\n";

  const std::array<std::pair<std::string, std::string>, 7> cases{{
    {section + "set Relaxation time = 1", "\"Modulus ratio E2/E1\""},
    {section + "set Modulus ratio E2/E1 = 0.3", "\"Relaxation time\""},
    {viscous + "set Radius = 1e-3", "\"Young's modulus E1\""},
    {viscous + section + "set Poisson's ratio = -1", "\"Poisson's ratio\""},
    {viscous + "set Young's modulus E1 = 1e8", "\"Radius\""},
    {viscous + "set Stiffness input = direct\n"
               "set EI1 = 1\nset EI2 = 1\nset GJ = 1",
     "\"EA\""},
    {viscous + section + "set Relaxation time = -2", "Relaxation time"},
  }};
  for (const auto &[entries, entry] : cases)
    {
      const std::string text = message(entries);
      EXPECT_NE(text.find(entry), std::string::npos)
        << "input\n"
        << entries << "\ngave \"" << text << "\"";
    }
}
