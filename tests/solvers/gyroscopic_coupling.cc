// GyroscopicCoupling (solvers/time/gyroscopic_coupling.h): the force of the
// sections' spin on the centreline over a midpoint step has no resultant
// and does no work; when the segments keep their lengths its moment is
// minus the turn of the spin, sum_k pbar_k (t_k - t_k,n) / h, formed here
// from the tangents and the twist rows of M; and its Jacobian is that of
// central differences of the force.
#include <core/mass_matrix.h>
#include <core/rod_model.h>
#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/time/gyroscopic_coupling.h>

#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>

namespace
{
  using namespace rodnet;

  /// The right-angle frame of leg 10 without its clamp, 4 segments a leg,
  /// and its mass matrix (rho A = 1, rho J = 20, rho I_b = 10).
  struct SpinningFrame
  {
    std::unique_ptr<RodModel> model;
    MatrixType                mass;
  };

  SpinningFrame
  spinning_frame()
  {
    RodGraph graph = network_generators::right_angle_frame(10);
    graph.nodes[graph.node_index("clamp")].kind.reset();
    BuiltNetwork  built = build_rod_network(graph, 4, "simple");
    SpinningFrame frame;
    frame.model = std::make_unique<RodModel>(
      std::move(built.network),
      std::vector<std::shared_ptr<const RodMaterial>>(
        2,
        std::make_shared<LinearElasticRod>(RodStiffness{1e6, 1e3, 1e3, 1e3})));
    frame.model->finalize();
    assemble_mass_matrix(*frame.model,
                         std::vector<RodInertia>(2, {1, 20, 10}),
                         MassKind::consistent,
                         frame.mass);
    return frame;
  }

  /// A step of every DoF: u_n, then y = u_n + a smooth field of size
  /// @p size.
  void
  random_step(const RodModel &model,
              VectorType     &u_n,
              VectorType     &y,
              const double    size)
  {
    for (unsigned int i = 0; i < u_n.size(); ++i)
      {
        u_n[i] = 0.3 * std::sin(1.7 * i);
        y[i]   = u_n[i] + size * std::cos(2.3 * i + 0.4);
      }
    model.constraints().distribute(u_n);
    model.constraints().distribute(y);
  }

  TEST(GyroscopicCoupling, NoResultantNoWorkMomentTurnsTheSpin)
  {
    SpinningFrame      frame = spinning_frame();
    const RodModel    &model = *frame.model;
    GyroscopicCoupling coupling(model, frame.mass);
    const DofRoles     roles(model);
    const double       h = 0.01;
    // A finite rotation of the undeformed frame (every segment keeps its
    // length) about its first vertex, with twist steps of every segment.
    VectorType u_n = model.create_vector(), y = model.create_vector(),
               f = model.create_vector();
    const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.3, Vector3(1, 2, -0.5).normalized()).matrix();
    for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
      if (roles.kind(d) == DofRoles::Kind::twist)
        y[d] = 0.05 * std::cos(3.1 * d);
    for (unsigned int i = 0; i < model.network().n_vertices(); ++i)
      {
        const Vector3 x     = model.position(u_n, i);
        const Vector3 moved = turn * (x - model.position(u_n, 0));
        for (unsigned int c = 0; c < 3; ++c)
          y[model.layout().vertex_dof(i, c)] =
            moved[c] + model.position(u_n, 0)[c] - x[c];
      }
    model.constraints().distribute(y);
    coupling.add_force(u_n, y, h, f);

    // Resultant, work, moment at the midpoint positions (the midpoint
    // rule's balance of angular momentum), against the turn of the spin.
    Vector3 resultant = Vector3::Zero(), moment = Vector3::Zero(),
            turned = Vector3::Zero();
    double work = 0, scale = 0;
    for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
      if (roles.kind(d) == DofRoles::Kind::position)
        {
          const unsigned int v = roles.owner(d);
          if (model.layout().vertex_dof(v, roles.component(d)) != d)
            continue;
          const Vector3 e = Vector3::Unit(roles.component(d));
          const Vector3 m = (model.position(u_n, v) + model.position(y, v)) / 2;
          resultant += f[d] * e;
          moment -= m.cross(f[d] * e);
          work += f[d] * (y[d] - u_n[d]);
          scale += std::abs(f[d] * (y[d] - u_n[d]));
        }
      else if (roles.kind(d) == DofRoles::Kind::twist)
        {
          const auto [r, k]   = roles.cell_place(roles.owner(d));
          const auto &chain   = model.network().rods()[r].vertices;
          const auto  tangent = [&](const VectorType &x) {
            return Vector3(
              (model.position(x, chain[k + 1]) - model.position(x, chain[k]))
                .normalized());
          };
          const double pbar = frame.mass.el(d, d) * (y[d] - u_n[d]) / h;
          turned += pbar * (tangent(y) - tangent(u_n)) / h;
        }
    std::cout << "turn of the spin " << turned.norm() << ", resultant "
              << resultant.norm() << ", work " << work << " of " << scale
              << ", moment's error " << (moment + turned).norm() << std::endl;
    ASSERT_GT(turned.norm(), 1e3);
    EXPECT_LT(resultant.norm(), 1e-12 * turned.norm());
    EXPECT_LT(std::abs(work), 1e-13 * scale);
    EXPECT_LT((moment + turned).norm(), 1e-12 * turned.norm())
      << moment.transpose() << " against " << -turned.transpose();
  }

  TEST(GyroscopicCoupling, JacobianMatchesCentralDifferences)
  {
    SpinningFrame      frame = spinning_frame();
    const RodModel    &model = *frame.model;
    GyroscopicCoupling coupling(model, frame.mass);
    const double       h   = 0.01;
    VectorType         u_n = model.create_vector(), y = model.create_vector();
    random_step(model, u_n, y, 0.05);
    MatrixType k;
    model.initialize_matrix(k);
    coupling.add_jacobian(u_n, y, h, k);

    const auto force = [&](const VectorType &at) {
      VectorType f = model.create_vector();
      coupling.add_force(u_n, at, h, f);
      return f;
    };
    // Columns of free DoFs: a junction end's copies follow its vertex.
    double       largest = 0, error = 0;
    const double step = 1e-6;
    for (global_dof_index j = 0; j < y.size(); ++j)
      {
        if (model.constraints().is_constrained(j))
          continue;
        VectorType plus = y, minus = y;
        plus[j] += step;
        minus[j] -= step;
        model.constraints().distribute(plus);
        model.constraints().distribute(minus);
        VectorType difference = force(plus);
        difference -= force(minus);
        difference /= 2 * step;
        for (global_dof_index i = 0; i < y.size(); ++i)
          if (!model.constraints().is_constrained(i))
            {
              largest = std::max(largest, std::abs(difference[i]));
              error   = std::max(error, std::abs(difference[i] - k.el(i, j)));
            }
      }
    std::cout << "Jacobian: largest entry " << largest
              << ", largest difference to central differences " << error
              << std::endl;
    ASSERT_GT(largest, 1);
    EXPECT_LT(error, 1e-7 * largest) << "largest entry " << largest;
  }
} // namespace
