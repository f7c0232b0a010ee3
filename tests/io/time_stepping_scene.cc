// What a scene gives a time-stepping run: the integrator's parameters with
// the load factor as a function of time, the inertia of every rod from the
// density and section of its material group, and the initial displacement
// and velocity fields at the vertices.
#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>
#include <io/scene_file.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;

  Scene
  parse_scene(const std::string &text)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm, text, "scene", false);
    return Scene(prm);
  }

  /// Linear elastic material with a circular section of radius @p radius
  /// and density @p density, in the current material subsection.
  std::string
  elastic_circle(const std::string &radius, const std::string &density)
  {
    return "  set Density = " + density +
           "\n"
           "  subsection linear elastic\n"
           "    set Young's modulus = 1e6\n"
           "    set Cross section = circle\n"
           "    set Radius = " +
           radius +
           "\n"
           "  end\n";
  }

  TEST(TimeSteppingScene, ParametersAndLoadFactor)
  {
    const Scene scene =
      parse_scene("subsection Material\n" + elastic_circle("0.01", "1000") +
                  "end\n"
                  "subsection Solver\n"
                  "  set Method = time stepping\n"
                  "  set Max iterations = 7\n"
                  "  subsection Time stepping\n"
                  "    set Integrator = backward euler\n"
                  "    set Time step = 0.002\n"
                  "    set Start time = 0.5\n"
                  "    set End time = 1.5\n"
                  "    set Mass = lumped\n"
                  "    set Preload time = 2\n"
                  "    set Preload steps = 4\n"
                  "    set Load factor = if(t < 1, 2*t, sin(pi*t))\n"
                  "  end\n"
                  "end\n");
    const TimeIntegrator::Parameters &p = scene.time_stepping;
    EXPECT_EQ(scene.method, SolutionMethod::time_stepping);
    EXPECT_EQ(p.integrator, "backward euler");
    EXPECT_EQ(p.time_step, 0.002);
    EXPECT_EQ(p.start_time, 0.5);
    EXPECT_EQ(p.end_time, 1.5);
    EXPECT_EQ(p.mass, MassKind::lumped);
    EXPECT_EQ(p.preload_time, 2);
    EXPECT_EQ(p.preload_steps, 4u);
    EXPECT_EQ(p.newton.max_iterations, 7u);
    EXPECT_DOUBLE_EQ(p.load_factor(0.25), 0.5);
    EXPECT_NEAR(p.load_factor(1.5), -1, 1e-15);
  }

  TEST(TimeSteppingScene, InertiaFollowsTheMaterialGroups)
  {
    // A square cell: beams 0 and 1 horizontal (subsection Material), 2 and
    // 3 vertical (group "y-beams", material "thick").
    const std::string geometry = "subsection Geometry\n"
                                 "  set Generator = square lattice\n"
                                 "  set Cells = 1, 1\n"
                                 "  set Segments = 2\n"
                                 "end\n"
                                 "subsection Material\n" +
                                 elastic_circle("0.01", "1000") + "end\n";
    const Scene                   scene   = parse_scene(geometry +
                                    "subsection Group y-beams\n"
                                                        "  set Material = thick\n"
                                                        "end\n"
                                                        "subsection Material thick\n" +
                                    elastic_circle("0.02", "500") + "end\n");
    const std::vector<RodInertia> inertia = scene.inertia();
    ASSERT_EQ(inertia.size(), 4u);
    // rho pi r^2, rho (I1 + I2) = rho pi r^4 / 2 and the rotary rho I =
    // rho pi r^4 / 4.
    for (const unsigned int rod : {0u, 1u})
      {
        EXPECT_NEAR(inertia[rod].mass_per_length, 1000 * M_PI * 1e-4, 1e-12);
        EXPECT_NEAR(inertia[rod].rotational_inertia_per_length,
                    1000 * M_PI * 1e-8 / 2,
                    1e-16);
        EXPECT_NEAR(inertia[rod].rotary_inertia_per_length,
                    1000 * M_PI * 1e-8 / 4,
                    1e-16);
      }
    for (const unsigned int rod : {2u, 3u})
      {
        EXPECT_NEAR(inertia[rod].mass_per_length, 500 * M_PI * 4e-4, 1e-12);
        EXPECT_NEAR(inertia[rod].rotational_inertia_per_length,
                    500 * M_PI * 16e-8 / 2,
                    1e-16);
        EXPECT_NEAR(inertia[rod].rotary_inertia_per_length,
                    500 * M_PI * 16e-8 / 4,
                    1e-16);
      }

    // A group without its own material takes that of "Material", density
    // included.
    const Scene shared = parse_scene(geometry);
    for (const RodInertia &i : shared.inertia())
      EXPECT_NEAR(i.mass_per_length, 1000 * M_PI * 1e-4, 1e-12);
  }

  TEST(TimeSteppingScene, InertiaStatedPerMaterialGroup)
  {
    // Rods 0, 1: "Material", rigidities given directly, inertia stated;
    // rods 2, 3: "Material thick", its Density and section with the mass
    // per length stated as well (they agree: 500 pi 4e-4) and no rotary
    // inertia (0: Euler-Bernoulli), whereas "Material" takes the default,
    // half its stated twist inertia.
    const std::string direct =
      "  subsection linear elastic\n    set Stiffness input = direct\n"
      "    set EA = 1e4\n    set EI1 = 1\n    set EI2 = 1\n    set GJ = 1\n"
      "  end\n";
    const Scene scene =
      parse_scene("subsection Geometry\n  set Generator = square lattice\n"
                  "  set Cells = 1, 1\n  set Segments = 2\nend\n"
                  "subsection Material\n  set Mass per length = 3\n"
                  "  set Twist inertia per length = 0.25\n" +
                  direct +
                  "end\n"
                  "subsection Group y-beams\n  set Material = thick\nend\n"
                  "subsection Material thick\n"
                  "  set Mass per length = 0.62831853071795865\n"
                  "  set Rotary inertia per length = 0\n" +
                  elastic_circle("0.02", "500") + "end\n");
    const std::vector<RodInertia> inertia = scene.inertia();
    ASSERT_EQ(inertia.size(), 4u);
    for (const unsigned int rod : {0u, 1u})
      {
        EXPECT_EQ(inertia[rod].mass_per_length, 3);
        EXPECT_EQ(inertia[rod].rotational_inertia_per_length, 0.25);
        EXPECT_EQ(inertia[rod].rotary_inertia_per_length, 0.125);
      }
    for (const unsigned int rod : {2u, 3u})
      {
        EXPECT_NEAR(inertia[rod].mass_per_length, 500 * M_PI * 4e-4, 1e-6);
        EXPECT_NEAR(inertia[rod].rotational_inertia_per_length,
                    500 * M_PI * 16e-8 / 2,
                    1e-16);
        EXPECT_EQ(inertia[rod].rotary_inertia_per_length, 0);
      }

    // Loads/Mass per length is the same quantity, for the materials that
    // give none; the twist inertia has no such fallback.
    const Scene loads = parse_scene(
      "subsection Material\n  set Twist inertia per length = 0.5\n" + direct +
      "end\nsubsection Loads\n  set Mass per length = 7\nend\n");
    EXPECT_EQ(loads.inertia().at(0).mass_per_length, 7);
    EXPECT_EQ(loads.inertia().at(0).rotational_inertia_per_length, 0.5);
  }

  TEST(TimeSteppingScene, InitialFieldsAtTheVertices)
  {
    const Scene scene =
      parse_scene("subsection Geometry\n  set Segments = 4\nend\n"
                  "subsection Material\n" +
                  elastic_circle("0.01", "1000") +
                  "end\n"
                  "subsection Supports\n  set Clamped ends = start\nend\n"
                  "subsection Solver\n"
                  "  set Method = time stepping\n"
                  "  subsection Time stepping\n"
                  "    set Time step = 0.01\n"
                  "    set Initial displacement = 0; 0; 0.1*x^2\n"
                  "    set Initial velocity = 0; 2 + y; 0\n"
                  "  end\n"
                  "end\n");
    const auto model = scene.build_model();
    VectorType u, v;
    scene.initial_state(*model, u, v);
    const RodNetwork &net = model->network();
    for (unsigned int vertex = 0; vertex < net.n_vertices(); ++vertex)
      {
        const double x = net.vertex(vertex)[0];
        const auto   z = model->layout().vertex_dof(vertex, 2);
        const auto   y = model->layout().vertex_dof(vertex, 1);
        EXPECT_DOUBLE_EQ(u[z], 0.1 * x * x) << "vertex " << vertex;
        // The clamp (first two vertices) holds still.
        EXPECT_EQ(v[y], model->constraints().is_constrained(y) ? 0 : 2)
          << "vertex " << vertex;
      }
    EXPECT_DOUBLE_EQ(v.l2_norm(), 2 * std::sqrt(net.n_vertices() - 2.0));
  }
} // namespace
