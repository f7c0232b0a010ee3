// VtuOutput writes the deformed rod with its fields and a .pvd time series.
// The .vtu files are decoded here (base64, zlib, 32-bit floats) and compared
// with the state that was written, the activation fields of a scene with
// the fields that were given.

#include <deal.II/base/utilities.h>

#include <common/run_scene_text.h>
#include <core/dr_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <io/vtu_output.h>
#include <materials/linear_elastic_rod.h>
#include <materials/standard_linear_solid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <string>
#include <vector>
#include <zlib.h>

using namespace rodnet;
namespace fs = std::filesystem;

namespace
{
  constexpr unsigned int n_segments = 8;

  /// A straight rod along x of 8 segments with the director hint @p d1:
  /// its vertices k/8 and the displacements below are exact in single
  /// precision, so the positions that deal.II stores as 32-bit floats can
  /// be checked to 1e-12.
  std::unique_ptr<RodNetwork>
  straight_network(const Vector3 &d1)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          n_segments),
                     false,
                     d1,
                     "simple");
    network->create_triangulation();
    return network;
  }

  /// The rod of straight_network() with d1 = e_y as a RodModel.
  std::unique_ptr<RodModel>
  straight_rod(
    std::shared_ptr<const RodMaterial> material =
      std::make_shared<LinearElasticRod>(RodStiffness{1.0, 1.0, 1.0, 1.0}))
  {
    auto model = std::make_unique<RodModel>(
      straight_network(Vector3::UnitY()),
      std::vector<std::shared_ptr<const RodMaterial>>{material});
    model->finalize();
    return model;
  }

  std::string
  read_text(const fs::path &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// A fresh scratch directory under the test's working directory.
  fs::path
  scratch(const std::string &name)
  {
    const fs::path dir = fs::current_path() / ("io_vtu_output_" + name);
    fs::remove_all(dir);
    return dir;
  }

  /**
   * The values of the DataArray called @p name (or, for an empty name, the
   * point coordinates) of a VTU file written by deal.II: a base64 header of
   * four UInt32 (one block: count, block size, last block size, compressed
   * size), then the base64 zlib stream of the Float32 values.
   */
  std::vector<float>
  read_data_array(const std::string &vtu, const std::string &name)
  {
    const std::size_t tag = name.empty() ?
                              vtu.find("<DataArray", vtu.find("<Points>")) :
                              vtu.find("Name=\"" + name + "\"");
    if (tag == std::string::npos)
      throw std::runtime_error("no DataArray " + name);
    const std::size_t start   = vtu.find('>', tag) + 1;
    const std::size_t end     = vtu.find("</DataArray>", start);
    std::string       encoded = vtu.substr(start, end - start);
    encoded.erase(0, encoded.find_first_not_of(" \n\t"));
    encoded.erase(encoded.find_last_not_of(" \n\t") + 1);

    const std::vector<unsigned char> header_bytes =
      dealii::Utilities::decode_base64(encoded.substr(0, 24));
    std::uint32_t header[4];
    std::memcpy(header, header_bytes.data(), sizeof(header));
    if (header[0] != 1)
      throw std::runtime_error("expected one compressed block");

    const std::vector<unsigned char> compressed =
      dealii::Utilities::decode_base64(encoded.substr(24));
    std::vector<unsigned char> raw(header[2]);
    uLongf                     raw_size = raw.size();
    if (uncompress(raw.data(), &raw_size, compressed.data(), header[3]) !=
          Z_OK ||
        raw_size != raw.size())
      throw std::runtime_error("cannot inflate DataArray " + name);
    std::vector<float> values(raw.size() / sizeof(float));
    std::memcpy(values.data(), raw.data(), raw.size());
    return values;
  }
} // namespace

TEST(VtuOutput, WritesDeformedRodFieldsAndTimeSeries)
{
  const auto       model = straight_rod();
  const fs::path   dir   = scratch("series");
  VtuOutput        output(model->network(), dir.string());
  const DofLayout &layout = model->layout();

  // Step 0: a rigid translation. Step 1: also a quarter turn of the twist
  // of segment 3, which turns its directors about the rod axis x.
  const Vector3 translation(0.25, -0.5, 0.125);
  VectorType    u = model->create_vector();
  for (unsigned int v = 0; v <= n_segments; ++v)
    for (unsigned int c = 0; c < 3; ++c)
      u[layout.vertex_dof(v, c)] = translation[c];
  output.write(0, 0.5, *model, u);

  const unsigned int twisted   = 3;
  const double       angle     = M_PI / 2;
  u[layout.twist_dof(twisted)] = angle;
  output.write(1, 1.0, *model, u);

  ASSERT_TRUE(fs::exists(dir / "solution-00000.vtu"));
  ASSERT_TRUE(fs::exists(dir / "solution-00001.vtu"));
  EXPECT_EQ(output.vtu_path(1), (dir / "solution-00001.vtu").string());

  const std::string pvd = read_text(dir / "solution.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.5\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"solution-00000.vtu\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"1\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"solution-00001.vtu\""), std::string::npos);

  const std::string vtu = read_text(dir / "solution-00001.vtu");
  for (const std::string name : {"displacement",
                                 "twist",
                                 "curvature",
                                 "twist_rate",
                                 "d1",
                                 "d2",
                                 "axial_strain"})
    EXPECT_NE(vtu.find("Name=\"" + name + "\""), std::string::npos) << name;

  // One patch per segment, its two points in the cell's vertex order; the
  // segments of the single rod are cells 0..7 joining vertices c, c+1.
  const std::vector<float> points       = read_data_array(vtu, "");
  const std::vector<float> displacement = read_data_array(vtu, "displacement");
  const std::vector<float> twist        = read_data_array(vtu, "twist");
  const std::vector<float> d1           = read_data_array(vtu, "d1");
  const std::vector<float> d2           = read_data_array(vtu, "d2");
  const std::vector<float> strain       = read_data_array(vtu, "axial_strain");
  const std::vector<float> curvature    = read_data_array(vtu, "curvature");
  const std::vector<float> twist_rate   = read_data_array(vtu, "twist_rate");
  ASSERT_EQ(points.size(), 3 * 2 * n_segments);
  ASSERT_EQ(displacement.size(), points.size());
  ASSERT_EQ(twist.size(), 2 * n_segments);

  const double l = 1.0 / n_segments;
  for (unsigned int cell = 0; cell < n_segments; ++cell)
    for (unsigned int k = 0; k < 2; ++k)
      {
        const unsigned int p      = 2 * cell + k;
        const unsigned int vertex = cell + k;
        const Vector3 expected = model->network().vertex(vertex) + translation;
        for (unsigned int c = 0; c < 3; ++c)
          {
            EXPECT_NEAR(points[3 * p + c], expected[c], 1e-12)
              << "point " << p << " component " << c;
            EXPECT_NEAR(displacement[3 * p + c], translation[c], 1e-12);
          }
        EXPECT_NEAR(strain[p], 0.0, 1e-6);

        // d1 = cos(phi) e_y + sin(phi) e_z, d2 = e_x x d1 (Korner eq. 2.8
        // with the undeformed frame d1 = e_y, d3 = e_x).
        const double  phi = (cell == twisted) ? angle : 0.0;
        const Vector3 expected_d1(0, std::cos(phi), std::sin(phi));
        const Vector3 expected_d2(0, -std::sin(phi), std::cos(phi));
        EXPECT_NEAR(twist[p], phi, 1e-6);
        for (unsigned int c = 0; c < 3; ++c)
          {
            EXPECT_NEAR(d1[3 * p + c], expected_d1[c], 1e-6) << "cell " << cell;
            EXPECT_NEAR(d2[3 * p + c], expected_d2[c], 1e-6) << "cell " << cell;
          }

        // A straight rod has no bending. At the two hinges that bound
        // segment 3 the frames differ by a rotation of +-phi about the
        // axis, whose integrated twist is 2 sin(phi / 2) (Korner et al.
        // eq. 2.13); divided by the Voronoi length l. Zero elsewhere.
        for (unsigned int c = 0; c < 3; ++c)
          EXPECT_NEAR(curvature[3 * p + c], 0.0, 1e-6);
        const double jump          = 2 * std::sin(angle / 2) / l;
        const double expected_rate = (vertex == twisted)     ? jump :
                                     (vertex == twisted + 1) ? -jump :
                                                               0.0;
        EXPECT_NEAR(twist_rate[p], expected_rate, 1e-5) << "vertex " << vertex;
      }

  // Rewriting a step replaces its entry instead of adding one.
  output.write(1, 1.0, *model, u);
  const std::string rewritten = read_text(dir / "solution.pvd");
  std::size_t       entries   = 0;
  for (std::size_t at = rewritten.find("<DataSet"); at != std::string::npos;
       at             = rewritten.find("<DataSet", at + 1))
    ++entries;
  EXPECT_EQ(entries, 2u);
}

// Two rods welded at a knee: the second rod's first vertex is a copy of the
// knee vertex, identity-constrained to it. A displacement given at the
// knee's DoFs alone (the copy's DoFs left at zero) is drawn at both: the
// writer distributes the junction constraints on the model's DoFHandler.
TEST(VtuOutput, DrawsRodEndsAtAJunctionWithTheJunctionsDisplacement)
{
  auto network = std::make_unique<RodNetwork>();
  network->add_rod(generators::straight(Vector3(0, 0, 0), Vector3(1, 0, 0), 2),
                   false,
                   Vector3::UnitZ(),
                   "simple");
  network->add_rod(generators::straight(Vector3(1, 0, 0), Vector3(1, 1, 0), 2),
                   false,
                   Vector3::UnitZ(),
                   "simple");
  network->add_junction("knee", JunctionKind::welded, {{0, false}, {1, true}});
  RodModel model(std::move(network),
                 std::vector<std::shared_ptr<const RodMaterial>>(
                   2,
                   std::make_shared<LinearElasticRod>(
                     RodStiffness{1.0, 1.0, 1.0, 1.0})));
  model.finalize();
  const RodNetwork  &net  = model.network();
  const unsigned int knee = net.junctions()[0].vertex;
  ASSERT_NE(net.rods()[1].vertices.front(), knee); // the copy
  ASSERT_EQ(model.layout().junction_constraints().n_constraints(), 3u);

  const Vector3 lift(0.25, 0.5, -0.125);
  VectorType    u = model.create_vector();
  for (unsigned int c = 0; c < 3; ++c)
    u[model.layout().vertex_dof(knee, c)] = lift[c];
  u.compress(dealii::VectorOperation::insert);

  const fs::path dir = scratch("junction");
  VtuOutput      output(net, dir.string());
  output.write(0, 0.0, model, u);
  const std::string        vtu    = read_text(dir / "solution-00000.vtu");
  const std::vector<float> points = read_data_array(vtu, "");
  // Patches in cell order, two points each; the knee's undeformed position
  // (1, 0, 0) appears at the end of rod 0 and the start of rod 1.
  unsigned int n_knee_points = 0;
  for (unsigned int p = 0; 3 * p < points.size(); ++p)
    {
      const unsigned int cell = p / 2;
      const unsigned int vertex =
        dealii::TriaActiveIterator<dealii::CellAccessor<1, 3>>(
          &net.triangulation(),
          0,
          cell)
          ->vertex_index(p % 2);
      const bool    at_knee = net.vertex(vertex).isApprox(net.vertex(knee));
      const Vector3 expected =
        net.vertex(vertex) + (at_knee ? lift : Vector3::Zero());
      n_knee_points += at_knee;
      for (unsigned int c = 0; c < 3; ++c)
        EXPECT_NEAR(points[3 * p + c], expected[c], 1e-12)
          << "point " << p << " component " << c;
    }
  EXPECT_EQ(n_knee_points, 2u);
}

// A viscoelastic rod stretched uniformly by e over one committed step of
// dt: its viscous axial strain is (1 - w) e per segment, w = t_r/(t_r + dt),
// and its viscous curvatures are zero.
TEST(VtuOutput, WritesInternalVariables)
{
  const double t_r = 2.0, dt = 0.5, e = 0.125;
  const auto   rod = straight_rod(
    std::make_shared<StandardLinearSolid>(RodStiffness{1.0, 1.0, 1.0, 1.0},
                                          0.5,
                                          t_r));
  RodModel  &model = *rod;
  VectorType u     = model.create_vector();
  for (unsigned int v = 0; v <= n_segments; ++v)
    u[model.layout().vertex_dof(v, 0)] = e * model.network().vertex(v)[0];
  model.set_time_step(dt);
  model.commit_internal_variables(u);

  const fs::path dir = scratch("history");
  VtuOutput      output(model.network(), dir.string());
  output.write(0, dt, model, u);
  const std::string        vtu = read_text(dir / "solution-00000.vtu");
  const std::vector<float> viscous =
    read_data_array(vtu, "viscous_axial_strain");
  ASSERT_EQ(viscous.size(), 2 * n_segments);
  const double w = t_r / (t_r + dt);
  for (const float value : viscous)
    EXPECT_NEAR(value, (1 - w) * e, 1e-7);
  for (const std::string name :
       {"viscous_curvature_1", "viscous_curvature_2", "viscous_twist_rate"})
    for (const float value : read_data_array(vtu, name))
      EXPECT_NEAR(value, 0.0, 1e-7) << name;
}

// The dynamic relaxation model is written through the same interface,
// without a RodModel: its rod translated rigidly, with the normals of its
// frames (e_z, the director hint).
TEST(VtuOutput, WritesDynamicRelaxationStates)
{
  DrModel model(straight_network(Vector3::UnitZ()),
                {RodStiffness{1.0, 1.0, 1.0, 1.0}});
  model.finalize();
  const Vector3 translation(0.25, -0.5, 0.125);
  DrVector      u = model.create_vector();
  for (unsigned int v = 0; v <= n_segments; ++v)
    for (unsigned int c = 0; c < 3; ++c)
      u[model.position_dof(v, c)] = translation[c];

  const fs::path dir = scratch("relaxation");
  VtuOutput      output(model.network(), dir.string());
  output.write(3, 0.75, model, u);
  const std::string        vtu    = read_text(dir / "solution-00003.vtu");
  const std::vector<float> points = read_data_array(vtu, "");
  const std::vector<float> normal = read_data_array(vtu, "normal");
  ASSERT_EQ(points.size(), 3 * 2 * n_segments);
  ASSERT_EQ(normal.size(), points.size());
  for (unsigned int cell = 0; cell < n_segments; ++cell)
    for (unsigned int k = 0; k < 2; ++k)
      {
        const unsigned int p   = 2 * cell + k;
        const Vector3 expected = model.network().vertex(cell + k) + translation;
        for (unsigned int c = 0; c < 3; ++c)
          {
            EXPECT_NEAR(points[3 * p + c], expected[c], 1e-12);
            EXPECT_NEAR(normal[3 * p + c], c == 2 ? 1.0 : 0.0, 1e-7);
          }
      }
  EXPECT_NE(read_text(dir / "solution.pvd").find("timestep=\"0.75\""),
            std::string::npos);
}

TEST(VtuOutput, UnusableDirectoryThrowsNamingIt)
{
  const auto     model = straight_rod();
  const fs::path dir   = scratch("blocked");
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "not a directory";
  const std::string bad = (dir / "file" / "output").string();
  try
    {
      VtuOutput output(model->network(), bad);
      FAIL() << "no exception for " << bad;
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
}

/// The length of [s0, s1] within [a, b].
double
overlap(const double s0, const double s1, const double a, const double b)
{
  return std::max(0.0, std::min(s1, b) - std::max(s0, a));
}

TEST(VtuOutput, ActivationFieldsPerSegment)
{
  // A clamped rod of length 1 in 10 segments; the fields on parts of it,
  // ends inside cells: curvature (2, 0.5) on [0.25, 0.6] and the twist rate
  // 3 s ramped, the eigenstrain 0.01 on [0.1, 0.35] fixed. Each segment
  // shows the field's mean over it: the value times the part of the
  // segment within the region (a linear field: its value at the middle),
  // the ramped ones at the load factor of the file, half of them in step 1
  // of 2.
  const std::string scene =
    "subsection Geometry\n  set Segments = 10\n"
    "  set Director d1 = 0, 0, 1\nend\n"
    "subsection Material\n  subsection linear elastic\n"
    "    set Stiffness input = direct\n    set EA = 1e4\n    set EI1 = 1\n"
    "    set EI2 = 1\n    set GJ = 1\n  end\nend\n"
    "subsection Group all\n"
    "  set Natural curvature = 2, 0.5 on 0.25 to 0.6\n"
    "  set Natural twist = 3*s/L\n"
    "  set Axial eigenstrain = 0.01 on 0.1 to 0.35 fixed\nend\n"
    "subsection Supports\n  set Clamped ends = start\nend\n"
    "subsection Loads\n  set Steps = 2\nend\n"
    "subsection Output\n  set Plot = false\nend\n";
  const fs::path   dir = scratch("activation");
  const RunSummary run = rodnet::testing::run_scene_text(scene, dir.string());
  ASSERT_TRUE(run.failure.empty()) << run.failure;
  for (const unsigned int step : {1u, 2u})
    {
      const double      lambda = 0.5 * step;
      const std::string vtu =
        read_text(dir / ("solution-0000" + std::to_string(step) + ".vtu"));
      const std::vector<float> points = read_data_array(vtu, "");
      const std::vector<float> u      = read_data_array(vtu, "displacement");
      const std::vector<float> k1 =
        read_data_array(vtu, "activation_curvature_1");
      const std::vector<float> k2 =
        read_data_array(vtu, "activation_curvature_2");
      const std::vector<float> tau = read_data_array(vtu, "activation_twist");
      const std::vector<float> eps =
        read_data_array(vtu, "activation_eigenstrain");
      ASSERT_EQ(k1.size(), 20u);
      for (unsigned int cell = 0; cell < 10; ++cell)
        {
          // The segment's ends, undeformed, along x.
          const double a  = points[6 * cell] - u[6 * cell],
                       b  = points[6 * cell + 3] - u[6 * cell + 3];
          const double s0 = std::min(a, b), s1 = std::max(a, b);
          ASSERT_NEAR(s1 - s0, 0.1, 1e-6);
          const double in_curved = overlap(s0, s1, 0.25, 0.6) / 0.1;
          for (const unsigned int p : {2 * cell, 2 * cell + 1})
            {
              EXPECT_NEAR(k1[p], lambda * 2 * in_curved, 1e-5) << cell;
              EXPECT_NEAR(k2[p], lambda * 0.5 * in_curved, 1e-5) << cell;
              EXPECT_NEAR(tau[p], lambda * 3 * (s0 + s1) / 2, 1e-5) << cell;
              EXPECT_NEAR(eps[p], 0.01 * overlap(s0, s1, 0.1, 0.35) / 0.1, 1e-7)
                << cell;
            }
        }
    }
}
