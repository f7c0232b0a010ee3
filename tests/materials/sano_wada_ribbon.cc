// SanoWadaRibbon (Korner et al. eq. 5.5): stress and tangent against
// central differences in every regime of the quartic term, the energy
// against a hand evaluation of eq. 5.5 in the paper's own ordering, the
// small-strain limit against the quadratic rod, which bending is the soft
// one, and the scene entries with their errors.

#include <deal.II/base/parameter_handler.h>

#include <materials/linear_elastic_rod.h>
#include <materials/rod_material.h>
#include <materials/sano_wada_ribbon.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <string>

using namespace rodnet;

namespace
{
  /// A PET strip like Sano & Wada's, in SI units: Y, nu, w, h.
  const RibbonConstants pet_strip{4e9, 0.4, 8e-3, 2e-4};

  /// The Voronoi length of 350 hinges on L = pi 108 mm.
  constexpr double ribbon_hinge = 9.7e-4;

  /// l / xi of pet_strip at ribbon_hinge, with xi^2 = (1 - nu^2) w^4 /
  /// (60 h^2) written out here: the strain scale where the quartic term
  /// sets in.
  double
  onset_strain()
  {
    const double xi2 = (1 - 0.4 * 0.4) * std::pow(8e-3, 4) / (60 * 4e-8);
    return ribbon_hinge / std::sqrt(xi2);
  }

  /// Central differences of the energy (stress) and of the stress
  /// (tangent) at @p kappa, with the step along kappa_i 1e-6 of
  /// max(|kappa_i|, @p scale): the quartic term varies with kappa_1 on the
  /// scale sqrt(l^2/xi^2 + kappa_1^2), not on that of the largest strain.
  std::pair<Eigen::Vector3d, Eigen::Matrix3d>
  central_differences(const SanoWadaRibbon  &ribbon,
                      const Eigen::Vector3d &kappa,
                      const double           scale)
  {
    Eigen::Vector3d stress;
    Eigen::Matrix3d tangent;
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double          h    = 1e-6 * std::max(std::abs(kappa(i)), scale);
        const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(i);
        const auto plus  = ribbon.hinge_energy(kappa + step, ribbon_hinge);
        const auto minus = ribbon.hinge_energy(kappa - step, ribbon_hinge);
        stress(i)        = (plus.energy - minus.energy) / (2 * h);
        tangent.col(i)   = (plus.stress - minus.stress) / (2 * h);
      }
    return {stress, tangent};
  }

  /// Creates "sano-wada ribbon" through the registry, as a scene does, and
  /// reads it from @p entries placed in its subsection.
  std::unique_ptr<RodMaterial>
  parse_ribbon(const std::string &entries)
  {
    auto material = MaterialRegistry::instance().create("sano-wada ribbon");
    dealii::ParameterHandler prm;
    prm.enter_subsection("sano-wada ribbon");
    material->declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection sano-wada ribbon\n" + entries +
                                "\nend\n");
    prm.enter_subsection("sano-wada ribbon");
    material->parse_parameters(prm);
    prm.leave_subsection();
    return material;
  }

  /// Message of the exception @p entries cause, its lines joined (deal.II
  /// wraps the text of ExcMessage), or "" if none.
  std::string
  ribbon_error(const std::string &entries)
  {
    try
      {
        parse_ribbon(entries);
      }
    catch (const std::exception &e)
      {
        std::istringstream words(e.what());
        std::string        line, word;
        while (words >> word)
          line += (line.empty() ? "" : " ") + word;
        return line;
      }
    return "";
  }
} // namespace

TEST(SanoWadaRibbon, DerivativesMatchCentralDifferencesInEveryRegime)
{
  // Strains in units of s = l / xi (0.026 here): general states, no soft
  // bending (kappa_1 = 0), no twist, twist far past the onset (|kappa_3| up
  // to 300 s, where the quartic term dominates), and states near zero.
  // Steps of 1e-6 of each strain's scale (central_differences) leave a
  // truncation error ~1e-12 and a round-off error ~1e-10 relative; 1e-7
  // of the response's scale allowed.
  const SanoWadaRibbon                   ribbon(pet_strip);
  const double                           s = onset_strain();
  std::mt19937                           generator(20250215);
  std::uniform_real_distribution<double> unit(-1., 1.);

  struct Regime
  {
    const char *name;
    double      soft, stiff, twist;
  };
  const Regime regimes[] = {{"general", 3, 3, 3},
                            {"no soft bending", 0, 3, 3},
                            {"no twist", 3, 3, 0},
                            {"large twist", 0.5, 1, 200},
                            {"near zero", 1e-3, 1e-3, 1e-3}};
  for (const Regime &regime : regimes)
    for (unsigned int sample = 0; sample < 30; ++sample)
      {
        Eigen::Vector3d kappa(regime.soft * s * unit(generator),
                              regime.stiff * s * unit(generator),
                              regime.twist * s * unit(generator));
        if (std::string(regime.name) == "large twist")
          kappa(2) += std::copysign(100 * s, kappa(2));
        const auto response = ribbon.hinge_energy(kappa, ribbon_hinge);
        const auto [fd_stress, fd_tangent] =
          central_differences(ribbon, kappa, s);
        const double scale_stress =
          std::max(response.stress.norm(),
                   response.tangent.norm() * kappa.norm());
        EXPECT_LE((fd_stress - response.stress).norm(), 1e-7 * scale_stress)
          << regime.name << " " << kappa.transpose() << ": analytic "
          << response.stress.transpose() << ", differences "
          << fd_stress.transpose();
        EXPECT_LE((fd_tangent - response.tangent).norm(),
                  1e-7 * response.tangent.norm())
          << regime.name << " " << kappa.transpose() << ":\nanalytic\n"
          << response.tangent << "\ndifferences\n"
          << fd_tangent;
        EXPECT_DOUBLE_EQ(response.tangent(0, 2), response.tangent(2, 0));
      }
}

TEST(SanoWadaRibbon, EnergyIsEquation55WithTheSoftBendingAboutD1)
{
  // Eq. 5.5 evaluated by hand (30 digits) in the paper's ordering: Y = 1e6,
  // nu = 0.5, w = 0.02, h = 0.001, l = 0.01, so A1 = 6.667e-4,
  // A2 = 1.667e-6, A3 = 2.222e-6, xi^2 = 0.002; the paper's stiff
  // kappa_1 = 0.01, soft kappa_2 = 0.2, kappa_3 = 0.5:
  //   E = 9.23148148148148148e-5, of which the quartic term
  //   A2 kappa_3^4 / (l^2/xi^2 + kappa_2^2) / (2 l) = 5.78703703703704e-5.
  // In rodnet's convention the soft strain is kappa_1 (about d1, along
  // which the width lies) and the stiff one kappa_2.
  const double         Y = 1e6, nu = 0.5, w = 0.02, h = 0.001, l = 0.01;
  const SanoWadaRibbon ribbon({Y, nu, w, h});
  const double         energy = ribbon.hinge_energy({0.2, 0.01, 0.5}, l).energy;
  EXPECT_NEAR(energy, 9.23148148148148148e-5, 1e-14 * 9.23e-5);
  const double quadratic =
    (Y * h * h * h * w / 12 * 0.2 * 0.2 + Y * h * w * w * w / 12 * 0.01 * 0.01 +
     Y * h * h * h * w / (6 * (1 + nu)) * 0.5 * 0.5) /
    (2 * l);
  EXPECT_NEAR(energy - quadratic, 5.78703703703704e-5, 1e-12 * 5.79e-5);
  // The paper's ordering read as rodnet's (the stiff strain about d1)
  // gives another energy.
  EXPECT_GT(std::abs(ribbon.hinge_energy({0.01, 0.2, 0.5}, l).energy -
                     9.23148148148148148e-5),
            1e-5);
}

TEST(SanoWadaRibbon, TwistCouplesWithTheSoftBendingOnly)
{
  // The twist's energy E(kappa) - E(kappa without twist) does not depend
  // on the stiff bending kappa_2 (to the rounding of the energies, 1e-13 of
  // them allowed) and
  // falls as the soft bending kappa_1 grows: a bent ribbon twists more
  // easily (Sano & Wada's l^2/xi^2 + kappa^2 denominator).
  const SanoWadaRibbon ribbon(pet_strip);
  const double         s  = onset_strain();
  const double         l  = ribbon_hinge;
  const auto twist_energy = [&](const double soft, const double stiff) {
    return ribbon.hinge_energy({soft, stiff, 2 * s}, l).energy -
           ribbon.hinge_energy({soft, stiff, 0.}, l).energy;
  };
  const double straight = twist_energy(0, 0);
  const double total    = ribbon.hinge_energy({0, -50 * s, 2 * s}, l).energy;
  EXPECT_NEAR(twist_energy(0, 5 * s), straight, 1e-12 * straight);
  EXPECT_NEAR(twist_energy(0, -50 * s), straight, 1e-13 * total);
  EXPECT_LT(twist_energy(s, 0), 0.9 * straight);
  EXPECT_LT(twist_energy(5 * s, 0), twist_energy(s, 0));
}

TEST(SanoWadaRibbon, SmallStrainsAreTheQuadraticRodWithTheStripModuli)
{
  // Far below the onset (strains 1e-4 l / xi) the quartic term is 1e-8 of
  // the quadratic ones: the ribbon is the linear elastic rod with
  // EI1 = Y h^3 w / 12 (soft, about d1), EI2 = Y h w^3 / 12 (stiff, about
  // d2), GJ = Y h^3 w / (6 (1 + nu)), EA = Y w h, written out here.
  const double                           Y = 4e9, nu = 0.4, w = 8e-3, h = 2e-4;
  const LinearElasticRod                 rod(RodStiffness{Y * w * h,
                                          Y * h * h * h * w / 12,
                                          Y * h * w * w * w / 12,
                                          Y * h * h * h * w / (6 * (1 + nu))});
  const SanoWadaRibbon                   ribbon(pet_strip);
  const double                           s = 1e-4 * onset_strain();
  std::mt19937                           generator(11);
  std::uniform_real_distribution<double> unit(-1., 1.);
  for (unsigned int sample = 0; sample < 20; ++sample)
    {
      const Eigen::Vector3d kappa(s * unit(generator),
                                  s * unit(generator),
                                  s * unit(generator));
      const auto            ours   = ribbon.hinge_energy(kappa, ribbon_hinge);
      const auto            linear = rod.hinge_energy(kappa, ribbon_hinge);
      EXPECT_NEAR(ours.energy, linear.energy, 1e-7 * linear.energy);
      EXPECT_LE((ours.stress - linear.stress).norm(),
                1e-7 * linear.stress.norm());
      EXPECT_LE((ours.tangent - linear.tangent).norm(),
                1e-7 * linear.tangent.norm());
    }
  // At zero strain the tangent is exactly diag(EI1, EI2, GJ) / l, the soft
  // modulus Y h^3 w / 12 about d1 (kappa_1), 1600 times less than the
  // stiff one about d2: (w / h)^2 = 1600.
  const auto at_rest = ribbon.hinge_energy(Eigen::Vector3d::Zero(), 0.5);
  EXPECT_NEAR(at_rest.tangent(0, 0) * 0.5 / (Y * h * h * h * w / 12), 1, 1e-15);
  EXPECT_NEAR(at_rest.tangent(1, 1) * 0.5 / (Y * h * w * w * w / 12), 1, 1e-15);
  EXPECT_NEAR(at_rest.tangent(1, 1) / at_rest.tangent(0, 0), 1600, 1e-9);
  const auto segment = ribbon.segment_energy(0.01, 0.3);
  EXPECT_NEAR(segment.energy / (0.5 * 0.3 * Y * w * h * 1e-4), 1, 1e-15);
  EXPECT_NEAR(segment.stress(0) / (0.3 * Y * w * h * 0.01), 1, 1e-15);
  EXPECT_NEAR(segment.tangent(0) / (0.3 * Y * w * h), 1, 1e-15);
}

TEST(SanoWadaRibbon, SceneEntriesGiveTheModuliAndTheSection)
{
  const auto  material = parse_ribbon("set Young's modulus = 4e9\n"
                                      "set Poisson's ratio = 0.4\n"
                                      "set Width = 8e-3\nset Thickness = 2e-4");
  const auto *ribbon   = dynamic_cast<const SanoWadaRibbon *>(material.get());
  ASSERT_NE(ribbon, nullptr);
  const RibbonModuli &m = ribbon->moduli();
  EXPECT_NEAR(m.soft_bending / (4e9 * 8e-12 * 8e-3 / 12), 1, 1e-15);
  EXPECT_NEAR(m.stiff_bending / (4e9 * 2e-4 * 5.12e-7 / 12), 1, 1e-15);
  EXPECT_NEAR(m.twisting / (4e9 * 8e-12 * 8e-3 / (6 * 1.4)), 1, 1e-15);
  EXPECT_NEAR(m.xi_squared / (0.84 * 4.096e-9 / (60 * 4e-8)), 1, 1e-15);
  EXPECT_NEAR(m.axial / (4e9 * 8e-3 * 2e-4), 1, 1e-15);
  // Width along d1: I1 = w h^3 / 12, the section time stepping takes.
  ASSERT_TRUE(material->cross_section().has_value());
  EXPECT_NEAR(material->cross_section()->area / 1.6e-6, 1, 1e-15);
  EXPECT_NEAR(material->cross_section()->I1 / (8e-3 * 8e-12 / 12), 1, 1e-15);
  // Not a linear elastic rod, so no dynamic relaxation; no natural shape.
  EXPECT_FALSE(material->straight_linear_elastic_stiffness().has_value());
  EXPECT_THROW(material->with_natural_shape_scaled({true, true, true}, 0.5),
               std::invalid_argument);
}

TEST(SanoWadaRibbon, ErrorsNameTheEntry)
{
  const std::string width = "set Width = 8e-3\n";
  const std::string thick = "set Thickness = 2e-4\n";
  const std::string young = "set Young's modulus = 4e9\n";
  struct Case
  {
    std::string entries, expected;
  };
  const Case cases[] = {
    {width + thick, "entry \"Young's modulus\" must be positive"},
    {young + thick, "entry \"Width\" must be positive"},
    {young + width, "entry \"Thickness\" must be positive"},
    {young + "set Width = 1e-4\n" + thick,
     "entry \"Thickness\" must be less than \"Width\" = 0.0001 (the model "
     "is that of a thin ribbon), got 0.0002"},
    {young + width + thick + "set Poisson's ratio = -1",
     "entry \"Poisson's ratio\" must lie in (-1, 0.5]"},
    {"set Young's modulus = 1e90\nset Width = 1e5\nset Thickness = 1e-3",
     "the stiff bending modulus Y h w^3 / 12 = 8.33333e+100 from \"Young's "
     "modulus\", \"Width\" and \"Thickness\" must be positive and at most "
     "1e100"},
    {"set Young's modulus = 1e-100\nset Width = 1e-90\n"
     "set Thickness = 1e-100",
     "the soft bending modulus Y h^3 w / 12 = 0"}};
  for (const Case &c : cases)
    {
      const std::string message = ribbon_error(c.entries);
      EXPECT_NE(message.find("sano-wada ribbon: "), std::string::npos)
        << message;
      EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected \"" << c.expected << "\" in: " << message;
    }
}

TEST(SanoWadaRibbon, RegisteredWithoutChangingTheDefaultMaterial)
{
  // Names sort by byte: a capital first letter would come before
  // "linear elastic" and make the ribbon every scene's default Model.
  const std::vector<std::string> names = MaterialRegistry::instance().names();
  EXPECT_EQ(names.front(), "linear elastic");
  EXPECT_NE(std::find(names.begin(), names.end(), "sano-wada ribbon"),
            names.end());
  EXPECT_NE(MaterialRegistry::instance()
              .description("sano-wada ribbon")
              .find("eq. 5.5"),
            std::string::npos);
}
