// Axial stiffness of a slender helical spring (VALIDATION.md): the shipped
// scene scenes/helical_spring.prm, a spring wound stress free (Natural
// shape = initial geometry) and clamped on the coil at both ends, against
// k = G d^4 / (8 D^3 n) with the pitch correction, for both hinge kernels;
// and the end effect of the clamps fading as the turns grow
// (doc/validation.md, "Helical spring", has the whole study of turns and
// segments per turn, bench/helical_spring.cc).
#include <common/helical_spring.h>

#include <gtest/gtest.h>
#include <iostream>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  class HelicalSpring : public ::testing::TestWithParam<std::string>
  {
  };

  // 16 turns of 64 segments: k / k_ideal - 1 = 2.8e-3 (simple), 5.3e-3
  // (classic); against VALIDATION.md's correction 4.9e-3, 7.3e-3.
  TEST_P(HelicalSpring, ShippedSceneMatchesTheSpringFormula)
  {
    const double k = helical_spring_stiffness(0, 0, GetParam());
    std::cout << GetParam() << ": k = " << k << " N/m, ideal "
              << ideal_spring_stiffness(16) << ", VALIDATION.md "
              << validation_md_stiffness(16) << ", close-coiled "
              << close_coiled_stiffness(16) << std::endl;
    EXPECT_NEAR(k, ideal_spring_stiffness(16), 0.01 * k);
    EXPECT_NEAR(k, validation_md_stiffness(16), 0.01 * k);
  }

  // At 64 segments per turn k / k_ideal - 1 is 6.2e-3, 2.8e-3, 1.5e-3 for
  // 8, 16, 32 turns (simple; classic 8.7e-3, 5.3e-3, 3.9e-3, whose
  // discretization error is larger): the clamps' end effect falls as 1 / n.
  TEST_P(HelicalSpring, EndEffectFadesWithTheTurns)
  {
    double previous = 1;
    for (const unsigned int turns : {8u, 16u, 32u})
      {
        const double excess = helical_spring_stiffness(turns, 64, GetParam()) /
                                ideal_spring_stiffness(turns) -
                              1;
        std::cout << GetParam() << ", " << turns
                  << " turns: k / k_ideal - 1 = " << excess << std::endl;
        // Clamps stiffen the spring; the excess shrinks with the turns.
        EXPECT_GT(excess, 0);
        EXPECT_LT(excess, previous);
        previous = excess;
      }
    EXPECT_LT(previous, 0.005);
  }

  INSTANTIATE_TEST_SUITE_P(BothKernels,
                           HelicalSpring,
                           ::testing::Values("simple", "classic"));
} // namespace
