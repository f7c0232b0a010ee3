// RigidMotionSplit (solvers/time/rigid_motion_split.h): the force w it leaves of
// M d has no resultant and no moment on a free part (sums formed here from
// the positions and tangents), w.d is the M-norm of what is left of d, and
// a rigid step leaves nothing, also where a rotation is no motion of the
// part (a straight rod about its line) and its column is rounding.
#include <core/mass_matrix.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/time/rigid_motion_split.h>

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <tests/common/free_frame.h>
#include <tests/common/rod_models.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

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
    // The free frame's loads are no part of M or of the split.
    auto       model = free_frame(6).model;
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
    const std::unique_ptr<RodModel> free_rod =
      elastic_model(straight_network(8), frame_stiffness);
    RodModel &model = *free_rod;
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
