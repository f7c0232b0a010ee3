// RigidMotionSplit (solvers/rigid_motion_split.h): the force w it leaves of
// M d has no resultant and no moment on a free part (sums formed here from
// the positions and tangents), w.d is the M-norm of what is left of d, and
// a rigid step leaves nothing, also where a rotation is no motion of the
// part (a straight rod about its line) and its column is rounding.
#include <core/mass_matrix.h>
#include <core/network_generators.h>
#include <core/rod_generators.h>
#include <core/rod_graph.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/dof_roles.h>
#include <solvers/rigid_motion_split.h>

#include <cmath>
#include <gtest/gtest.h>
#include <memory>

namespace
{
  using namespace rodnet;

  const RodStiffness stiffness{1e6, 1e3, 1e3, 1e3};

  /// The right-angle frame of leg 10 without its clamp, 6 segments a leg.
  std::unique_ptr<RodModel>
  free_frame()
  {
    RodGraph graph = network_generators::right_angle_frame(10);
    graph.nodes[graph.node_index("clamp")].kind.reset();
    BuiltNetwork built = build_rod_network(graph, 6, "simple");
    auto         model = std::make_unique<RodModel>(
      std::move(built.network),
      std::vector<std::shared_ptr<const RodMaterial>>(
        2,
        std::make_shared<LinearElasticRod>(stiffness)));
    model->finalize();
    return model;
  }

  /// Resultant, moment of the positions' rows about the origin and moment
  /// of the twist rows (along the segments' tangents) of @p f at @p x.
  std::array<Vector3, 3>
  sums(const RodModel &model, const VectorType &x, const VectorType &f)
  {
    const DofRoles         roles(model);
    std::array<Vector3, 3> s = {Vector3::Zero(),
                                Vector3::Zero(),
                                Vector3::Zero()};
    for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
      if (roles.kind(d) == DofRoles::Kind::position)
        {
          const Vector3 e = Vector3::Unit(roles.component(d));
          s[0] += f[d] * e;
          s[1] += model.position(x, roles.owner(d)).cross(f[d] * e);
        }
      else if (roles.kind(d) == DofRoles::Kind::twist)
        {
          const auto [r, k] = roles.cell_place(roles.owner(d));
          const auto &chain = model.network().rods()[r].vertices;
          s[2] += f[d] * (model.position(x, chain[k + 1]) -
                          model.position(x, chain[k]))
                           .normalized();
        }
    return s;
  }

  TEST(RigidMotionSplit, NoResultantNoMomentOnAFreeFrame)
  {
    auto       model = free_frame();
    MatrixType mass;
    assemble_mass_matrix(*model,
                         {{1, 0.5}, {2, 0.3}},
                         MassKind::consistent,
                         mass);
    RigidMotionSplit split(*model, mass);
    ASSERT_TRUE(split.has_free_parts());
    // A deformed configuration x and a step d, both out of plane.
    VectorType x = model->create_vector(), d = model->create_vector();
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        x[i] = 0.3 * std::sin(1.7 * i);
        d[i] = 0.01 * std::cos(2.3 * i + 0.4);
      }
    model->constraints().distribute(x);
    model->constraints().set_zero(d);
    VectorType md = model->create_vector(), w = model->create_vector();
    mass.vmult(md, d);
    w = md;
    split.remove_rigid_part(x, w);
    const std::array<Vector3, 3> before = sums(*model, x, md),
                                 after  = sums(*model, x, w);
    for (unsigned int k = 0; k < 3; ++k)
      EXPECT_LT(after[k].norm(), 1e-14 * before[0].norm() * 10) << k;
    // w = M d_def, d_def = d - R alpha M-orthogonal to R: 0 < w.d <= d.Md.
    EXPECT_GT(w * d, 0);
    EXPECT_LT(w * d, md * d);
  }

  TEST(RigidMotionSplit, ARigidStepLeavesNothing)
  {
    // A straight free rod: no rotation about its line (the column is
    // rounding, 1e-36), which must not remove part of a translation.
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          8),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(stiffness)});
    model.finalize();
    MatrixType mass;
    assemble_mass_matrix(model, {{1, 2e-3}}, MassKind::consistent, mass);
    RigidMotionSplit split(model, mass);
    VectorType       x = model.create_vector(), d = model.create_vector();
    // Stretched along its line (and off it by rounding), translated by t and
    // turned by w about z (infinitesimally: x_i moves by w x x_i, no twist
    // change as the tangent stays in the plane normal to w).
    const Vector3 t(0.3, -0.4, 1.2), w(0, 0, 0.05);
    for (const unsigned int i : model.network().rods()[0].vertices)
      {
        const Vector3 p = model.position(x, i);
        for (unsigned int c = 0; c < 3; ++c)
          {
            // Off the line by rounding, as states of a run are.
            x[model.layout().vertex_dof(i, c)] =
              c == 0 ? 1e-3 * p[0] : 1e-17 * std::sin(3.0 * i + c);
            d[model.layout().vertex_dof(i, c)] = (t + w.cross(1.001 * p))[c];
          }
      }
    VectorType md = model.create_vector();
    mass.vmult(md, d);
    VectorType rest = md;
    split.remove_rigid_part(x, rest);
    EXPECT_LT(rest.l2_norm(), 1e-14 * md.l2_norm());
  }
} // namespace
