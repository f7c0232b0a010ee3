// "Supports/Pinned vertices = junctions" pins every junction of a network,
// whatever made it: each network generator, a network file and a Gmsh
// network. Every junction that ties rod ends has its position held and,
// where it carries a rotation, that rotation free (only the quaternion's
// gauge fixed); no other vertex is held by it; the rotation handles that a
// moment adds inside a rod are not junctions of the network and stay free.
// Without junctions (a single rod) the entry is refused naming it.
#include <deal.II/base/parameter_handler.h>

#include <common/scene_text.h>
#include <io/scene.h>

#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  /// The model of @p geometry (subsection Geometry's entries) with every
  /// junction pinned and the moment entry @p moments.
  std::unique_ptr<RodModel>
  pinned_network(const std::string &geometry, const std::string &moments = "")
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Geometry\n" + geometry + "end\n" +
      rodnet::testing::direct_material() +
      "subsection Supports\n  set Pinned vertices = junctions\nend\n"
      "subsection Loads\n  set Moments = " +
      moments + "\nend\n");
    return Scene(prm, RODNET_SOURCE_DIR "/tests/input/data").build_model();
  }

  /// Checks that the position of every junction of @p model that ties rod
  /// ends is held by a support "Pinned vertices: @<name>", its rotation
  /// free, and that these supports hold nothing else; returns how many
  /// junctions were pinned.
  unsigned int
  expect_junctions_pinned(const RodModel &model, const std::string &what)
  {
    const RodNetwork      &network     = model.network();
    const auto            &constraints = model.constraints();
    std::set<unsigned int> pinned;
    for (const Support &s : model.supports())
      if (s.name.rfind("Pinned vertices: @", 0) == 0)
        pinned.insert(s.vertices.begin(), s.vertices.end());
    unsigned int n = 0;
    for (unsigned int j = 0; j < network.junctions().size(); ++j)
      {
        const Junction &junction  = network.junctions()[j];
        const bool      ties_ends = !junction.ends.empty();
        EXPECT_EQ(pinned.count(junction.vertex), ties_ends ? 1u : 0u)
          << what << ", junction " << junction.name;
        if (!ties_ends)
          continue;
        ++n;
        EXPECT_NE(model.supports().end(),
                  std::find_if(model.supports().begin(),
                               model.supports().end(),
                               [&](const Support &s) {
                                 return s.name ==
                                        "Pinned vertices: @" + junction.name;
                               }))
          << what << ", junction " << junction.name;
        for (unsigned int c = 0; c < 3; ++c)
          EXPECT_TRUE(constraints.is_constrained(
            model.layout().vertex_dof(junction.vertex, c)))
            << what << ", junction " << junction.name;
        if (junction.kind == JunctionKind::welded)
          {
            for (unsigned int c = 1; c < 4; ++c)
              EXPECT_FALSE(
                constraints.is_constrained(model.layout().rotation_dof(j, c)))
                << what << ", junction " << junction.name << " rotation " << c;
          }
      }
    EXPECT_EQ(pinned.size(), n) << what;
    return n;
  }

  TEST(PinnedJunctions, EveryNetworkSource)
  {
    struct Source
    {
      std::string name, geometry;
      /// Junctions that tie rod ends.
      unsigned int junctions;
    };
    const std::vector<Source> sources = {
      // clamp (clamped, one beam end) and corner; the tip is a free end.
      {"frame", "  set Generator = frame\n  set Segments = 4\n", 2},
      // hub and top (clamped, one beam end); the blade tips are free ends.
      {"windmill", "  set Generator = windmill\n  set Segments = 4\n", 2},
      {"square lattice",
       "  set Generator = square lattice\n  set Cells = 3, 2\n"
       "  set Segments = 2\n",
       12},
      {"hexagonal lattice",
       "  set Generator = hexagonal lattice\n  set Cells = 2, 1\n"
       "  set Segments = 2\n",
       10},
      {"network file",
       "  set Generator = network file\n  set Network file = frame.net\n"
       "  set Segments = 4\n",
       2},
      {"gmsh network",
       "  set Generator = gmsh network\n"
       "  set Mesh file = square_lattice_2x2.msh\n",
       9}};
    for (const Source &source : sources)
      EXPECT_EQ(expect_junctions_pinned(*pinned_network(source.geometry),
                                        source.name),
                source.junctions)
        << source.name;
  }

  TEST(PinnedJunctions, RotationHandlesStayFree)
  {
    // A moment inside a lattice beam adds a rotation handle there: not a
    // junction of the network, its position stays free.
    const std::unique_ptr<RodModel> model =
      pinned_network("  set Generator = square lattice\n  set Cells = 1, 1\n"
                     "  set Segments = 4\n",
                     "0:mid: 0,0,1 0.1");
    EXPECT_EQ(expect_junctions_pinned(*model, "handle"), 4u);
    const RodNetwork  &network = model->network();
    const unsigned int mid     = network.rods()[0].vertices[2];
    for (unsigned int c = 0; c < 3; ++c)
      EXPECT_FALSE(model->constraints().is_constrained(
        model->layout().vertex_dof(mid, c)));
  }
} // namespace
