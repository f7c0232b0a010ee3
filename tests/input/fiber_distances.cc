// The fiber distances of the strain-range check from a scene's section
// (Scene::fiber_distances()): per bending axis, so that a flat section
// bent in its soft direction is measured by its thickness.
#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>

#include <cmath>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  TEST(FiberDistances, PerBendingAxisOfARectangle)
  {
    // Width w along d1, height h along d2: bending about d1 strains the
    // fibers at h/2 (reported 2 sqrt(I1/A) = h/sqrt(3)), about d2 those at
    // w/2 (w/sqrt(3)).
    const double             w = 0.04, h = 0.001;
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n"
                                "  set Generator = straight\n"
                                "  set Segments = 4\n"
                                "end\n"
                                "subsection Material\n"
                                "  subsection linear elastic\n"
                                "    set Young's modulus = 1e9\n"
                                "    set Cross section = rectangle\n"
                                "    set Width = " +
                                std::to_string(w) +
                                "\n"
                                "    set Height = " +
                                std::to_string(h) +
                                "\n"
                                "  end\n"
                                "end\n"
                                "subsection Supports\n"
                                "  set Clamped ends = start\n"
                                "end\n");
    const Scene scene(prm);
    const auto  c = scene.fiber_distances();
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0][0], h / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(c[0][1], w / std::sqrt(3.0), 1e-15);
  }
} // namespace
