// The mass matrix against the kinetic energy of rigid motions, computed
// from the geometry alone: translations of single rods and welded networks
// (shared junction vertices counted once), rotation about the axis of a
// straight rod (twist inertia) and about a perpendicular axis (exact for
// the consistent mass, the trapezoidal rule for the lumped one; the rotary
// inertia of the sections exact for both), the rotary inertia's quadratic
// form on a welded network; the
// eigenvalues of one segment, lumping as row sums, symmetry, zero rows of
// quaternion DoFs, the constrained variant and the errors; and the spin of
// the director frames that the twist inertia approximates.
#include <core/mass_matrix.h>
#include <core/rod_model.h>
#include <geometry/network_generators.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <map>
#include <random>

namespace
{
  using namespace rodnet;

  std::shared_ptr<const RodMaterial>
  elastic()
  {
    return std::make_shared<LinearElasticRod>(RodStiffness{100, 1, 2, 1.5});
  }

  std::unique_ptr<RodModel>
  single_rod(const std::vector<Vector3> &points, const bool closed = false)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(points, closed, Vector3(0.3, 0.2, 1.0), "simple");
    network->create_triangulation();
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{elastic()});
    model->finalize();
    return model;
  }

  std::unique_ptr<RodModel>
  network_model(const RodGraph &graph, const unsigned int segments_per_beam)
  {
    BuiltNetwork built = build_rod_network(graph, segments_per_beam, "simple");
    const unsigned int n_rods = built.network->rods().size();
    auto               model  = std::make_unique<RodModel>(
      std::move(built.network),
      std::vector<std::shared_ptr<const RodMaterial>>(n_rods, elastic()));
    model->finalize();
    return model;
  }

  /// Rod r gets rho A = 1 + r and rho (I1 + I2) = 0.1 (2 + r), so that a
  /// mix-up of rods shows.
  std::vector<RodInertia>
  graded_inertia(const RodModel &model)
  {
    std::vector<RodInertia> inertia;
    for (unsigned int r = 0; r < model.network().rods().size(); ++r)
      inertia.push_back({1.0 + r, 0.1 * (2.0 + r)});
    return inertia;
  }

  /// Component (0-2) of every position DoF, the constrained copies at
  /// junctions included.
  std::map<global_dof_index, unsigned int>
  position_components(const RodModel &model)
  {
    std::map<global_dof_index, unsigned int> component;
    for (unsigned int v = 0; v < model.network().n_vertices(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        component[model.layout().vertex_dof(v, c)] = c;
    for (const auto &copy : model.layout().junction_constraints().get_lines())
      component[copy.index] = component.at(copy.entries.at(0).first);
    return component;
  }

  /// Velocity of the rigid translation @p e: every position DoF moves.
  VectorType
  translation(const RodModel &model, const Vector3 &e)
  {
    VectorType v = model.create_vector();
    for (const auto &[dof, c] : position_components(model))
      v[dof] = e[c];
    v.compress(dealii::VectorOperation::insert);
    return v;
  }

  Eigen::MatrixXd
  dense(const MatrixType &m)
  {
    Eigen::MatrixXd result(m.m(), m.n());
    for (unsigned int i = 0; i < m.m(); ++i)
      for (unsigned int j = 0; j < m.n(); ++j)
        result(i, j) = m.el(i, j);
    return result;
  }

  MatrixType
  mass_of(const RodModel                &model,
          const std::vector<RodInertia> &inertia,
          const MassKind                 kind,
          const bool                     apply_constraints = false)
  {
    MatrixType mass;
    assemble_mass_matrix(model, inertia, kind, mass, apply_constraints);
    return mass;
  }

  class MassMatrixTest : public ::testing::TestWithParam<MassKind>
  {
  };

  std::string
  kind_name(const ::testing::TestParamInfo<MassKind> &info)
  {
    return info.param == MassKind::consistent ? "consistent" : "lumped";
  }

  // 1/2 (sum_rods rho A L) |e|^2 with the lengths from the geometry: a
  // polygonal ring of n sides of radius R has length 2 n R sin(pi / n).
  TEST_P(MassMatrixTest, RigidTranslationCarriesTotalMass)
  {
    const Vector3      e(0.3, -1.2, 0.7);
    const double       La = 2.0, R = 0.4;
    const unsigned int n_ring = 9;
    struct Case
    {
      std::string               name;
      std::unique_ptr<RodModel> model;
      std::vector<double>       lengths;
    };
    std::vector<Case> cases;
    cases.push_back(
      {"straight rod",
       single_rod(
         generators::straight(Vector3(0, 0, 0), Vector3(1.5, 0, 0), 7)),
       {1.5}});
    cases.push_back({"ring",
                     single_rod(generators::ring(Vector3(1, 2, 3),
                                                 R,
                                                 Vector3::UnitX(),
                                                 Vector3::UnitY(),
                                                 n_ring),
                                true),
                     {2 * n_ring * R * std::sin(M_PI / n_ring)}});
    cases.push_back(
      {"right-angle frame",
       network_model(network_generators::right_angle_frame(1.5), 4),
       {1.5, 1.5}});
    cases.push_back({"windmill",
                     network_model(network_generators::windmill(La), 3),
                     {La, La / 2, La / 2, La / 2}});
    for (const Case &c : cases)
      {
        const std::vector<RodInertia> inertia = graded_inertia(*c.model);
        double                        total   = 0;
        for (unsigned int r = 0; r < c.lengths.size(); ++r)
          total += inertia[r].mass_per_length * c.lengths[r];
        const MatrixType mass  = mass_of(*c.model, inertia, GetParam());
        const double     T     = kinetic_energy(mass, translation(*c.model, e));
        const double     exact = 0.5 * total * e.squaredNorm();
        std::cout << c.name << ": kinetic energy " << T << ", exact " << exact
                  << std::endl;
        EXPECT_NEAR(T, exact, 1e-13 * exact) << c.name;
      }
  }

  // Turning a straight rod about its own axis moves no vertex and turns
  // every cross-section at the rate omega: T = 1/2 rho (I1 + I2) L omega^2.
  TEST_P(MassMatrixTest, RotationAboutAxisCarriesPolarInertia)
  {
    const double L = 1.3, omega = 2.5;
    const auto   model =
      single_rod(generators::straight(Vector3(0.1, 0.2, 0.3),
                                      Vector3(0.1, 0.2, 0.3) +
                                        L * Vector3(1, 2, 2).normalized(),
                                      8));
    const std::vector<RodInertia> inertia = {{3.0, 0.02}};
    VectorType                    v       = model->create_vector();
    for (const SegmentStencil &s : model->layout().segments())
      v[model->layout().twist_dof(s.cell)] = omega;
    v.compress(dealii::VectorOperation::insert);
    const double T = kinetic_energy(mass_of(*model, inertia, GetParam()), v);
    const double exact = 0.5 * 0.02 * L * omega * omega;
    EXPECT_NEAR(T, exact, 1e-14 * exact);
  }

  // Turning a straight rod of length L about a perpendicular axis through
  // its midpoint at the rate Omega: the continuum gives
  // T = 1/2 (rho A L^3 / 12 + rho I_b L) Omega^2, the sections turning at
  // Omega about a bending axis. The consistent mass (linear shape
  // functions, exact for the linear velocity field) reproduces it; the
  // lumped mass integrates r^2 by the trapezoidal rule, whose error for
  // segments of length h is L h^2 / 6. The rotary part is exact for both.
  // The twist rate is zero (the rotation axis is normal to the tangent).
  TEST_P(MassMatrixTest, RotationAboutPerpendicularAxis)
  {
    const double       L = 2.0, Omega = 0.7, rhoA = 1.7, rhoIb = 0.09;
    const unsigned int n     = 5;
    const double       h     = L / n;
    const auto         model = single_rod(
      generators::straight(Vector3(-L / 2, 0, 0), Vector3(L / 2, 0, 0), n));
    VectorType v = model->create_vector();
    for (unsigned int i = 0; i < model->network().n_vertices(); ++i)
      {
        const Vector3 velocity =
          Omega * Vector3::UnitZ().cross(model->network().vertex(i));
        for (unsigned int c = 0; c < 3; ++c)
          v[model->layout().vertex_dof(i, c)] = velocity[c];
      }
    v.compress(dealii::VectorOperation::insert);
    const double T =
      kinetic_energy(mass_of(*model, {{rhoA, 5.0, rhoIb}}, GetParam()), v);
    const double second_moment = GetParam() == MassKind::consistent ?
                                   L * L * L / 12 :
                                   L * L * L / 12 + L * h * h / 6;
    const double exact =
      0.5 * (rhoA * second_moment + rhoIb * L) * Omega * Omega;
    std::cout << "kinetic energy " << T << ", exact " << exact
              << ", of which rotary " << 0.5 * rhoIb * L * Omega * Omega
              << std::endl;
    EXPECT_NEAR(T, exact, 1e-13 * exact);
  }

  // The rotary inertia on the windmill (four rods welded at the hub): for a
  // random velocity of the vertices, what it adds to 1/2 v^T M v is the sum
  // over segments of rho I_b / (2 l0) |v_b - v_a|^2, l0 from the vertices'
  // positions, the hub's segments counted on its one vertex; the same for
  // both kinds.
  TEST_P(MassMatrixTest, RotaryInertiaIsChordRateQuadraticForm)
  {
    const auto model = network_model(network_generators::windmill(2.0), 3);
    std::vector<RodInertia> with_rotary = graded_inertia(*model);
    for (unsigned int r = 0; r < with_rotary.size(); ++r)
      with_rotary[r].rotary_inertia_per_length = 0.05 * (1.0 + r);
    std::mt19937                           random(5);
    std::uniform_real_distribution<double> uniform(-1, 1);
    const RodNetwork                      &network = model->network();
    VectorType                             v       = model->create_vector();
    for (unsigned int i = 0; i < network.n_vertices(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        v[model->layout().vertex_dof(i, c)] = uniform(random);
    v.compress(dealii::VectorOperation::insert);
    // The rod ends at the hub move with it.
    model->layout().junction_constraints().distribute(v);
    std::vector<Vector3> velocity(network.n_vertices());
    for (unsigned int i = 0; i < network.n_vertices(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        velocity[i][c] = v[model->layout().vertex_dof(i, c)];

    double exact = 0;
    for (const SegmentStencil &s : model->layout().segments())
      {
        const unsigned int a = s.vertices[0], b = s.vertices[1];
        const double       l0 = (network.vertex(b) - network.vertex(a)).norm();
        const double rho_Ib   = with_rotary[s.rod].rotary_inertia_per_length;
        exact += rho_Ib / (2 * l0) * (velocity[b] - velocity[a]).squaredNorm();
      }
    const double rotary =
      kinetic_energy(mass_of(*model, with_rotary, GetParam()), v) -
      kinetic_energy(mass_of(*model, graded_inertia(*model), GetParam()), v);
    std::cout << "rotary kinetic energy " << rotary << ", exact " << exact
              << std::endl;
    EXPECT_NEAR(rotary, exact, 1e-12 * exact);
  }

  INSTANTIATE_TEST_SUITE_P(Kinds,
                           MassMatrixTest,
                           ::testing::Values(MassKind::consistent,
                                             MassKind::lumped),
                           kind_name);

  // One segment: three decoupled copies of rho A l0 / 6 [[2, 1], [1, 2]]
  // (eigenvalues rho A l0 / 6 and rho A l0 / 2) for the consistent mass,
  // rho A l0 / 2 six times for the lumped one, and rho (I1 + I2) l0. The
  // rotary inertia adds 2 rho I_b / l0 to the relative motion of the ends.
  TEST(MassMatrix, OneSegmentEigenvalues)
  {
    const double l0 = 0.8, rhoA = 2.5, rhoJ = 0.3, rhoIb = 0.04;
    const double relative = 2 * rhoIb / l0;
    const auto   model    = single_rod(
      {Vector3(0.1, 0.2, 0.3),
            Vector3(0.1, 0.2, 0.3) + l0 * Vector3(2, -1, 2).normalized()});
    ASSERT_EQ(model->layout().n_dofs(), 7u);
    for (const MassKind kind : {MassKind::consistent, MassKind::lumped})
      {
        const Eigen::MatrixXd m =
          dense(mass_of(*model, {{rhoA, rhoJ, rhoIb}}, kind));
        const double ends =
          kind == MassKind::consistent ? rhoA * l0 / 6 : rhoA * l0 / 2;
        Eigen::VectorXd expected(7);
        expected << ends + relative, ends + relative, ends + relative,
          rhoA * l0 / 2, rhoA * l0 / 2, rhoA * l0 / 2, rhoJ * l0;
        std::sort(expected.data(), expected.data() + expected.size());
        const Eigen::VectorXd eigenvalues =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues();
        EXPECT_LT((eigenvalues - expected).norm(), 1e-14);
      }
  }

  // On the windmill (four rods welded at the hub, one clamped junction):
  // both matrices symmetric, the lumped one diagonal with the row sums of
  // the consistent one, and zero rows for quaternion DoFs and the unused
  // position DoFs of rod ends at the hub.
  TEST(MassMatrix, LumpedIsRowSumOfConsistentAndMasslessDofsHaveZeroRows)
  {
    const auto model = network_model(network_generators::windmill(2.0), 3);
    const std::vector<RodInertia> inertia = graded_inertia(*model);
    const Eigen::MatrixXd         consistent =
      dense(mass_of(*model, inertia, MassKind::consistent));
    const Eigen::MatrixXd lumped =
      dense(mass_of(*model, inertia, MassKind::lumped));
    const double scale = consistent.cwiseAbs().maxCoeff();

    EXPECT_EQ((consistent - consistent.transpose()).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((lumped - lumped.transpose()).cwiseAbs().maxCoeff(), 0.0);
    const Eigen::MatrixXd lumped_diagonal = lumped.diagonal().asDiagonal();
    EXPECT_EQ((lumped - lumped_diagonal).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(
      (consistent.rowwise().sum() - lumped.diagonal()).cwiseAbs().maxCoeff(),
      1e-15 * scale);
    EXPECT_NEAR(consistent.sum(), lumped.sum(), 1e-14 * consistent.sum());

    std::vector<global_dof_index> massless;
    for (unsigned int j = 0; j < model->network().junctions().size(); ++j)
      if (model->layout().has_rotation_dofs(j))
        for (unsigned int c = 0; c < 4; ++c)
          massless.push_back(model->layout().rotation_dof(j, c));
    ASSERT_EQ(massless.size(), 8u);
    for (const auto &copy : model->layout().junction_constraints().get_lines())
      massless.push_back(copy.index);
    ASSERT_EQ(massless.size(), 8u + 9u); // three rod ends share the hub's
    for (const global_dof_index i : massless)
      {
        EXPECT_EQ(consistent.row(i).cwiseAbs().maxCoeff(), 0.0) << "DoF " << i;
        EXPECT_EQ(lumped.row(i).cwiseAbs().maxCoeff(), 0.0) << "DoF " << i;
      }
    // Every other DoF (positions in use, twists) carries inertia.
    unsigned int n_massive = 0;
    for (unsigned int i = 0; i < consistent.rows(); ++i)
      n_massive += consistent(i, i) > 0;
    EXPECT_EQ(n_massive, model->layout().n_dofs() - massless.size());
  }

  // With the model's constraints, rows and columns of fixed DoFs are zero
  // (diagonal included) and the rest is the unconstrained matrix; added to
  // the constrained tangent it leaves the tangent's fixed rows alone.
  TEST(MassMatrix, ConstrainedMassZeroesFixedRowsAndColumns)
  {
    const auto model =
      network_model(network_generators::right_angle_frame(1.5), 4);
    const std::vector<RodInertia> inertia = graded_inertia(*model);
    const MatrixType free_mass = mass_of(*model, inertia, MassKind::consistent);
    const MatrixType fixed_mass =
      mass_of(*model, inertia, MassKind::consistent, true);
    const Eigen::MatrixXd free = dense(free_mass), fixed = dense(fixed_mass);
    const auto           &constraints = model->constraints();
    unsigned int          n_fixed     = 0;
    for (unsigned int i = 0; i < free.rows(); ++i)
      for (unsigned int j = 0; j < free.cols(); ++j)
        {
          const bool is_fixed =
            constraints.is_constrained(i) || constraints.is_constrained(j);
          EXPECT_EQ(fixed(i, j), is_fixed ? 0.0 : free(i, j)) << i << ", " << j;
          n_fixed += i == j && constraints.is_constrained(i);
        }
    // The clamp's position and rotation, the gauge of the corner's
    // quaternion, the unused copy of the corner vertex.
    EXPECT_EQ(n_fixed, 3u + 4u + 1u + 3u);
    const global_dof_index clamp_x =
      model->layout().vertex_dof(model->network().junctions()[0].vertex, 0);
    EXPECT_GT(free(clamp_x, clamp_x), 0.0);

    MatrixType tangent;
    model->initialize_matrix(tangent);
    model->assemble(model->create_vector(), 0.0, nullptr, &tangent, true);
    const double fixed_diagonal = tangent.el(clamp_x, clamp_x);
    tangent.add(1e3, fixed_mass);
    EXPECT_EQ(tangent.el(clamp_x, clamp_x), fixed_diagonal);
  }

  // The approximation of the twist inertia (doc/theory.md): the spin of
  // the director frame about the tangent, from central differences of the
  // frames, is the twist rate at the reference and the twist rate minus
  // the transport term (T x t) . tdot / (1 + T . t) away from it.
  TEST(MassMatrix, FrameSpinAboutTangent)
  {
    const auto   model = single_rod(generators::helix(0.5, 0.1, 0.5, 12));
    std::mt19937 random(3);
    std::uniform_real_distribution<double> small(-0.05, 0.05);
    const auto random_vector = [&](const double scale) {
      VectorType x = model->create_vector();
      for (unsigned int i = 0; i < x.size(); ++i)
        x[i] = scale * small(random);
      x.compress(dealii::VectorOperation::insert);
      return x;
    };
    VectorType reference = random_vector(1);
    model->reset_reference(reference);
    const VectorType     v    = random_vector(20);
    const Configuration &conf = model->configuration();
    const double         h    = 1e-6;

    const auto tangent = [&](const VectorType &u, const SegmentStencil &s) {
      return (conf.position(u, s.vertices[1]) - conf.position(u, s.vertices[0]))
        .normalized();
    };
    for (const double distance : {0.0, 1.0})
      {
        VectorType u = reference;
        u.add(1.0, random_vector(distance));
        VectorType plus = u, minus = u;
        plus.add(h, v);
        minus.add(-h, v);
        double error = 0, transport = 0;
        for (const SegmentStencil &s : model->layout().segments())
          {
            const Vector3 T =
              conf.director_frame(reference, s.cell) * Vector3::UnitZ();
            const Vector3 t = tangent(u, s);
            const Vector3 tdot =
              (tangent(plus, s) - tangent(minus, s)) / (2 * h);
            const Quaternion q = conf.director_frame(u, s.cell);
            const Quaternion qdot(
              (conf.director_frame(plus, s.cell).coeffs() -
               conf.director_frame(minus, s.cell).coeffs()) /
              (2 * h));
            // Spatial angular velocity of a frame q: 2 Im(qdot conj(q)).
            const Vector3 omega  = 2 * (qdot * q.conjugate()).vec();
            const double  phidot = v[model->layout().twist_dof(s.cell)];
            const double  term   = T.cross(t).dot(tdot) / (1 + T.dot(t));
            error = std::max(error, std::abs(omega.dot(t) - (phidot - term)));
            transport = std::max(transport, std::abs(term));
          }
        std::cout << "distance " << distance << ": transport term up to "
                  << transport << ", spin error " << error << std::endl;
        EXPECT_LT(error, 1e-7);
        if (distance == 0)
          EXPECT_LT(transport, 1e-12);
        else
          EXPECT_GT(transport, 1e-3);
      }
  }

  // copy_nonzeros keeps the entries that are not zero and the diagonal,
  // nothing else, and its products are those of the full matrix to the
  // bit (the consistent mass with rotary inertia, on the windmill).
  TEST(MassMatrix, CopyOfNonzerosHasTheirEntriesAndTheSameProducts)
  {
    const auto model = network_model(network_generators::windmill(2.0), 3);
    std::vector<RodInertia> inertia = graded_inertia(*model);
    for (RodInertia &rod : inertia)
      rod.rotary_inertia_per_length = 0.03;
    const MatrixType full = mass_of(*model, inertia, MassKind::consistent);
    MatrixType       copy;
    copy_nonzeros(full, copy);
    const Eigen::MatrixXd m       = dense(full);
    std::size_t           entries = 0;
    for (unsigned int i = 0; i < m.rows(); ++i)
      for (unsigned int j = 0; j < m.cols(); ++j)
        entries += m(i, j) != 0 || i == j;
    EXPECT_EQ(copy.n_nonzero_elements(), entries);
    EXPECT_LT(copy.n_nonzero_elements(), full.n_nonzero_elements() / 2);
    EXPECT_EQ((dense(copy) - m).cwiseAbs().maxCoeff(), 0.0);

    std::mt19937                           random(7);
    std::uniform_real_distribution<double> value(-1, 1);
    VectorType x = model->create_vector(), y = x, z = x;
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = value(random);
    x.compress(dealii::VectorOperation::insert);
    full.vmult(y, x);
    copy.vmult(z, x);
    for (unsigned int i = 0; i < x.size(); ++i)
      EXPECT_EQ(y[i], z[i]) << "row " << i;
  }

  TEST(MassMatrix, InertiaOfCircularSection)
  {
    const double     r = 0.01, rho = 7800;
    const RodInertia inertia = rod_inertia(circle_section(r), rho);
    EXPECT_NEAR(inertia.mass_per_length, rho * M_PI * r * r, 1e-15);
    EXPECT_NEAR(inertia.rotational_inertia_per_length,
                rho * M_PI * std::pow(r, 4) / 2,
                1e-18);
    // rho I of a circle about a diameter.
    EXPECT_NEAR(inertia.rotary_inertia_per_length,
                rho * M_PI * std::pow(r, 4) / 4,
                1e-18);
  }

  /// Runs @p f and returns the message of the @p Exception it throws
  /// (fails the test where it throws none).
  template <typename Exception, typename F>
  std::string
  message_of(F &&f)
  {
    try
      {
        f();
      }
    catch (const Exception &e)
      {
        return e.what();
      }
    ADD_FAILURE() << "nothing thrown";
    return "";
  }

  TEST(MassMatrix, BadInputIsRefusedNamingTheRod)
  {
    const auto model =
      network_model(network_generators::right_angle_frame(1.5), 2);
    MatrixType mass;
    const auto assemble = [&](const std::vector<RodInertia> &inertia) {
      return message_of<std::invalid_argument>(
        [&] { assemble_mass_matrix(*model, inertia, MassKind::lumped, mass); });
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const auto &[inertia, expected] :
         std::vector<std::pair<std::vector<RodInertia>, std::string>>{
           {{{1, 1}, {-1, 1}}, "rod 1 has mass per length"},
           {{{1, 1}, {1, nan}}, "rod 1 has rotational inertia per length"},
           {{{inf, 1}, {1, 1}}, "rod 0 has mass per length"},
           {{{1, -0.5}, {1, 1}}, "rod 0 has rotational inertia per length"},
           {{{1, 1}, {1, 1, -2}}, "rod 1 has rotary inertia per length"},
           {{{1, 1, nan}, {1, 1}}, "rod 0 has rotary inertia per length"},
           {{{1, 1}}, "no inertia for rod 1"},
           {{{1, 1}, {1, 1}, {1, 1}},
            "inertia given for rod 2, which does not exist"}})
      {
        const std::string message = assemble(inertia);
        std::cout << message << std::endl;
        EXPECT_NE(message.find(expected), std::string::npos) << message;
      }
    EXPECT_NE(message_of<std::invalid_argument>([] {
                rod_inertia(circle_section(0.1), -1);
              }).find("density"),
              std::string::npos);
    EXPECT_THROW(rod_inertia(circle_section(0.1), nan), std::invalid_argument);

    assemble_mass_matrix(*model, {{1, 1}, {1, 1}}, MassKind::lumped, mass);
    EXPECT_THROW(
      kinetic_energy(
        mass,
        single_rod(generators::straight(Vector3(0, 0, 0), Vector3(1, 0, 0), 2))
          ->create_vector()),
      std::invalid_argument);

    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          3),
                     false,
                     Vector3::UnitY(),
                     "simple");
    const RodModel unfinished(std::move(network), {elastic()});
    EXPECT_NE(
      message_of<std::logic_error>([&] {
        assemble_mass_matrix(unfinished, {{1, 1}}, MassKind::lumped, mass);
      }).find("finalize"),
      std::string::npos);
  }
} // namespace
