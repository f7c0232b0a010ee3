// Natural shape "initial geometry": every generator's rods and networks are
// stress free where they are built, i.e. the residual at zero load and zero
// displacement vanishes to round-off, for both hinge kernels. With
// "straight" the curved ones are prestressed, with a residual of the order
// of the bending stiffness over the segment length squared, so the first
// check is not vacuous. The natural strains stay valid across reference
// resets.
#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace
{
  using namespace rodnet;

  struct GeneratorCase
  {
    std::string name;
    /// Geometry entries of the case (besides the natural shape and kernel).
    std::string geometry;
    /// Whether a rod is curved, so that "straight" prestresses it.
    bool curved;
  };

  const std::string data = RODNET_SOURCE_DIR "/tests/input/data/";

  /// d1 = e_z keeps the hint off every in-plane tangent of the rods
  /// (networks orient their beams so themselves, and refuse the entry).
  const std::string rod_director = "set Director d1 = 0, 0, 1\n";

  /// One scene per generator, each with curved hinges where it can have
  /// them.
  const std::vector<GeneratorCase> generator_cases = {
    {"straight",
     rod_director + "set Generator = straight\nset Segments = 8\n",
     false},
    {"arc",
     rod_director +
       "set Generator = arc\nset Radius = 0.7\nset End angle = 120\n"
       "set Segments = 12\n",
     true},
    {"ring",
     rod_director +
       "set Generator = ring\nset Radius = 0.7\nset Segments = 12\n",
     true},
    {"helix",
     rod_director +
       "set Generator = helix\nset Radius = 0.5\nset Rise per radian = 0.1\n"
       "set Turns = 1.5\nset Segments = 20\n",
     true},
    {"polyline",
     rod_director +
       "set Generator = polyline\nset Points = 0,0,0; 1,0,0; 1,1,0.5; 0,1,1\n"
       "set Segments = 3\n",
     true},
    {"gmsh",
     rod_director + "set Generator = gmsh\nset Mesh file = " + data +
       "kinked_rod.msh\n",
     true},
    {"frame", "set Generator = frame\nset Segments = 4\n", false},
    {"windmill", "set Generator = windmill\nset Segments = 4\n", false},
    {"square lattice",
     "set Generator = square lattice\nset Cells = 2, 2\nset Segments = 2\n",
     false},
    {"hexagonal lattice",
     "set Generator = hexagonal lattice\nset Cells = 2, 1\nset Segments = 2\n",
     false},
    {"network file",
     "set Generator = network file\nset Network file = " + data +
       "frame.net\nset Segments = 3\n",
     false},
    {"gmsh network",
     "set Generator = gmsh network\nset Mesh file = " + data +
       "bent_network.msh\n",
     true},
    {"triple ring",
     rod_director +
       "set Generator = ring\nset Radius = 0.7\nset Segments = 16\n"
       "set Turns = 3\n",
     true}};

  std::unique_ptr<RodModel>
  build(const GeneratorCase &c,
        const std::string   &kernel,
        const std::string   &natural_shape)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    std::string geometry = "subsection Geometry\n" + c.geometry +
                           "set Hinge kernel = " + kernel +
                           "\nset Natural shape = " + natural_shape + "\nend\n";
    // Anisotropic, so that swapped bending axes would show.
    prm.parse_input_from_string(geometry + "subsection Material\n"
                                           "  subsection linear elastic\n"
                                           "    set Stiffness input = direct\n"
                                           "    set EA = 1e4\n"
                                           "    set EI1 = 1\n"
                                           "    set EI2 = 2\n"
                                           "    set GJ = 0.7\n"
                                           "  end\n"
                                           "end\n");
    return Scene(prm).build_model();
  }

  /// Energy and largest residual entry at zero displacement and zero
  /// load, and the round-off scale EI / l^2 of the bending rows (l the
  /// shortest segment).
  struct AtRest
  {
    double energy, residual, scale;
  };

  AtRest
  at_rest(const RodModel &model)
  {
    const VectorType u        = model.create_vector();
    VectorType       r        = model.create_vector();
    const double     energy   = model.assemble(u, 0.0, &r, nullptr);
    double           shortest = std::numeric_limits<double>::max();
    for (const SegmentStencil &s : model.layout().segments())
      shortest = std::min(shortest, model.configuration().rest_length(s.cell));
    return {energy, r.linfty_norm(), 2.0 / (shortest * shortest)};
  }

  class ZeroLoad
      : public ::testing::TestWithParam<std::tuple<GeneratorCase, std::string>>
  {
  };

  TEST_P(ZeroLoad, InitialGeometryIsStressFree)
  {
    const auto &[c, kernel] = GetParam();
    const AtRest rest       = at_rest(*build(c, kernel, "initial geometry"));
    // Round-off of kappa - kappa_bar, ~1e-16, through EI / l^2.
    EXPECT_LE(rest.residual, 1e-12 * rest.scale) << c.name << ", " << kernel;
    // Energies are of order 1 J here (EI ~ 1 N m^2, lengths ~ 1 m).
    EXPECT_LE(rest.energy, 1e-20) << c.name << ", " << kernel;

    // A ring bent from a straight rod is prestressed but in equilibrium:
    // the energy tells.
    const AtRest prestressed = at_rest(*build(c, kernel, "straight"));
    std::cout << c.name << ", " << kernel << ": at rest, residual "
              << rest.residual << " (scale " << rest.scale << "), energy "
              << rest.energy << " J; natural shape straight: energy "
              << prestressed.energy << " J" << std::endl;
    if (c.curved)
      EXPECT_GT(prestressed.energy, 1e-2) << c.name << ", " << kernel;
    else
      {
        // Straight beams, and junctions keep their initial angles either
        // way.
        EXPECT_LE(prestressed.residual, 1e-12 * rest.scale) << c.name;
        EXPECT_LE(prestressed.energy, 1e-20) << c.name;
      }
  }

  INSTANTIATE_TEST_SUITE_P(
    EveryGenerator,
    ZeroLoad,
    ::testing::Combine(::testing::ValuesIn(generator_cases),
                       ::testing::Values("simple", "classic")),
    [](const auto &info) {
      std::string name =
        std::get<0>(info.param).name + "_" + std::get<1>(info.param);
      for (char &ch : name)
        if (ch == ' ')
          ch = '_';
      return name;
    });

  class Reset : public ::testing::TestWithParam<std::string>
  {
  };

  // The measures do not depend on the reference, so neither does the
  // energy of kappa - kappa_bar: a reset at a deformed state changes no
  // energy there, and the undeformed state stays stress free, with zero
  // energy and residual. (The residual at a state off equilibrium does
  // change: the twist DoFs are angles about the reference tangents.)
  TEST_P(Reset, NaturalStrainsSurviveAReset)
  {
    // The helix of the generator cases, free at both ends.
    ASSERT_EQ(generator_cases[3].name, "helix");
    const auto model =
      build(generator_cases[3], GetParam(), "initial geometry");
    // A deformation of every DoF, up to 0.05 (m or rad), without pattern.
    VectorType u = model->create_vector();
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = 0.05 * std::sin(1.7 * i + 0.3);
    u.compress(dealii::VectorOperation::insert);

    const double energy = model->elastic_energy(u, 0.0);
    model->reset_reference(u);
    EXPECT_NEAR(model->elastic_energy(u, 0.0), energy, 1e-12 * energy);

    // Back at the undeformed positions and twists after one reset, the
    // frames are the undeformed ones again (transported there and back).
    const VectorType zero = model->create_vector();
    VectorType       r    = model->create_vector();
    // Energy of order 1e-2 J and forces of order 1 N at u.
    EXPECT_LE(model->assemble(zero, 0, &r, nullptr), 1e-20 * energy);
    EXPECT_LE(r.linfty_norm(), 1e-10);
    ASSERT_GT(energy, 1e-3);
    std::cout << GetParam() << ": energy change under the reset "
              << std::abs(model->elastic_energy(u, 0.0) - energy) / energy
              << " relative; at rest after it, energy "
              << model->assemble(zero, 0, &r, nullptr) << " J, residual "
              << r.linfty_norm() << " N" << std::endl;
  }

  INSTANTIATE_TEST_SUITE_P(BothKernels,
                           Reset,
                           ::testing::Values("simple", "classic"));
} // namespace
