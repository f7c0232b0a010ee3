// Probe kinds are registered by keyword: the distance probe of the library
// on both models (one class reads either state), a kind that this test
// program registers itself (a user's extension, with one registration
// line), and the refusals of malformed probes. References: distances of
// prescribed vertex displacements, by Pythagoras.

#include <core/dr_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <io/probes.h>
#include <materials/linear_elastic_rod.h>

#include <cmath>
#include <gtest/gtest.h>
#include <memory>

namespace rodnet
{
  namespace
  {
    /// "height <vertex>": the vertex's height above its undeformed one,
    /// a probe kind of this program.
    class HeightProbe : public Probe
    {
    public:
      HeightProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
          , vertex(std::stoi(words.first))
          , undeformed(model.network().vertex(vertex)[2])
      {
        require_probe_arguments(words, 1, "height <vertex>");
      }

      std::string
      unit() const override
      {
        return "m";
      }

      double
      value(const ProbedState &state) const override
      {
        return state.position(vertex)[2] - undeformed;
      }

    private:
      unsigned int vertex;
      double       undeformed;
    };
  } // namespace

  RODNET_REGISTER_PROBE_KIND(HeightProbe,
                             "height",
                             "height <vertex> [m]: above the undeformed one")
} // namespace rodnet

namespace
{
  using namespace rodnet;

  constexpr unsigned int n_probed_segments = 8;
  const RodStiffness     probed_stiffness{1e4, 1, 1, 1};

  std::unique_ptr<RodNetwork>
  probed_rod_network()
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          n_probed_segments),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    return network;
  }

  /// The end vertex moved by (0.125, 0.3, 0.4), the vertex 4 up by 0.25,
  /// in the state @p u of a model whose position DoF of vertex v and
  /// component c is @p dof(v, c).
  template <class State, class Dof>
  void
  displace(State &u, const Dof &dof)
  {
    const Vector3 end_move(0.125, 0.3, 0.4);
    for (unsigned int c = 0; c < 3; ++c)
      u[dof(n_probed_segments, c)] = end_move[c];
    u[dof(4, 2)] = 0.25;
  }

  const std::string probes_text =
    "span: distance start end; mid: height 4; tip: position end z";

  void
  expect_probe_values(const std::vector<double> &values)
  {
    ASSERT_EQ(values.size(), 3u);
    EXPECT_NEAR(values[0], std::sqrt(1.125 * 1.125 + 0.09 + 0.16), 1e-14);
    EXPECT_NEAR(values[1], 0.25, 1e-14);
    EXPECT_NEAR(values[2], 0.4, 1e-14);
  }

  TEST(ProbeKinds, OneProbeClassReadsEitherModel)
  {
    RodModel rods(probed_rod_network(),
                  {std::make_shared<LinearElasticRod>(probed_stiffness)});
    rods.finalize();
    VectorType u = rods.create_vector();
    displace(u, [&](unsigned int v, unsigned int c) {
      return rods.layout().vertex_dof(v, c);
    });
    u.compress(dealii::VectorOperation::insert);
    const ProbeList probes = parse_probes(probes_text, rods, "test");
    EXPECT_EQ(probes[0]->unit(), "m");
    expect_probe_values(evaluate_probes(probes, rods, u, 1.0));

    DrModel beams(probed_rod_network(), {probed_stiffness});
    beams.finalize();
    DrVector w = beams.create_vector();
    displace(w, [&](unsigned int v, unsigned int c) {
      return beams.position_dof(v, c);
    });
    expect_probe_values(
      evaluate_probes(parse_probes(probes_text, beams, "test"), beams, w, 1.0));
  }

  TEST(ProbeKinds, TheDescriptionListsEveryRegisteredKind)
  {
    const std::string text = probe_kinds_description();
    for (const char *kind : {"distance <vertex> <vertex> [m]",
                             "height <vertex> [m]",
                             "position <vertex> <x|y|z> [m]",
                             "moment <junction> <x|y|z> [N m]"})
      EXPECT_NE(text.find(kind), std::string::npos) << kind;
  }

  TEST(ProbeKinds, MalformedProbesAreRefusedNamingThem)
  {
    RodModel rods(probed_rod_network(),
                  {std::make_shared<LinearElasticRod>(probed_stiffness)});
    rods.finalize();
    const auto message = [&](const std::string &text) {
      try
        {
          parse_probes(text, rods, "Output/Probes");
        }
      catch (const std::invalid_argument &e)
        {
          return std::string(e.what());
        }
      return std::string("accepted");
    };
    EXPECT_EQ(message("d: distance start"),
              "entry \"Output/Probes\", probe \"d: distance start\": "
              "expected \"distance <vertex> <vertex>\"");
    EXPECT_EQ(message("e: energy 3"),
              "entry \"Output/Probes\", probe \"e: energy 3\": expected "
              "\"energy\"");
    EXPECT_NE(message("d: distance start nowhere").find("nowhere"),
              std::string::npos);
    EXPECT_NE(message("a: angle end")
                .find("unknown probe kind \"angle\"; "
                      "known: angular momentum <x|y|z> [N m s], distance "
                      "<vertex> <vertex> [m], eigenvalue"),
              std::string::npos);
    // Kinds of two words (io/motion_probes.cc).
    EXPECT_EQ(message("k: kinetic energy 3"),
              "entry \"Output/Probes\", probe \"k: kinetic energy 3\": "
              "expected \"kinetic energy\"");
    EXPECT_EQ(message("p: linear momentum"),
              "entry \"Output/Probes\", probe \"p: linear momentum\": "
              "expected \"linear momentum <x|y|z>\"");
    EXPECT_EQ(message("L: angular momentum x y"),
              "entry \"Output/Probes\", probe \"L: angular momentum x y\": "
              "expected \"angular momentum <x|y|z>\"");
  }
} // namespace
