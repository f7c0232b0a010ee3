// Beam networks read three ways give the same rods and junctions: built by
// the network generators, read from a node/edge list (.net) and from Gmsh
// line meshes (.msh 2.2 and 4.1). Bad input fails with a message that names
// the node, beam or file line.
#include <core/rod_model.h>
#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>
#include <io/gmsh_network.h>
#include <io/network_file.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  std::string
  data(const std::string &name)
  {
    return RODNET_SOURCE_DIR "/tests/input/data/" + name;
  }

  /// Writes @p text to @p name in the working directory; returns the path.
  std::string
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
    return name;
  }

  /// Expects @p f to throw std::invalid_argument whose message holds every
  /// one of @p parts.
  void
  expect_error(const std::function<void()>    &f,
               const std::vector<std::string> &parts)
  {
    try
      {
        f();
        ADD_FAILURE() << "no exception; expected one naming " << parts[0];
      }
    catch (const std::invalid_argument &e)
      {
        for (const std::string &part : parts)
          EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
            << "\"" << e.what() << "\" does not mention " << part;
      }
  }

  /// Same rods (vertex positions to 1e-14, directors), same
  /// junctions (kinds, ends, names if @p same_names) and node maps.
  void
  expect_same_network(const BuiltNetwork &a,
                      const BuiltNetwork &b,
                      const bool          same_names)
  {
    const RodNetwork &na = *a.network, &nb = *b.network;
    ASSERT_EQ(na.rods().size(), nb.rods().size());
    for (unsigned int r = 0; r < na.rods().size(); ++r)
      {
        const Rod &ra = na.rods()[r], &rb = nb.rods()[r];
        ASSERT_EQ(ra.vertices.size(), rb.vertices.size()) << "rod " << r;
        for (unsigned int k = 0; k < ra.vertices.size(); ++k)
          EXPECT_LE(
            (na.vertex(ra.vertices[k]) - nb.vertex(rb.vertices[k])).norm(),
            1e-14)
            << "rod " << r << ", vertex " << k;
        EXPECT_EQ(ra.director_hint, rb.director_hint) << "rod " << r;
        EXPECT_EQ(ra.closed, rb.closed);
      }
    EXPECT_EQ(a.node_junction, b.node_junction);
    EXPECT_EQ(a.node_vertex, b.node_vertex);
    ASSERT_EQ(na.junctions().size(), nb.junctions().size());
    for (unsigned int j = 0; j < na.junctions().size(); ++j)
      {
        const Junction &ja = na.junctions()[j], &jb = nb.junctions()[j];
        if (same_names)
          {
            EXPECT_EQ(ja.name, jb.name);
          }
        EXPECT_EQ(ja.kind, jb.kind) << ja.name;
        EXPECT_EQ(ja.vertex, jb.vertex) << ja.name;
        ASSERT_EQ(ja.ends.size(), jb.ends.size()) << ja.name;
        for (unsigned int e = 0; e < ja.ends.size(); ++e)
          {
            EXPECT_EQ(ja.ends[e].rod, jb.ends[e].rod);
            EXPECT_EQ(ja.ends[e].at_start, jb.ends[e].at_start);
          }
      }
  }

  BuiltNetwork
  build(const RodGraph &graph, const unsigned int segments)
  {
    return build_rod_network(graph, segments, "simple");
  }

  TEST(NetworkInputs, FrameFileMatchesGenerator)
  {
    const BuiltNetwork generated =
      build(network_generators::right_angle_frame(1.5), 4);
    const BuiltNetwork read = build(read_network_file(data("frame.net")), 4);
    expect_same_network(generated, read, true);

    const RodNetwork &net = *generated.network;
    ASSERT_EQ(net.junctions().size(), 2u);
    EXPECT_EQ(net.junctions()[0].name, "clamp");
    EXPECT_EQ(net.junctions()[0].kind, JunctionKind::clamped);
    EXPECT_EQ(net.junctions()[1].name, "corner");
    EXPECT_EQ(net.junctions()[1].kind, JunctionKind::welded);
    EXPECT_EQ(generated.node_junction[2], -1); // the tip is free
    EXPECT_LE(
      (net.vertex(net.named_vertex("tip")) - Vector3(1.5, 1.5, 0)).norm(),
      1e-15);
    EXPECT_EQ(net.rods()[0].director_hint, Vector3::UnitZ());
  }

  TEST(NetworkInputs, FrameGmsh41MatchesGenerator)
  {
    // Physical points name the nodes as the generator does and clamp one;
    // the corner joins two lines of one physical group and is a junction
    // only because a physical point marks it.
    const BuiltNetwork generated =
      build(network_generators::right_angle_frame(1.5), 2);
    const BuiltNetwork read =
      build(read_gmsh_network(data("frame_v41.msh")), 2);
    expect_same_network(generated, read, true);
  }

  TEST(NetworkInputs, SquareLatticeGmsh22MatchesGenerator)
  {
    const RodGraph generated_graph =
      network_generators::square_lattice(2, 2, 0.5);
    const RodGraph read_graph =
      read_gmsh_network(data("square_lattice_2x2.msh"));
    EXPECT_EQ(generated_graph.nodes.size(), 9u);
    EXPECT_EQ(generated_graph.beams.size(), 12u);
    ASSERT_EQ(read_graph.nodes.size(), 9u);
    ASSERT_EQ(read_graph.beams.size(), 12u);
    for (const RodGraph::Beam &beam : read_graph.beams)
      EXPECT_EQ(beam.interior.size(), 2u);

    const BuiltNetwork generated = build(generated_graph, 3);
    const BuiltNetwork read      = build(read_graph, 3);
    // The mesh numbers nodes and elements as the generator orders them:
    // the rods come out identical, not only equal as sets.
    expect_same_network(generated, read, false);
    EXPECT_EQ(generated.network->junctions().size(), 9u);
    for (const Junction &j : read.network->junctions())
      EXPECT_EQ(j.kind, JunctionKind::welded) << j.name;
    // The mesh's two physical lines split the beams as the generator's
    // "x-beams" and "y-beams" do; a beam of the mesh is in the group of
    // its physical tag.
    for (unsigned int b = 0; b < read_graph.beams.size(); ++b)
      {
        const std::vector<std::string> &groups = read_graph.beams[b].groups;
        ASSERT_FALSE(groups.empty()) << "beam " << b;
        EXPECT_EQ(groups.front() == read_graph.beams.front().groups.front(),
                  generated_graph.beams[b].groups.front() == "x-beams")
          << "beam " << b;
      }
  }

  /// Solves the lattice @p graph (beams of EA = 1000, EI = 1, GJ = 2/3 in
  /// 3 segments) with its bottom row (y = 0) clamped and a force (F, 0, 0)
  /// on each top-row node (y = 1), in 5 steps. Returns the model and state.
  std::pair<std::unique_ptr<RodModel>, VectorType>
  solve_sheared_lattice(RodGraph graph, const double F)
  {
    for (RodGraph::Node &node : graph.nodes)
      if (node.position.y() == 0)
        node.kind = JunctionKind::clamped;
    BuiltNetwork built = build(graph, 3);
    const auto   material =
      std::make_shared<LinearElasticRod>(RodStiffness{1000, 1, 1, 2.0 / 3});
    auto model = std::make_unique<RodModel>(
      std::move(built.network),
      std::vector<std::shared_ptr<const RodMaterial>>(graph.beams.size(),
                                                      material));
    for (unsigned int n = 0; n < graph.nodes.size(); ++n)
      if (graph.nodes[n].position.y() == 1)
        model->add_point_force(built.node_vertex[n], Vector3(F, 0, 0));
    model->finalize();
    VectorType               u = model->create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = 5;
    StaticSolver(*model, parameters).run(u, [](const auto &, const auto &) {});
    return {std::move(model), u};
  }

  TEST(NetworkInputs, SquareLatticeGmshSolvesLikeGenerator)
  {
    // The welded 2 x 2 lattice sheared in its plane, built by the generator
    // and read from the Gmsh file (nodes and elements listed out of order):
    // every vertex, matched by its undeformed position, ends at the same
    // place to 1e-9 of the span, and the shear is large enough (top row
    // moved by more than 5% of the span) for that to mean something.
    const double F = 2.0;
    const auto [generated, u_generated] =
      solve_sheared_lattice(network_generators::square_lattice(2, 2, 0.5), F);
    const auto [read, u_read] =
      solve_sheared_lattice(read_gmsh_network(data("square_lattice_2x2.msh")),
                            F);
    const RodNetwork &a = generated->network();
    const RodNetwork &b = read->network();
    ASSERT_EQ(a.n_vertices(), b.n_vertices());
    double largest = 0;
    for (unsigned int v = 0; v < a.n_vertices(); ++v)
      {
        unsigned int match = b.n_vertices();
        for (unsigned int w = 0; w < b.n_vertices(); ++w)
          if ((a.vertex(v) - b.vertex(w)).norm() < 1e-12)
            match = w;
        ASSERT_LT(match, b.n_vertices())
          << "vertex at " << a.vertex(v).transpose() << " not in the mesh";
        const Vector3 x = generated->configuration().position(u_generated, v);
        const Vector3 y = read->configuration().position(u_read, match);
        EXPECT_LT((x - y).norm(), 1e-9)
          << "vertex at " << a.vertex(v).transpose();
        largest = std::max(largest, (x - a.vertex(v)).norm());
      }
    EXPECT_GT(largest, 0.05);
    std::cout << "largest displacement " << largest << std::endl;
  }

  TEST(NetworkInputs, GmshChainsFollowTheirElements)
  {
    // A star of three chains of two elements from hub node 1: the first
    // runs hub -> tip, the second tip -> hub, the third disagrees and
    // follows its lower element tag (5: node 7 -> hub, so tip -> hub).
    const std::string path =
      write("star.msh",
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            "$Nodes\n7\n"
            "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
            "5 0.5 0 0\n6 0 0.5 0\n7 0 0 0.5\n$EndNodes\n"
            "$Elements\n6\n"
            "1 1 2 1 1 1 5\n2 1 2 1 1 5 2\n"
            "3 1 2 1 1 3 6\n4 1 2 1 1 6 1\n"
            "5 1 2 1 1 7 1\n6 1 2 1 1 7 4\n$EndElements\n");
    const RodGraph graph = read_gmsh_network(path);
    ASSERT_EQ(graph.beams.size(), 3u);
    const auto name = [&](const unsigned int n) { return graph.nodes[n].name; };
    EXPECT_EQ(name(graph.beams[0].from) + ">" + name(graph.beams[0].to),
              "node1>node2");
    EXPECT_EQ(name(graph.beams[1].from) + ">" + name(graph.beams[1].to),
              "node3>node1");
    EXPECT_EQ(name(graph.beams[2].from) + ">" + name(graph.beams[2].to),
              "node4>node1");
    EXPECT_EQ(graph.beams[2].interior,
              std::vector<Vector3>{Vector3(0, 0, 0.5)});

    const BuiltNetwork built = build(graph, 1);
    ASSERT_EQ(built.network->junctions().size(), 1u);
    EXPECT_EQ(built.network->junctions()[0].name, "node1");
    EXPECT_EQ(built.network->junctions()[0].ends.size(), 3u);
  }

  TEST(NetworkInputs, GmshCornerOfOneGroupStaysInsideABeam)
  {
    // Documented limit: without a physical point or a change of group, a
    // node where two lines meet is an interior vertex (a bent rod).
    const RodGraph graph = read_gmsh_network(
      write("corner.msh",
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 1 1 0\n$EndNodes\n"
            "$Elements\n2\n1 1 2 4 1 1 2\n2 1 2 4 1 2 3\n$EndElements\n"));
    ASSERT_EQ(graph.beams.size(), 1u);
    EXPECT_EQ(graph.beams[0].interior, std::vector<Vector3>{Vector3(1, 0, 0)});
  }

  TEST(NetworkGenerators, Windmill)
  {
    const double       La    = 2.0;
    const RodGraph     graph = network_generators::windmill(La);
    const BuiltNetwork built = build(graph, 5);
    const RodNetwork  &net   = *built.network;
    const auto         chord = [&](const unsigned int b) {
      return Vector3(graph.nodes[graph.beams[b].to].position -
                     graph.nodes[graph.beams[b].from].position);
    };
    ASSERT_EQ(graph.beams.size(), 4u);
    EXPECT_NEAR((chord(0) - Vector3(0, 0, La)).norm(), 0, 1e-15);
    EXPECT_EQ(graph.beams[0].groups, std::vector<std::string>{"shaft"});
    for (unsigned int b = 1; b <= 3; ++b)
      EXPECT_EQ(graph.beams[b].groups, std::vector<std::string>{"blades"});
    EXPECT_EQ(net.rods()[0].director_hint, Vector3::UnitX());
    for (unsigned int b = 1; b <= 3; ++b)
      {
        EXPECT_NEAR(chord(b).norm(), La / 2, 1e-15);
        EXPECT_EQ(chord(b)[2], 0.);
        EXPECT_EQ(net.rods()[b].director_hint, Vector3::UnitZ());
        // 120 degrees between each pair of blades.
        const unsigned int c = b % 3 + 1;
        EXPECT_NEAR(chord(b).dot(chord(c)) / (La * La / 4), -0.5, 1e-14);
      }
    EXPECT_NEAR((chord(1) - Vector3(0, La / 2, 0)).norm(), 0, 1e-15);

    ASSERT_EQ(net.junctions().size(), 2u);
    const Junction &hub = net.junctions()[net.junction_index("hub")];
    EXPECT_EQ(hub.kind, JunctionKind::welded);
    EXPECT_EQ(hub.ends.size(), 4u);
    EXPECT_EQ(net.junctions()[net.junction_index("top")].kind,
              JunctionKind::clamped);
    // The blade tips are free ends the scene supports by name.
    for (const std::string tip : {"blade1", "blade2", "blade3"})
      {
        EXPECT_EQ(built.node_junction[graph.node_index(tip)], -1);
        EXPECT_EQ(net.named_vertex(tip),
                  built.node_vertex[graph.node_index(tip)]);
      }
  }

  TEST(NetworkGenerators, SquareLatticeCounts)
  {
    // (nx + 1)(ny + 1) nodes, nx (ny + 1) + ny (nx + 1) beams; corners
    // join two beams, so every node is a welded junction.
    const RodGraph     graph = network_generators::square_lattice(3, 2, 1.0);
    const BuiltNetwork built = build(graph, 2);
    EXPECT_EQ(graph.nodes.size(), 12u);
    EXPECT_EQ(graph.beams.size(), 17u);
    EXPECT_EQ(built.network->junctions().size(), 12u);
    EXPECT_EQ(graph.nodes[graph.node_index("n_3_1")].position,
              Vector3(3, 1, 0));
    const Junction &corner =
      built.network->junctions()[built.network->junction_index("n_3_2")];
    EXPECT_EQ(corner.ends.size(), 2u);
  }

  TEST(NetworkGenerators, HexagonalLatticeCounts)
  {
    // A patch of ny rows of nx cells, odd rows shifted by half a cell: its
    // corners lie on ny + 1 zigzag lines. The bottom and top ones hold
    // 2 nx + 1 corners, each of the ny - 1 between two rows 2 nx + 2. Euler
    // for the connected planar graph, V - E + F = 2 with the nx ny cells
    // and the outer face, gives E.
    const double a = 0.7;
    for (const auto &[nx, ny] :
         std::vector<std::pair<unsigned int, unsigned int>>{{1, 1},
                                                            {2, 2},
                                                            {3, 2},
                                                            {2, 3}})
      {
        const unsigned int V = 2 * (2 * nx + 1) + (ny - 1) * (2 * nx + 2);
        const unsigned int E = V + nx * ny - 1;
        if (nx == 2 && ny == 2)
          {
            EXPECT_EQ(V, 16u);
            EXPECT_EQ(E, 19u);
          }
        const RodGraph graph = network_generators::hexagonal_lattice(nx, ny, a);
        EXPECT_EQ(graph.nodes.size(), V) << nx << " x " << ny;
        EXPECT_EQ(graph.beams.size(), E) << nx << " x " << ny;

        std::vector<unsigned int> degree(graph.nodes.size(), 0);
        for (unsigned int b = 0; b < graph.beams.size(); ++b)
          {
            const RodGraph::Beam &beam = graph.beams[b];
            ++degree[beam.from];
            ++degree[beam.to];
            const Vector3 d =
              graph.nodes[beam.to].position - graph.nodes[beam.from].position;
            EXPECT_NEAR(d.norm(), a, 1e-14) << "beam " << b;
            // Sides are vertical or at +-30 degrees to x.
            EXPECT_NEAR(std::abs(d[1]) / a,
                        std::abs(d[0]) < 1e-12 ? 1.0 : 0.5,
                        1e-14);
          }
        for (const unsigned int d : degree)
          EXPECT_TRUE(d == 2 || d == 3) << d;

        const BuiltNetwork built = build(graph, 3);
        EXPECT_EQ(built.network->junctions().size(), V);
      }
  }

  TEST(NetworkInputs, BadNetworkFiles)
  {
    const auto read = [](const std::string &name, const std::string &text) {
      return [=] { read_network_file(write(name, text)); };
    };
    const std::string nodes = "node a 0 0 0\nnode b 1 0 0\n";
    expect_error(read("unknown.net", nodes + "beam a c\n"),
                 {"unknown.net:3", "\"c\""});
    expect_error(read("duplicate.net", nodes + "node a 2 0 0\n"),
                 {"duplicate.net:3", "\"a\"", "line 1"});
    expect_error(read("number.net", "node a 0 zero 0\n"),
                 {"number.net:1", "\"zero\""});
    expect_error(read("keyword.net", "# fine\n\nnod a 0 0 0\n"),
                 {"keyword.net:3", "\"nod\""});
    expect_error(read("missing.net", "node a 0 0\n"),
                 {"missing.net:1", "missing"});
    expect_error(read("kind.net", "node a 0 0 0 glued\n"),
                 {"kind.net:1", "\"glued\""});
    expect_error(read("option.net", nodes + "beam a b group\n"),
                 {"option.net:3", "the group's name"});
    expect_error(read("option.net", nodes + "beam a b d1 0 0 1 d1 0 1 0\n"),
                 {"option.net:3", "\"d1\""});
    expect_error([] { read_network_file("no/such/file.net"); },
                 {"no/such/file.net"});

    // The geometry is checked when the network is built.
    const auto built = [](const std::string &name, const std::string &text) {
      return [=] { build(read_network_file(write(name, text)), 2); };
    };
    expect_error(built("zero.net", "node a 0 0 0\nnode b 0 0 0\nbeam a b\n"),
                 {"beam 0 from node \"a\" to node \"b\" has zero length"});
    expect_error(built("welded.net",
                       "node a 0 0 0 welded\nnode b 1 0 0\n"
                       "beam a b\n"),
                 {"\"a\"", "welded"});
    expect_error(built("pinned.net",
                       "node a 0 0 0\nnode b 1 0 0 pinned\n"
                       "beam a b\n"),
                 {"\"b\"", "pinned"});
    // A single clamped or welded-and-pinned end is a support.
    const BuiltNetwork support =
      build(read_network_file(write("support.net",
                                    "node a 0 0 0 welded-and-pinned\n"
                                    "node b 1 0 0 clamped\nbeam a b\n")),
            2);
    EXPECT_EQ(support.network->junctions()[0].kind,
              JunctionKind::welded_pinned);
  }

  TEST(NetworkInputs, BadGraphs)
  {
    const auto graph =
      [](const std::vector<Vector3>                       &points,
         const std::vector<std::pair<unsigned, unsigned>> &beams) {
        RodGraph g;
        for (unsigned int n = 0; n < points.size(); ++n)
          g.nodes.push_back({std::string(1, char('a' + n)), points[n], {}});
        for (const auto &[from, to] : beams)
          {
            RodGraph::Beam beam;
            beam.from = from;
            beam.to   = to;
            g.beams.push_back(beam);
          }
        return g;
      };
    const Vector3 o = Vector3::Zero(), x = Vector3::UnitX();
    expect_error(
      [&] {
        build(graph({o, x}, {{0, 0}}), 2);
      },
      {"beam 0", "\"a\"", "same node"});
    expect_error([&] { build(graph({o, x}, {{0, 2}}), 2); }, {"beam 0"});
    expect_error([&] { build(graph({o, x}, {{0, 1}}), 0); }, {"segments"});
    expect_error(
      [&] {
        build(graph({o, x, 2 * x}, {{0, 1}}), 2);
      },
      {"node \"c\"", "not the end of any beam"});
    expect_error(
      [&] {
        build(graph({o, x, o}, {{0, 1}, {2, 1}}), 2);
      },
      {"\"a\"", "\"c\"", "coincide"});
    RodGraph parallel_hint               = graph({o, x}, {{0, 1}});
    parallel_hint.beams[0].director_hint = -x;
    expect_error([&] { build(parallel_hint, 2); }, {"beam 0", "parallel"});
    // The default director falls back to the axis least aligned with the
    // beam where it is parallel to it.
    RodGraph vertical = graph({o, Vector3::UnitZ()}, {{0, 1}});
    EXPECT_EQ(build(vertical, 2).network->rods()[0].director_hint,
              Vector3::UnitX());
  }

  TEST(NetworkInputs, BadGmshMeshes)
  {
    const std::string header = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
    const std::string square_nodes =
      "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n";
    const auto read = [](const std::string &name, const std::string &text) {
      return [=] { read_gmsh_network(write(name, text)); };
    };
    expect_error(read("loop.msh",
                      header + square_nodes +
                        "$Elements\n4\n1 1 2 1 1 1 2\n2 1 2 1 1 2 3\n"
                        "3 1 2 1 1 3 4\n4 1 2 1 1 4 1\n$EndElements\n"),
                 {"loop.msh", "closed beam loops are not supported"});
    // A loop through one branch node: the tail 1-5 makes node 1 a branch.
    expect_error(read("lasso.msh",
                      header +
                        "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n5 -1 0 0\n"
                        "$EndNodes\n$Elements\n4\n1 1 2 1 1 1 2\n"
                        "2 1 2 1 1 2 3\n3 1 2 1 1 3 1\n4 1 2 1 1 1 5\n"
                        "$EndElements\n"),
                 {"lasso.msh", "node 1", "closed beam loops"});
    expect_error(read("triangle.msh",
                      header + square_nodes +
                        "$Elements\n2\n1 1 2 1 1 1 2\n"
                        "7 2 2 1 1 1 2 3\n$EndElements\n"),
                 {"triangle.msh:", "element 7", "type 2"});
    expect_error(read("node.msh",
                      header + square_nodes +
                        "$Elements\n1\n3 1 2 1 1 1 9\n$EndElements\n"),
                 {"node.msh", "element 3", "node 9"});
    expect_error(read("number.msh",
                      header + "$Nodes\n1\n1 0 zero 0\n$EndNodes\n"),
                 {"number.msh:6", "\"zero\""});
    expect_error(read("name.msh",
                      header +
                        "$PhysicalNames\n1\n0 5 \"tip\"\n$EndPhysicalNames\n" +
                        square_nodes +
                        "$Elements\n4\n1 1 2 1 1 1 2\n2 1 2 1 1 3 4\n"
                        "3 15 2 5 5 2\n4 15 2 5 5 4\n$EndElements\n"),
                 {"name.msh", "\"tip\"", "nodes 2 and 4"});
    expect_error(read("version.msh", "$MeshFormat\n4.0 0 8\n$EndMeshFormat\n"),
                 {"version.msh:2", "4.0"});
    expect_error(read("binary.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n"),
                 {"binary.msh:2", "binary"});
    expect_error([] { read_gmsh_network("no/such/mesh.msh"); },
                 {"no/such/mesh.msh"});
  }
} // namespace
