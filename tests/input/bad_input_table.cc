// The "bad input" table of doc/validation.md: each row is an input given
// to rodnet-run, the exit code it must end with and a fragment of the one
// line that says what is wrong, where, and what to do. None may reach the
// solver, print deal.II's assertion text or a stack trace.
#include <common/run_driver.h>
#include <common/scene_text.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using rodnet::testing::run_driver_with;

  /// One row of the table.
  struct BadInput
  {
    std::string name;
    /// Contents of the scene file name + extension; none if empty.
    std::string scene;
    std::string extension;
    /// Arguments after the scene file (or instead of it if there is none).
    std::string arguments;
    int         exit_code;
    std::string fragment;
  };

  std::ostream &
  operator<<(std::ostream &out, const BadInput &b)
  {
    return out << b.name;
  }

  /// A cantilever that runs as it is: every case breaks one thing of it.
  const std::string valid_cantilever =
    rodnet::testing::direct_material() +
    "subsection Geometry\n  set Segments = 10\nend\n"
    "subsection Supports\n  set Clamped ends = start\nend\n"
    "subsection Output\n  set Write VTU = false\n"
    "  set Plot = false\nend\n";

  std::string
  section(const std::string &name, const std::string &entries)
  {
    return "subsection " + name + "\n" + entries + "end\n";
  }

  /// cantilever with the lines @p entries in subsection @p name (given
  /// last, they override).
  std::string
  with(const std::string &name, const std::string &entries)
  {
    return valid_cantilever + section(name, entries);
  }

  const std::string valid_time_stepping =
    section("Solver",
            "  set Method = time stepping\n"
            "  subsection Time stepping\n"
            "    set Integrator = quasi-static\n"
            "    set Time step = 0.1\n"
            "  end\n");

  const std::string midpoint_integrator =
    section("Solver",
            "  subsection Time stepping\n"
            "    set Integrator = midpoint\n"
            "  end\n");

  const std::string data_folder = RODNET_SOURCE_DIR "/tests/input/data/";

  /// The cantilever's geometry replaced by the rods of the Gmsh mesh
  /// @p mesh of data_folder (Segments back at its default: the mesh's
  /// elements are the segments).
  std::string
  gmsh_rods(const std::string &mesh)
  {
    return valid_cantilever + section("Geometry",
                                      "  set Generator = gmsh\n"
                                      "  set Segments = 100\n"
                                      "  set Mesh file = " +
                                        data_folder + mesh + "\n");
  }

  /// The cantilever's geometry replaced by the block map @p map of
  /// data_folder, blocks of @p size (the map is refused before the supports
  /// are read).
  std::string
  block_map(const std::string &map, const std::string &size)
  {
    return valid_cantilever + section("Geometry",
                                      "  set Generator = block map\n"
                                      "  set Block size = " +
                                        size +
                                        "\n"
                                        "  set Block map file = " +
                                        data_folder + map + "\n");
  }

  const std::vector<BadInput> bad_inputs = {
    // Non-finite and absurd numbers, in every kind of entry.
    {"nan_force",
     with("Loads", "  set Point forces = end: nan, 0, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Point forces\": in \"end: nan, 0, 0\", \"nan\" is not a "
     "finite number"},
    {"huge_force",
     with("Loads", "  set Point forces = end: 1e308, 0, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Point forces\": in \"end: 1e308, 0, 0\", 1e308 exceeds "
     "1e100"},
    // A developable ribbon built curved and stress free.
    {"curved_wunderlich_ribbon",
     valid_cantilever +
       section(
         "Geometry",
         "  set Generator = arc\n  set Natural shape = initial geometry\n") +
       section("Material",
               "  set Model = wunderlich ribbon\n"
               "  subsection wunderlich ribbon\n"
               "    set Young's modulus = 1e9\n    set Width = 0.01\n"
               "    set Thickness = 0.001\n  end\n"),
     ".prm",
     "",
     1,
     "a developable ribbon is straight and flat when unstressed"},
    {"huge_stiffness",
     with("Material",
          "  subsection linear elastic\n    set EA = 1e308\n  end\n"),
     ".prm",
     "",
     1,
     "entry \"Material/linear elastic/EA\": in \"1e308\", 1e308 exceeds 1e100"},
    {"overflowing_section",
     valid_cantilever + section("Material",
                                "  subsection linear elastic\n"
                                "    set Stiffness input = section\n"
                                "    set Young's modulus = 1\n"
                                "    set Radius = 1e90\n"
                                "  end\n"),
     ".prm",
     "",
     1,
     "subsection \"Material\": circle cross section: the area = "
     "3.14159e+180 from \"Radius\" is beyond 1e100"},
    {"overflowing_moment",
     with("Loads", "  set Moments = end: 0,0,1 1e400\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Moments\": in \"end: 0,0,1 1e400\", 1e400 is beyond the "
     "range of a double"},
    {"infinite_displacement",
     with("Supports", "  set Prescribed displacements = end: x=-inf\n"),
     ".prm",
     "",
     1,
     "entry \"Supports/Prescribed displacements\": in \"end: x=-inf\", "
     "\"inf\" is not a finite number"},
    {"nan_vector",
     with("Loads", "  set Gravity = 0, NaN, 0\n"),
     ".prm",
     "",
     1,
     "Gravity"},
    {"huge_point",
     valid_cantilever + section("Geometry",
                                "  set Generator = polyline\n"
                                "  set Points = 0,0,0; 1e200,0,0\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Points\": in \"0,0,0; 1e200,0,0\", 1e200 exceeds "
     "1e100"},
    {"huge_expression",
     with("Loads", "  set Point forces = end: 0, 1, 0\n") +
       valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Load factor = 1e300*t\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Solver/Time stepping/Load factor\": in \"1e300*t\", 1e300 "
     "exceeds 1e100"},
    // Runs that cannot end in reasonable time or fit in memory.
    {"billion_load_steps",
     with("Loads", "  set Steps = 1000000000\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Steps\": 1000000000 load steps are more than the 100000"},
    {"billion_time_steps",
     valid_cantilever + valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Time step = 1e-9\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Solver/Time stepping/Time step\": 1e-09 s from 0 to 1 s are "
     "1e+09 time steps, more than the 1e+06"},
    {"negative_rayleigh_damping",
     valid_cantilever + valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Integrator = newmark\n"
               "    set Rayleigh damping = 0.1, -0.01\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Solver/Time stepping/Rayleigh damping\": alpha = 0.1 and "
     "beta = -0.01 must not be negative"},
    {"negative_viscous_drag",
     valid_cantilever + valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Integrator = newmark\n"
               "    set Viscous drag per length = -2\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Solver/Time stepping/Viscous drag per length\": -2 N s/m^2 "
     "must not be negative"},
    {"spectral_radius_above_one",
     valid_cantilever + valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Integrator = generalized alpha\n"
               "    set Spectral radius at infinity = 1.2\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Solver/Time stepping/Spectral radius at infinity\": 1.2 lies "
     "outside [0, 1]"},
    {"damping_in_quasi_static_run",
     valid_cantilever + valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Rayleigh damping = 0.1, 0\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Solver/Time stepping/Integrator\": damping acts on "
     "velocities, which a quasi-static run does not have"},
    {"too_many_vtu_files",
     with("Loads", "  set Steps = 50000\n") +
       section("Output", "  set Write VTU = true\n"),
     ".prm",
     "",
     1,
     "entry \"Output/VTU interval\": the run would write 50001 VTU files, "
     "more than the 10000 a run may write; set the interval to 6 or more"},
    {"unknown_picture_field",
     with("Output", "  set Picture field = curvatur\n"),
     ".prm",
     "",
     1,
     "entry \"Output/Picture field\": no field \"curvatur\" to colour the "
     "picture by (nearest: \"curvature\""},
    {"picture_elevation_out_of_range",
     with("Output", "  set Picture view = -60, 95\n"),
     ".prm",
     "",
     1,
     "entry \"Output/Picture view\": in \"-60, 95\", the elevation \"95\" "
     "is not an angle in degrees from -90 to 90"},
    {"picture_range_decreasing",
     with("Output", "  set Picture range = 1, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Output/Picture range\": \"1, 0\" should read \"auto\" or "
     "\"<low>, <high>\", two finite numbers with low < high"},
    {"picture_group_unknown",
     with("Output",
          "  set Picture field = group\n  set Picture groups = layer1\n"),
     ".prm",
     "",
     1,
     "entry \"Output/Picture groups\": no rod is in group \"layer1\"; the "
     "groups of this geometry are \"all\""},
    {"billion_segments",
     with("Geometry", "  set Segments = 1000000000\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Segments\": the model would have 1000000000 segments "
     "and 4000000003 DoFs and need about"},
    {"huge_lattice",
     valid_cantilever + section("Geometry",
                                "  set Generator = square lattice\n"
                                "  set Cells = 3000, 3000\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Cells\": the model would have 180060000 segments"},
    // Errors that used to say too little.
    {"empty_scene", "", ".prm", "", 1, "the scene sets no entry"},
    {"comments_only", "# nothing here\n\n", ".prm", "", 1, "sets no entry"},
    {"no_material",
     section("Supports", "  set Clamped ends = start\n"),
     ".prm",
     "",
     1,
     "subsection \"Material/linear elastic\" sets no entry, so the rods have "
     "no stiffness"},
    {"json_value_for_subsection",
     "{\"Geometry\": 5}",
     ".json",
     "",
     1,
     "\"Geometry\" is a subsection: give an object of its entries"},
    {"json_array_for_entry",
     "{\"Geometry\": {\"Segments\": [1, 2]}}",
     ".json",
     "",
     1,
     "entry \"Geometry/Segments\" takes one string or number (e.g. \"100\"), "
     "not a JSON array"},
    {"json_array_scene",
     "[1, 2]",
     ".json",
     "",
     1,
     "the scene is a JSON array or value"},
    {"json_unknown_entry",
     "{\"Geometry\": {\"Segmnts\": \"5\"}}",
     ".json",
     "",
     1,
     "\"Geometry/Segmnts\" is no subsection or entry of a scene"},
    {"json_syntax", "{\"Geometry\": {", ".json", "", 1, "not valid JSON"},
    // Found by fuzz/scene: a value that is not UTF-8 (a Latin-1 byte).
    {"value_not_utf8",
     valid_cantilever +
       section("Output", "  set Probes = tip\xff: position end x\n"),
     ".prm",
     "",
     1,
     "the value of entry \"Probes\" is not UTF-8 text"},
    // A portal frame (several tags per entity) read as one kinked rod,
    // whose columns run along the default director.
    {"gmsh_frame_director_along_a_column",
     gmsh_rods("frame_v41.msh"),
     ".prm",
     "",
     1,
     "rod 0, segment 2: the director d1 hint is parallel to the segment; "
     "choose another \"Director d1\""},
    {"lattice_as_gmsh_rods",
     gmsh_rods("square_lattice_2x2.msh"),
     ".prm",
     "",
     1,
     "use \"Generator = gmsh network\""},
    // Coincident nodes: a Gmsh mesh's nodes a little too far apart to be
    // merged, a line element between two coincident nodes, two nodes of a
    // .net file at one point.
    {"gmsh_nodes_slightly_apart",
     valid_cantilever + section("Geometry",
                                "  set Generator = gmsh network\n"
                                "  set Mesh file = " +
                                  data_folder + "nodes_1e-5_apart.msh\n"),
     ".prm",
     "",
     1,
     "nodes_1e-5_apart.msh\": nodes 2 and 3 are 1e-05 m apart: too far to be "
     "merged (within 2e-08 m) and too close to be distinct"},
    {"gmsh_element_between_coincident_nodes",
     valid_cantilever + section("Geometry",
                                "  set Generator = gmsh network\n"
                                "  set Mesh file = " +
                                  data_folder + "zero_length_element.msh\n"),
     ".prm",
     "",
     1,
     "zero_length_element.msh\": element 2 joins nodes 2 and 3, which "
     "coincide (0 apart, within 2e-08 m): a line element of zero length; "
     "remove it"},
    {"network_file_coincident_nodes",
     valid_cantilever + section("Geometry",
                                "  set Generator = network file\n"
                                "  set Network file = " +
                                  data_folder + "coincident_nodes.net\n"),
     ".prm",
     "",
     1,
     "nodes \"b\" and \"c\" coincide at (1, 0, 0) (1e-10 apart, within "
     "1.41e-08 m): a joint is one node; let the beams that meet there name "
     "the same node"},
    // Block maps (doc/networks.md, "Block maps").
    {"block_map_unknown_character",
     block_map("block_map_unknown.map", "1, 1"),
     ".prm",
     "",
     1,
     "block_map_unknown.map:3:2: unknown block 'x'; a block map knows '+' "
     "(shrink-up), '-' (shrink-down), '.' (passive) and ' ' (no block)"},
    {"block_map_without_block",
     block_map("block_map_empty.map", "1, 1"),
     ".prm",
     "",
     1,
     "block_map_empty.map\" has no block; a map needs at least one '+', '-' "
     "or '.'"},
    {"block_map_in_pieces",
     block_map("block_map_pieces.map", "1, 1"),
     ".prm",
     "",
     1,
     "block_map_pieces.map:3:1: this block is not joined to the block at line "
     "1, column 1 (blocks join where they share a corner); a network in "
     "pieces moves rigidly under one support"},
    {"block_map_zero_size",
     block_map("block_map_pieces.map", "1, 0"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Block size\": a block's width and height must be "
     "positive, got \"1, 0\""},
    {"output_without_directory",
     valid_cantilever,
     ".prm",
     "--output",
     1,
     "rodnet-run: --output needs a directory, e.g. --output my_run"},
    {"output_is_a_file",
     valid_cantilever,
     ".prm",
     "--output " + data_folder + "frame.net",
     1,
     "cannot create the output directory"},
    {"scene_is_a_directory",
     "",
     "",
     data_folder,
     1,
     "this is a directory, not a scene file"},
    {"missing_scene", "", "", "no_such_scene.prm", 1, "does not exist"},
    {"unknown_option", "", "", "--frobnicate", 1, "unexpected argument"},
    {"zero_director",
     with("Geometry", "  set Director d1 = 0, 0, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Director d1\": \"0, 0, 0\" has no direction"},
    {"parallel_arc_axes",
     with("Geometry",
          "  set Generator = arc\n"
          "  set Plane axis 1 = 1, 0, 0\n"
          "  set Plane axis 2 = 2, 0, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Plane axis 2\": \"2, 0, 0\" makes 0 deg with \"Plane "
     "axis 1\" = \"1, 0, 0\"; the axes of the circle's plane must be "
     "orthogonal"},
    {"zero_ring_axis",
     with("Geometry",
          "  set Generator = ring\n"
          "  set Plane axis 1 = 0, 0, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Plane axis 1\": \"0, 0, 0\" has no direction"},
    {"fractional_ring_turns",
     with("Geometry",
          "  set Generator = ring\n"
          "  set Turns = 2.5\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Turns\": a ring is wound a whole number of times, at "
     "least once, not 2.5"},
    // Gravity weighs rho A of the material, or Mass per length: without
    // either it would weigh nothing.
    {"gravity_without_mass",
     with("Loads", "  set Gravity = 0, 0, -9.81\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Gravity\": the rods of \"Material\" have no mass to "
     "weigh; give \"Material/Density\" (with a cross-section) or "
     "\"Loads/Mass per length\""},
    {"gravity_density_without_section",
     with("Loads", "  set Gravity = 0, 0, -9.81\n") +
       section("Material", "  set Density = 7850\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Gravity\": the weight of the rods of \"Material\" is "
     "\"Material/Density\" times the section's area, but \"Material/linear "
     "elastic\" gives its rigidities directly, without a section; give "
     "\"Loads/Mass per length\" or \"Stiffness input = section\""},
    {"mass_per_length_contradicts_density",
     with("Loads", "  set Gravity = 0, 0, -9.81\n  set Mass per length = 1\n") +
       section("Material",
               "  set Density = 7850\n"
               "  subsection linear elastic\n"
               "    set Stiffness input = section\n"
               "    set Young's modulus = 2.1e11\n"
               "    set Cross section = circle\n"
               "    set Radius = 0.01\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Mass per length\": 1 kg/m differs from the 2.46615 kg/m "
     "of \"Material/Density\" times the section's area"},
    // Time stepping with rigidities given directly: the inertia is stated.
    {"dynamics_without_mass_per_length",
     valid_cantilever + valid_time_stepping + midpoint_integrator,
     ".prm",
     "",
     1,
     "entry \"Material/Mass per length\": time stepping with the midpoint "
     "integrator needs the mass per length rho A of the rods of "
     "\"Material\": give it, or \"Material/Density\" with a cross-section "
     "(\"Stiffness input = section\")"},
    {"dynamics_without_twist_inertia",
     valid_cantilever + valid_time_stepping + midpoint_integrator +
       section("Material", "  set Mass per length = 1\n"),
     ".prm",
     "",
     1,
     "entry \"Material/Twist inertia per length\": time stepping with the "
     "midpoint integrator needs the twist inertia per length of the rods of "
     "\"Material\""},
    {"negative_mass_per_length",
     with("Material", "  set Mass per length = -1\n"),
     ".prm",
     "",
     1,
     "entry \"Mass per length\" cannot be \"-1\"; it takes: number "
     ">= 0"},
    // The rotary inertia: "auto" or a finite number >= 0, in our words.
    {"negative_rotary_inertia",
     with("Material", "  set Rotary inertia per length = -1e-3\n"),
     ".prm",
     "",
     1,
     "entry \"Material/Rotary inertia per length\": \"-1e-3\" is not a "
     "rotary inertia: give a finite number >= 0 (kg m; 0 for none) or auto "
     "(half the twist inertia per length)"},
    {"rotary_inertia_not_a_number",
     with("Material", "  set Rotary inertia per length = half\n"),
     ".prm",
     "",
     1,
     "entry \"Material/Rotary inertia per length\": \"half\" is not a "
     "rotary inertia"},
    {"infinite_rotary_inertia",
     with("Material", "  set Rotary inertia per length = inf\n"),
     ".prm",
     "",
     1,
     "entry \"Material/Rotary inertia per length\": in \"inf\", \"inf\" "
     "is not a finite number; every number of a scene must be finite"},
    {"mass_per_length_contradicts_material_density",
     valid_cantilever + valid_time_stepping + midpoint_integrator +
       section("Material",
               "  set Density = 7850\n"
               "  set Mass per length = 1\n"
               "  subsection linear elastic\n"
               "    set Stiffness input = section\n"
               "    set Young's modulus = 2.1e11\n"
               "    set Cross section = circle\n"
               "    set Radius = 0.01\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Material/Mass per length\": 1 kg/m differs from the 2.46615 "
     "kg/m of \"Material/Density\" times the section's area; give one of "
     "them"},
    // Rigid bodies: positive numbers, a known place, and what a constant
    // mass matrix can represent (doc/dynamics.md, "Rigid bodies").
    {"rigid_body_negative_mass",
     with("Loads", "  set Rigid bodies = end: mass -1\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the mass \"-1\" must be a "
     "positive number"},
    {"rigid_body_mass_not_finite",
     with("Loads", "  set Rigid bodies = end: mass inf\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": in \"end: mass inf\", \"inf\" is not a "
     "finite number; every number of a scene must be finite"},
    {"rigid_body_zero_inertia",
     with("Loads", "  set Rigid bodies = end: mass 1 inertia 0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the inertia \"0\" must be a "
     "positive number"},
    {"rigid_body_zero_offset",
     with("Loads", "  set Rigid bodies = end: mass 1 offset 0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the offset \"0\" must be a "
     "positive number (the centre lies beyond the rod end; leave the offset "
     "out for a centre at the end)"},
    {"rigid_body_without_mass",
     with("Loads", "  set Rigid bodies = end: inertia 1\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the body has no mass; write "
     "\"<place>: mass <m> [inertia <j> | <J_t>,<J_p> | "
     "<J_xx>,<J_yy>,<J_zz>[,<J_yz>,<J_zx>,<J_xy>]] [offset <c> | centre "
     "<dx>,<dy>,<dz>]\""},
    {"rigid_body_unknown_word",
     with("Loads", "  set Rigid bodies = end: mass 1 spin 2\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": \"spin\" is none of mass, "
     "inertia, offset"},
    // A general inertia tensor (doc/dynamics.md, "Rigid bodies"): positive
    // moments, positive definite, no offset, the midpoint rule.
    {"rigid_body_tensor_negative_moment",
     with("Loads", "  set Rigid bodies = end: mass 1 inertia 1,2,-3\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the inertia \"-3\" must be a "
     "positive number"},
    {"rigid_body_tensor_not_positive_definite",
     with("Loads", "  set Rigid bodies = end: mass 1 inertia 1,1,1,0,0,2\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the inertia tensor has the "
     "principal moment -1"},
    {"rigid_body_four_inertias",
     with("Loads", "  set Rigid bodies = end: mass 1 inertia 1,2,3,4\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the inertia \"1,2,3,4\" should "
     "be <j> (isotropic), <J_t>,<J_p> (axisymmetric about a rod end's "
     "tangent), or three or six components of a tensor"},
    {"rigid_body_tensor_with_offset",
     with("Loads", "  set Rigid bodies = end: mass 1 inertia 1,2,3 offset 1\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the inertia tensor comes with "
     "another inertia or a rod end's offset; give the tensor alone (a centre "
     "off a junction: centre <dx>,<dy>,<dz>)"},
    // A centre off the vertex (doc/dynamics.md, "Rigid bodies"): three
    // finite numbers, not all zero, a junction that turns, the midpoint
    // rule.
    {"rigid_body_centre_zero",
     with("Loads", "  set Rigid bodies = end: mass 1 centre 0,0,0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the centre \"0,0,0\" must be "
     "three finite numbers <dx>,<dy>,<dz> (m), not all zero (leave it out "
     "for a centre at the vertex)"},
    {"rigid_body_centre_two_numbers",
     with("Loads", "  set Rigid bodies = end: mass 1 centre 0.1,0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the centre \"0.1,0\" must be "
     "three finite numbers"},
    {"rigid_body_centre_not_finite",
     with("Loads", "  set Rigid bodies = end: mass 1 centre 0.1,inf,0\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": in \"end: mass 1 centre 0.1,inf,0\", "
     "\"inf\" is not a finite number; every number of a scene must be "
     "finite"},
    {"rigid_body_centre_newmark",
     with("Loads", "  set Rigid bodies = end: mass 1 centre 0.1,0,0\n") +
       section("Material",
               "  set Mass per length = 1\n"
               "  set Twist inertia per length = 1\n") +
       valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Integrator = newmark\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": a centre off the vertex turns "
     "with the body, and only the midpoint rule carries it"},
    {"rigid_body_centre_dynamic_relaxation",
     with("Loads", "  set Rigid bodies = end: mass 1 centre 0.1,0,0\n") +
       section("Solver", "  set Method = dynamic relaxation\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": the bending-active element of "
     "dynamic relaxation has no junction rotation to carry a centre off the "
     "vertex; use Solver/Method = newton or continuation"},
    {"rigid_body_centre_vertex_held_in_part",
     with("Loads", "  set Rigid bodies = end: mass 1 centre 0.1,0,0\n") +
       section("Material",
               "  set Mass per length = 1\n"
               "  set Twist inertia per length = 1\n") +
       section("Supports", "  set Fixed components = end: z\n") +
       valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Integrator = midpoint\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": its centre is off vertex 10 "
     "of rod 0, which is held in part; a centre off the vertex is "
     "represented at a free vertex or at one held fixed"},
    {"rigid_body_tensor_newmark",
     with("Loads", "  set Rigid bodies = end: mass 1 inertia 1,2,3\n") +
       section("Material",
               "  set Mass per length = 1\n"
               "  set Twist inertia per length = 1\n") +
       valid_time_stepping +
       section("Solver",
               "  subsection Time stepping\n"
               "    set Integrator = newmark\n"
               "  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"end\": a general inertia tensor turns "
     "with the body, and only the midpoint rule carries it (its force "
     "depends on the orientation, not on the constant mass matrix); the "
     "newmark integrator does not: use Integrator = midpoint"},
    {"rigid_body_unknown_place",
     with("Loads", "  set Rigid bodies = tip: mass 1\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"tip\" names no vertex"},
    {"rigid_body_offset_inside_rod",
     with("Loads", "  set Rigid bodies = mid: mass 1 offset 0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Rigid bodies\": \"mid\": vertex 5 of rod 0 is no free "
     "rod end, and an offset needs the end's tangent to align with; give "
     "the isotropic \"inertia <j>\" alone there"},
    // An entry that the generator does not read would look as if it acted.
    {"lattice_director",
     with("Geometry",
          "  set Generator = square lattice\n"
          "  set Director d1 = 0, 1, 1\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Director d1\": the square lattice generator does not "
     "read it: a network orients each beam itself"},
    {"frame_cells",
     with("Geometry",
          "  set Generator = frame\n"
          "  set Cells = 3, 3\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Cells\": the frame generator does not read it, only "
     "the square lattice and hexagonal lattice generators do; remove it"},
    {"gmsh_rods_segments",
     valid_cantilever + section("Geometry",
                                "  set Generator = gmsh\n"
                                "  set Mesh file = " +
                                  data_folder + "straight_rod.msh\n"),
     ".prm",
     "",
     1,
     "entry \"Geometry/Segments\": the gmsh generator does not read it: the "
     "mesh's line elements are the segments; remove it"},
    // In a network a vertex without its rod meant rod 0.
    {"network_clamp_without_rod",
     with("Geometry", "  set Generator = frame\n"),
     ".prm",
     "",
     1,
     "entry \"Supports/Clamped ends\": \"start\" names no rod, and the scene "
     "has 2 rods; write \"<rod>:start\" (\"0:start\" for rod 0) or "
     "\"@<name>\" of a free network end or junction"},
    {"network_force_without_rod",
     with("Geometry", "  set Generator = frame\n") +
       section("Supports", "  set Clamped ends =\n") +
       section("Loads", "  set Point forces = mid: 0, 0, -1\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Point forces\": \"mid\" names no rod, and the scene has "
     "2 rods; write \"<rod>:mid\" (\"0:mid\" for rod 0) or \"@<name>\" of "
     "a named vertex"},
    {"unknown_vertex_name",
     with("Geometry", "  set Generator = frame\n") +
       section("Supports", "  set Clamped ends = @tipp\n"),
     ".prm",
     "",
     1,
     "entry \"Supports/Clamped ends\": there is no vertex or junction called "
     "\"tipp\"; the names are \"clamp\", \"corner\", \"tip\""},
    // Substrate loading (doc/morphing.md): sites that are no vertex or rod
    // end, held twice or off the substrate, strains that fold it.
    {"substrate_unknown_site",
     with("Substrate",
          "  set Pinned sites = @nowhere\n  set Compressive strain = 0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Pinned sites\": there is no vertex or junction "
     "called \"nowhere\""},
    {"substrate_clamped_site_not_an_end",
     with("Substrate",
          "  set Clamped sites = mid\n  set Compressive strain = 0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Clamped sites\": \"mid\" names no rod end"},
    {"substrate_site_also_clamped",
     with("Substrate",
          "  set Clamped sites = start\n  set Compressive strain = 0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Clamped sites\": the bonding site \"start\" holds "
     "vertex 0 of rod 0, which \"Clamped ends: start\" holds as well; a "
     "bonding site takes its position from the substrate alone"},
    {"substrate_site_also_prescribed",
     with("Substrate",
          "  set Pinned sites = end\n  set Compressive strain = 0.1\n") +
       section("Supports", "  set Prescribed displacements = end: x=-0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Pinned sites\": the bonding site \"end\" holds "
     "vertex 10 of rod 0, which \"Prescribed displacements: end: x=-0.1\" "
     "holds as well"},
    {"substrate_clamped_pinned_junction",
     valid_cantilever +
       section("Geometry",
               "  set Generator = network file\n"
               "  set Network file = " +
                 data_folder + "pinned_junction.net\n") +
       section("Supports", "  set Clamped ends = @a\n") +
       section("Substrate",
               "  set Clamped sites = @j\n  set Compressive strain = 0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Clamped sites\": \"@j\" is the pinned junction "
     "\"j\", which has no rotation to clamp; give it in \"Substrate/Pinned "
     "sites\""},
    {"substrate_site_off_the_plane",
     with("Geometry",
          "  set Generator = polyline\n"
          "  set Points = 0,0,0; 1,0,0; 1,0,1\n") +
       section("Substrate",
               "  set Pinned sites = 0:10, end\n"
               "  set Compressive strain = 0.1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Pinned sites\": the bonding site \"end\" lies at "
     "z = 1, off the substrate, the plane z = 0 of \"0:10\""},
    {"substrate_inverted",
     with("Substrate",
          "  set Pinned sites = end\n  set Compressive strain = 1\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/Compressive strain\": 1 would shrink the substrate "
     "to a point or turn it inside out"},
    {"substrate_folded",
     with("Substrate",
          "  set Pinned sites = end\n  set In-plane strain = 0.2, -1.5, 0\n"),
     ".prm",
     "",
     1,
     "entry \"Substrate/In-plane strain\": the substrate's principal "
     "stretch -0.5 at load factor 1 folds or inverts it"},
    {"substrate_two_strains",
     with("Substrate",
          "  set Pinned sites = end\n  set Compressive strain = 0.1\n"
          "  set Released prestretch = 0.2\n"),
     ".prm",
     "",
     1,
     "subsection \"Substrate\": give one of \"Compressive strain\", "
     "\"Released prestretch\" and \"In-plane strain\", not several"},
    {"substrate_without_sites",
     with("Substrate", "  set Released prestretch = 0.5\n"),
     ".prm",
     "",
     1,
     "subsection \"Substrate\": the substrate is strained but nothing is "
     "bonded to it"},
    // Pinning every junction where there is none.
    {"pinned_junctions_of_a_rod",
     with("Supports", "  set Pinned vertices = junctions\n"),
     ".prm",
     "",
     1,
     "entry \"Supports/Pinned vertices\": \"junctions\" pins every "
     "junction, but the scene has none (1 rod and no junction)"},
    // Imperfections that cannot act as their Magnitude says.
    {"held_imperfection_alone",
     with("Loads",
          "  subsection Imperfections\n"
          "    set Moments = end: 0,0,1 0.01\n  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Imperfections/Magnitude\": the imperfections are held "
     "at their full value and the load factor has nothing else to ramp"},
    {"ramped_imperfection_fixed_loads",
     with("Supports", "  set Prescribed displacements = end: x=1e-3\n") +
       section("Loads",
               "  set Fixed loads = true\n"
               "  subsection Imperfections\n"
               "    set Point forces = end: 0, 1e-3, 0\n"
               "    set Magnitude = ramped\n  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Imperfections/Magnitude\": \"ramped\" contradicts "
     "Loads/Fixed loads = true"},
    {"imperfection_moment_without_value",
     with("Loads",
          "  set Point forces = end: 0, 0, 1\n"
          "  subsection Imperfections\n"
          "    set Moments = end: 0,0,1\n  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Imperfections/Moments\": \"0,0,1\" should read "
     "\"<ax>,<ay>,<az> <value>\""},
    {"imperfection_moment_at_a_clamped_junction",
     with("Geometry", "  set Generator = frame\n") +
       section("Supports", "  set Clamped ends =\n") +
       section("Loads",
               "  set Point forces = @tip: 0, 0, 1e-3\n"
               "  subsection Imperfections\n"
               "    set Moments = clamp: 0,0,1 0.1\n  end\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Imperfections/Moments\": \"clamp\": moment at junction "
     "\"clamp\": a clamped junction has no free rotation to load"},
    {"held_imperfection_dynamic_relaxation",
     with("Loads",
          "  set Point forces = end: 0, 0, 1\n"
          "  subsection Imperfections\n"
          "    set Point forces = end: 0, 1e-3, 0\n  end\n") +
       section("Solver", "  set Method = dynamic relaxation\n"),
     ".prm",
     "",
     1,
     "entry \"Loads/Imperfections/Magnitude\": dynamic relaxation ramps its "
     "loads only"},
    {"unknown_probe_kind",
     with("Output", "  set Probes = a: angle end\n"),
     ".prm",
     "",
     1,
     "unknown probe kind \"angle\"; known: angular momentum <x|y|z> "
     "[N m s], distance <vertex> <vertex> [m], eigenvalue [mixed], energy "
     "[J], kinetic energy [J], linear momentum <x|y|z> [N s], "
     "moment <junction> <x|y|z> [N m], position <vertex> <x|y|z> [m], "
     "potential energy [J], reaction <vertex> <x|y|z> [N], rotation "
     "<junction> <ax>,<ay>,<az> [rad], total energy [J]"},
    {"unknown_momentum_component",
     with("Output", "  set Probes = p: linear momentum w\n"),
     ".prm",
     "",
     1,
     "entry \"Output/Probes\", probe \"p: linear momentum w\": component "
     "\"w\" is not x, y or z"},
    {"motion_probe_in_statics",
     with("Output", "  set Probes = E: kinetic energy\n"),
     ".prm",
     "",
     1,
     "entry \"Output/Probes\", probe \"E\": energies and momenta of the "
     "motion need dynamic time stepping (Solver/Method = time stepping with "
     "an Integrator other than quasi-static)"},
    // Activation fields (doc/morphing.md) on the cantilever of length 1.
    {"activation_past_the_rod",
     with("Group all", "  set Natural curvature = 1, 0 on 0.5 to 1.5\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Natural curvature\", item \"1, 0 on 0.5 to 1.5\": "
     "the region reaches s = 1.5, past the end of rod 0 (length 1)"},
    {"activation_unknown_group",
     with("Group x-beams", "  set Natural twist = 1\n"),
     ".prm",
     "",
     1,
     "subsection \"Group x-beams\": no rod is in group \"x-beams\"; the "
     "groups of this geometry are \"all\""},
    {"activation_not_finite",
     with("Group all", "  set Natural curvature = 1/(s-0.5), 0\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Natural curvature\", item \"1/(s-0.5), 0\": the "
     "value is inf at s = 0.5 of rod 0; give values finite on the whole "
     "region"},
    {"activation_values",
     with("Group all", "  set Natural curvature = 1 on 0 to 0.5\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Natural curvature\", item \"1 on 0 to 0.5\": give 2 "
     "values separated by ','"},
    {"activation_region",
     with("Group all", "  set Axial eigenstrain = 0.01 on middle\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Axial eigenstrain\", item \"0.01 on middle\": the "
     "region after \"on\" should be \"all\", \"<s0> to <s1>\" or \"near "
     "ends <d>\""},
    {"activation_inextensible",
     with("Material", "  set Inextensible = true\n") +
       section("Group all", "  set Axial eigenstrain = 0.01\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Axial eigenstrain\": rod 0 is inextensible: an axial "
     "eigenstrain cannot change its length"},
    {"activation_expression",
     with("Group all", "  set Natural twist = 2*q\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Natural twist\": \"2*q\" is not an expression of "
     "s,L: Parsing Error at Column 1. The parser said: Unexpected token "
     "\"q\" found at position 2."},
    {"activation_time_missing",
     with("Group all", "  set Natural twist = 1 in time\n") +
       valid_time_stepping,
     ".prm",
     "",
     1,
     "entry \"Group all/Natural twist\", item \"1 in time\": give the "
     "function of time after \"in time\", e.g. \"in time 1 - exp(-t/2)\""},
    {"activation_time_outside_time_stepping",
     with("Group all", "  set Natural curvature = 1, 0 in time t\n"),
     ".prm",
     "",
     1,
     "entry \"Group all/Natural curvature\", item \"1, 0 in time t\": a "
     "function of time drives a field in time stepping only; set "
     "Solver/Method = time stepping, or drive it by the load factor "
     "(\"ramped\")"},
    {"activation_time_not_finite",
     with("Group all", "  set Natural curvature = 1, 0 in time 1/(t - 0.5)\n") +
       valid_time_stepping,
     ".prm",
     "",
     1,
     "entry \"Group all/Natural curvature\", item \"1, 0 in time 1/(t - "
     "0.5)\": the function of time is inf at t = 0.5 s"},
    {"moving_support_outside_time_stepping",
     with("Supports",
          "  set Prescribed displacements = end: x=0.1 in time t\n"),
     ".prm",
     "",
     1,
     "entry \"Supports/Prescribed displacements\", item \"end: x=0.1 in "
     "time t\": a function of time moves a support in time stepping only; "
     "set Solver/Method = time stepping, or let the load factor move it "
     "(without \"in time\")"},
    {"fixed_loads_only_supports_in_time",
     with("Supports",
          "  set Prescribed displacements = end: x=0.1 in time t\n") +
       section("Loads", "  set Fixed loads = true\n") + valid_time_stepping,
     ".prm",
     "",
     1,
     "entry \"Loads/Fixed loads\": with the loads fixed the load factor has "
     "nothing to ramp; give Loads/Ramped natural shape, a ramped activation "
     "field (Group <name>/Natural curvature, ...), Supports/Prescribed "
     "displacements or rotations without \"in time\""},
    {"moving_support_time_missing",
     with("Supports", "  set Prescribed displacements = end: x=0.1 in time\n") +
       valid_time_stepping,
     ".prm",
     "",
     1,
     "entry \"Supports/Prescribed displacements\", item \"end: x=0.1 in "
     "time\": give the function of time after \"in time\""},
    {"moving_support_not_finite",
     with("Supports",
          "  set Prescribed rotations = end: 0,0,1 10 in time 1/(t - 0.5)\n") +
       valid_time_stepping,
     ".prm",
     "",
     1,
     "entry \"Supports/Prescribed rotations\", item \"end: 0,0,1 10 in "
     "time 1/(t - 0.5)\": the function of time is inf at t = 0.5 s"},
    {"moving_support_conflict",
     with("Supports",
          "  set Prescribed displacements = end: x=0.1 in time t; end: x=0.1 "
          "in time t^2\n") +
       valid_time_stepping,
     ".prm",
     "",
     1,
     "the supports \"Prescribed displacements: end: x=0.1 in time t\" and "
     "\"Prescribed displacements: end: x=0.1 in time t^2\" hold x of vertex "
     "10 of rod 0 at different values, 0.1 m times t and 0.1 m times t^2; a "
     "position may be held twice only at the same value"},
  };

  class BadInputTable : public ::testing::TestWithParam<BadInput>
  {
  };

  TEST_P(BadInputTable, RefusedWithOneClearLine)
  {
    const BadInput &b         = GetParam();
    std::string     arguments = b.arguments;
    if (!b.extension.empty())
      {
        const std::string path = "bad_input_" + b.name + b.extension;
        std::ofstream(path) << b.scene;
        arguments = path + " " +
                    (b.arguments.empty() ? "--output out_bad_input_" + b.name :
                                           b.arguments);
      }
    const rodnet::testing::DriverOutcome o = run_driver_with(arguments);
    EXPECT_EQ(o.exit_code, b.exit_code) << o.output;
    EXPECT_NE(o.output.find(b.fragment), std::string::npos)
      << "message lacks \"" << b.fragment << "\":\n"
      << o.output;
    // One line of error, after the size lines ("rodnet: ...") of a scene
    // refused once its model is built; a usage text follows errors of the
    // arguments only.
    const bool argument_error =
      b.extension.empty() || b.arguments == "--output";
    std::istringstream lines(o.output);
    std::string        line;
    unsigned int       n_lines = 0;
    while (std::getline(lines, line))
      n_lines += line.rfind("rodnet: ", 0) != 0;
    if (!argument_error)
      {
        EXPECT_EQ(n_lines, 1u) << o.output;
      }
    for (const char *noise : {"Stacktrace", "An error occurred", "Aborting"})
      EXPECT_EQ(o.output.find(noise), std::string::npos) << o.output;
  }

  INSTANTIATE_TEST_SUITE_P(Cases,
                           BadInputTable,
                           ::testing::ValuesIn(bad_inputs),
                           [](const auto &info) { return info.param.name; });

  TEST(BadInputTable, VtuFilesBeyondTheDisk)
  {
    // 10000 VTU files of 1e6 segments, at most 60 bytes per vertex each:
    // up to 600 GB, refused before the model is built where the disk has
    // less (the memory check must pass first: 4e6 DoFs, about 3.4 GB).
    const double vtu_bytes = 10000 * (2000 + 60 * 1000001.0);
    if (std::filesystem::space(".").available > vtu_bytes / 2)
      GTEST_SKIP() << "the disk has room for the files";
    std::ifstream meminfo("/proc/meminfo");
    std::string   key;
    double        available = 0;
    while (meminfo >> key >> available && key != "MemAvailable:")
      meminfo.ignore(100, '\n');
    if (available * 1024 < 5e9)
      GTEST_SKIP() << "too little memory for the scene to pass that check";
    std::ofstream("bad_input_disk.prm")
      << with("Geometry", "  set Segments = 1000000\n") +
           section("Loads", "  set Steps = 9999\n") +
           section("Output", "  set Write VTU = true\n");
    const rodnet::testing::DriverOutcome o =
      run_driver_with("bad_input_disk.prm --output out_bad_input_disk");
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find("entry \"Output/VTU interval\": the 10000 VTU "
                            "files of the run would take up to 600 GB"),
              std::string::npos)
      << o.output;
    EXPECT_EQ(o.output.find("building"), std::string::npos) << o.output;
  }

  TEST(BadInputTable, ByteOrderMarkIsSkipped)
  {
    // A UTF-8 byte-order mark, as some editors write, before a valid scene.
    std::ofstream("bom.prm") << "\xEF\xBB\xBF" << valid_cantilever;
    const rodnet::testing::DriverOutcome o =
      run_driver_with("bom.prm --output out_bom");
    EXPECT_EQ(o.exit_code, 0) << o.output;
    EXPECT_TRUE(std::filesystem::exists("out_bom/probes.csv"));
  }
} // namespace
