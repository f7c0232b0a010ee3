// Cross-section constants against closed forms and Saint-Venant's tabulated
// torsion coefficients.

#include <deal.II/base/numbers.h>

#include <materials/cross_section.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>

using namespace rodnet;

namespace
{
  const double section_pi = dealii::numbers::PI;

  /// Message of the exception thrown by @p f, or "" if none is.
  template <typename F>
  std::string
  section_error_message(F f)
  {
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

TEST(CrossSection, Circle)
{
  const double r = 3e-3;
  const auto   c = circle_section(r);
  EXPECT_DOUBLE_EQ(c.area, section_pi * r * r);
  EXPECT_DOUBLE_EQ(c.I1, section_pi * std::pow(r, 4) / 4.);
  EXPECT_DOUBLE_EQ(c.I2, section_pi * std::pow(r, 4) / 4.);
  EXPECT_DOUBLE_EQ(c.J, section_pi * std::pow(r, 4) / 2.);
}

TEST(CrossSection, SquareTorsionMatchesTable)
{
  // Timoshenko & Goodier's table of J = k a b^3: k = 0.1406 for a = b.
  const double a = 0.02;
  EXPECT_NEAR(rectangle_section(a, a).J / std::pow(a, 4), 0.1406, 1e-3);
}

TEST(CrossSection, RectangleTorsionMatchesTable)
{
  // Same table, a/b = 2 and 10 (three digits given).
  const double b = 0.01;
  EXPECT_NEAR(rectangle_section(2. * b, b).J / (2. * b * b * b * b),
              0.229,
              1e-3);
  EXPECT_NEAR(rectangle_section(b, 10. * b).J / (10. * b * b * b * b),
              0.312,
              1e-3);
}

TEST(CrossSection, ThinStripTorsion)
{
  // a/b = 100: J -> a b^3 / 3 (1 - 0.630 b/a).
  const double a = 0.1, b = 1e-3;
  const double thin = a * b * b * b / 3. * (1. - 0.630 * b / a);
  EXPECT_NEAR(rectangle_section(a, b).J, thin, 5e-3 * thin);
  EXPECT_NEAR(rectangle_section(b, a).J, thin, 5e-3 * thin);
}

TEST(CrossSection, RectangleMomentsFollowDirectors)
{
  // Width along d1, height along d2: I1 = int y2^2 dA = w h^3 / 12.
  const double w = 0.3, h = 0.1;
  const auto   rect = rectangle_section(w, h);
  EXPECT_DOUBLE_EQ(rect.area, w * h);
  EXPECT_DOUBLE_EQ(rect.I1, 2.5e-5);
  EXPECT_DOUBLE_EQ(rect.I2, 2.25e-4);
  // A section wide along d1 resists bending about d2 more.
  EXPECT_GT(rect.I2, rect.I1);
  EXPECT_DOUBLE_EQ(rect.J, rectangle_section(h, w).J);
}

TEST(CrossSection, Explicit)
{
  const auto s = explicit_section(1., 2., 3., 4.);
  EXPECT_EQ(s.area, 1.);
  EXPECT_EQ(s.I1, 2.);
  EXPECT_EQ(s.I2, 3.);
  EXPECT_EQ(s.J, 4.);
}

TEST(CrossSection, RejectsInadmissibleDimensionsByName)
{
  EXPECT_NE(section_error_message([] {
              circle_section(0.);
            }).find("\"Radius\""),
            std::string::npos);
  EXPECT_NE(section_error_message([] {
              circle_section(NAN);
            }).find("\"Radius\""),
            std::string::npos);
  EXPECT_NE(section_error_message([] {
              rectangle_section(1., -1.);
            }).find("\"Height\""),
            std::string::npos);
  EXPECT_NE(section_error_message([] {
              rectangle_section(INFINITY, 1.);
            }).find("\"Width\""),
            std::string::npos);
  EXPECT_NE(section_error_message([] {
              explicit_section(1., 1., 0., 1.);
            }).find("\"I2\""),
            std::string::npos);
}
