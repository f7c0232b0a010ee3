// An entry of subsection Geometry that the chosen generator does not read
// is refused where the scene sets it, naming the entry, the generator and
// why: "Director d1" for every network generator (a network orients its
// beams itself; a square lattice gave the same output with d1 = (0, 1, 1)
// and (0, 0, 1)), "Segments" for the rods of a Gmsh mesh, the entries of
// other generators. Left at its default, or written otherwise with the
// same value, it is not refused.
#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  const std::string unread_data = RODNET_SOURCE_DIR "/tests/input/data/";

  /// Constructs the scene of the Geometry entries @p geometry with a
  /// material; returns the message it was refused with, "" if it was not.
  std::string
  geometry_refusal(const std::string &geometry)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n" + geometry +
                                "end\n"
                                "subsection Material\n"
                                "  subsection linear elastic\n"
                                "    set Stiffness input = direct\n"
                                "    set EA = 1e4\n    set EI1 = 1\n"
                                "    set EI2 = 1\n    set GJ = 1\n"
                                "  end\n"
                                "end\n");
    try
      {
        const Scene scene(prm);
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }

  /// Geometry entries of every network generator, with the files those
  /// that read one need.
  const std::vector<std::pair<std::string, std::string>> network_geometries = {
    {"frame", ""},
    {"windmill", ""},
    {"square lattice", ""},
    {"hexagonal lattice", ""},
    {"network file", "  set Network file = " + unread_data + "frame.net\n"},
    {"gmsh network", "  set Mesh file = " + unread_data + "frame_v41.msh\n"},
    {"block map",
     "  set Block map file = " RODNET_SOURCE_DIR "/scenes/fig6_block.map\n"}};

  TEST(UnreadGeometryEntries, NetworkGeneratorsRefuseADirector)
  {
    for (const auto &[generator, files] : network_geometries)
      {
        const std::string geometry =
          "  set Generator = " + generator + "\n" + files;
        EXPECT_EQ(geometry_refusal(geometry), "") << generator;
        // Its default, written otherwise, is no setting.
        EXPECT_EQ(geometry_refusal(geometry + "  set Director d1 = 0,1,0.0\n"),
                  "")
          << generator;
        const std::string message =
          geometry_refusal(geometry + "  set Director d1 = 0, 1, 1\n");
        EXPECT_NE(message.find("entry \"Geometry/Director d1\": the " +
                               generator +
                               " generator does not read it: a network "
                               "orients each beam itself"),
                  std::string::npos)
          << generator << ": " << message;
        EXPECT_NE(message.find("remove it"), std::string::npos) << message;
      }
  }

  TEST(UnreadGeometryEntries, RodGeneratorsReadTheDirector)
  {
    EXPECT_EQ(geometry_refusal("  set Generator = straight\n"
                               "  set Director d1 = 0, 1, 1\n"),
              "");
    EXPECT_EQ(geometry_refusal("  set Generator = gmsh\n"
                               "  set Mesh file = " +
                               unread_data +
                               "straight_rod.msh\n"
                               "  set Director d1 = 0, 1, 1\n"),
              "");
  }

  TEST(UnreadGeometryEntries, EntriesOfOtherGeneratorsAreRefused)
  {
    EXPECT_NE(geometry_refusal("  set Generator = frame\n"
                               "  set Cells = 3, 3\n")
                .find("entry \"Geometry/Cells\": the frame generator does "
                      "not read it, only the square lattice and hexagonal "
                      "lattice generators do; remove it"),
              std::string::npos);
    EXPECT_NE(geometry_refusal("  set Generator = network file\n"
                               "  set Network file = " +
                               unread_data +
                               "frame.net\n"
                               "  set Beam length = 2\n")
                .find("entry \"Geometry/Beam length\": the network file "
                      "generator does not read it, only the frame, "
                      "windmill, square lattice and hexagonal lattice "
                      "generators do"),
              std::string::npos);
    EXPECT_NE(geometry_refusal("  set Generator = straight\n"
                               "  set Radius = 2\n")
                .find("entry \"Geometry/Radius\": the straight generator "
                      "does not read it, only the arc, ring and helix "
                      "generators do"),
              std::string::npos);
    // The lattices read "Cells" and "Beam length".
    EXPECT_EQ(geometry_refusal("  set Generator = square lattice\n"
                               "  set Cells = 3, 3\n"
                               "  set Beam length = 2\n"),
              "");
  }

  TEST(UnreadGeometryEntries, GmshRodsRefuseASegmentCount)
  {
    const std::string mesh = "  set Generator = gmsh\n"
                             "  set Mesh file = " +
                             unread_data + "straight_rod.msh\n";
    EXPECT_EQ(geometry_refusal(mesh), "");
    EXPECT_NE(geometry_refusal(mesh + "  set Segments = 40\n")
                .find("entry \"Geometry/Segments\": the gmsh generator does "
                      "not read it: the mesh's line elements are the "
                      "segments; remove it"),
              std::string::npos);
  }
} // namespace
