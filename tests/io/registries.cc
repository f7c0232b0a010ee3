// The registries of generators, time integrators and solution methods: an
// unknown name is refused with the known ones listed, the scene's
// selections list exactly the registered names in the order of
// registration (a registry's names are sorted otherwise), and a generator
// registered from outside is declared and run through the registry alone.
#include <deal.II/base/parameter_handler.h>

#include <io/entry_tree.h>
#include <io/generator_registry.h>
#include <io/scene.h>
#include <io/solution_methods.h>

#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  /// The message of what @p f throws, "" if it does not.
  template <class F>
  std::string
  message_of(const F &f)
  {
    try
      {
        f();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }

  /// A rod of one segment from the origin to "Tip": a generator in the
  /// smallest form a user writes one.
  class TipGenerator : public GeometryGenerator
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm) const override
    {
      prm.declare_entry("Tip", "0, 0, 2", dealii::Patterns::Anything());
    }

    GeneratedGeometry
    generate(const dealii::ParameterHandler &prm,
             const GeneratorInput &) const override
    {
      GeneratedGeometry geometry;
      geometry.rod_points.push_back(
        {Vector3::Zero(),
         prm.get("Tip") == "0, 0, 2" ? Vector3(0, 0, 2) : Vector3(0, 0, 1)});
      geometry.rod_closed.push_back(false);
      return geometry;
    }
  };

  TEST(Registries, UnknownGeneratorListsTheKnownOnes)
  {
    const std::string message =
      message_of([] { GeneratorRegistry::instance().create("spiral"); });
    EXPECT_NE(message.find("unknown generator \"spiral\"; known generators: "
                           "\"straight\", \"arc\", \"ring\", \"helix\", "
                           "\"polyline\", \"gmsh\", \"frame\", "
                           "\"windmill\", \"square lattice\", \"hexagonal "
                           "lattice\", \"network file\", \"gmsh network\""),
              std::string::npos)
      << message;
  }

  TEST(Registries, UnknownSolutionMethodListsTheKnownOnes)
  {
    const std::string message =
      message_of([] { solution_method("explicit dynamics"); });
    EXPECT_NE(message.find("unknown solution method \"explicit dynamics\"; "
                           "known methods: newton, dynamic relaxation, time "
                           "stepping"),
              std::string::npos)
      << message;
  }

  TEST(Registries, SelectionsListTheRegisteredNames)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    const EntryNode tree = entry_tree(prm);
    EXPECT_EQ(tree.find("Geometry")->find("Generator")->pattern,
              "[Selection straight|arc|ring|helix|polyline|gmsh|frame|"
              "windmill|square lattice|hexagonal lattice|network file|gmsh "
              "network|block map ]");
    EXPECT_EQ(tree.find("Solver")->find("Method")->pattern,
              "[Selection newton|dynamic relaxation|time stepping|"
              "continuation ]");
    EXPECT_EQ(
      tree.find("Solver")->find("Time stepping")->find("Integrator")->pattern,
      "[Selection quasi-static|backward euler|newmark|midpoint|generalized "
      "alpha ]");
  }

  TEST(Registries, OrderIsSortedOrThatOfRegistration)
  {
    Registry<GeometryGenerator> sorted("generator", "generators");
    GeneratorRegistry           ordered;
    for (const std::string name : {"tip", "base", "middle"})
      {
        sorted.add<TipGenerator>(name, "a rod to a tip");
        ordered.add<TipGenerator>(name, "a rod to a tip");
      }
    EXPECT_EQ(sorted.names(),
              (std::vector<std::string>{"base", "middle", "tip"}));
    EXPECT_EQ(ordered.names(),
              (std::vector<std::string>{"tip", "base", "middle"}));
    EXPECT_NE(message_of([&] {
                ordered.create("top");
              }).find("known generators: \"tip\", \"base\", \"middle\""),
              std::string::npos);
  }

  TEST(Registries, AGeneratorIsOneClassAndOneRegistration)
  {
    GeneratorRegistry registry;
    registry.add<TipGenerator>("tip", "a rod to a tip");
    EXPECT_EQ(registry.description("tip"), "a rod to a tip");
    EXPECT_THROW(registry.add<TipGenerator>("tip", "again"), std::logic_error);

    dealii::ParameterHandler prm;
    registry.create("tip")->declare_parameters(prm);
    prm.parse_input_from_string("set Tip = 0, 0, 2\n");
    const auto generator = registry.create("tip");
    EXPECT_FALSE(generator->open_rods());
    EXPECT_FALSE(generator->planned_size(prm, {}).has_value());
    EXPECT_EQ(generator->size_entry(), "Geometry/Segments");
    const GeneratedGeometry g = generator->generate(prm, {});
    ASSERT_EQ(g.rod_points.size(), 1u);
    EXPECT_DOUBLE_EQ((g.rod_points[0][1] - g.rod_points[0][0]).norm(), 2.);
    EXPECT_NE(message_of([&] {
                registry.create("straight");
              }).find("known generators: \"tip\""),
              std::string::npos);
  }
} // namespace
