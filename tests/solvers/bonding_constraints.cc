// Bonding constraints solved (families/bonding_constraint.h), each against
// a run that reaches the same state by another mechanism:
// - a cantilever whose tip is bonded to its own undeformed point is the
//   propped cantilever that a pin support makes: the same deflections and
//   the bond's force equal to the pin's reaction, under a load that bends
//   it far from linear;
// - a tip bonded to a point a gap away is pulled there over the load steps,
//   as a support that moves the tip by the gap: the same states, the bond's
//   force the support's reaction;
// - two mirror-image cantilevers tip to tip, bonded, under a small load P at
//   the joint: each carries P / 2 (the reference: a single cantilever under
//   P / 2), and the bond holds the loaded tip up by P / 2;
// - bonds hold like supports in the free-motion check: three bonds at
//   points not on a line hold a free rod, two leave the rotation about
//   the line through them, and two free rods bonded to each other move
//   together (one part), not each held by the other.
#include <common/solve_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/checks/free_motions.h>

#include <algorithm>
#include <families/bonding_constraint.h>
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  const double       EI = 1, EA = 1e4, GJ = 0.8, L = 1;
  const unsigned int n = 20;

  /// Cantilevers from each start in @p starts to the matching end, clamped
  /// at their starts.
  std::unique_ptr<RodModel>
  cantilevers(const std::vector<std::pair<Vector3, Vector3>> &spans)
  {
    auto network = std::make_unique<RodNetwork>();
    for (const auto &[start, end] : spans)
      network->add_rod(generators::straight(start, end, n),
                       false,
                       Vector3::UnitZ(),
                       "simple");
    network->create_triangulation();
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>(
        spans.size(),
        std::make_shared<LinearElasticRod>(RodStiffness{EA, EI, EI, GJ})));
    for (unsigned int r = 0; r < spans.size(); ++r)
      model->clamp_end("clamp " + std::to_string(r), r, true);
    return model;
  }

  /// Vertex @p k of rod @p r of @p model.
  unsigned int
  vertex(const RodModel &model, const unsigned int r, const unsigned int k)
  {
    return model.network().rods()[r].vertices[k];
  }

  /// The displacement of vertex @p v at @p u.
  Vector3
  displacement(const RodModel &model, const VectorType &u, const unsigned v)
  {
    Vector3 d;
    for (unsigned int c = 0; c < 3; ++c)
      d[c] = u[model.layout().vertex_dof(v, c)];
    return d;
  }

  /// The vertex field "bond_force" at vertex @p v.
  Vector3
  bond_force(const RodModel &model, const VectorType &u, const unsigned v)
  {
    const OutputFields out = model.output_fields(u);
    const auto         field =
      std::find_if(out.vertex_fields.begin(),
                   out.vertex_fields.end(),
                   [](const auto &f) { return f.name == "bond_force"; });
    EXPECT_NE(field, out.vertex_fields.end());
    return Vector3(field->values[3 * v],
                   field->values[3 * v + 1],
                   field->values[3 * v + 2]);
  }

  /// Largest difference of the vertex displacements of @p a and @p b.
  double
  largest_difference(const RodModel   &a,
                     const VectorType &u_a,
                     const RodModel   &b,
                     const VectorType &u_b)
  {
    double largest = 0;
    for (unsigned int v = 0; v < a.network().n_vertices(); ++v)
      largest =
        std::max(largest,
                 (displacement(a, u_a, v) - displacement(b, u_b, v)).norm());
    return largest;
  }

  /// Solves a cantilever along x with @p load at its middle and its tip
  /// bonded to @p point, or else held by a support that moves it there.
  std::pair<std::unique_ptr<RodModel>, VectorType>
  held_tip(const bool bonded, const Vector3 &point, const Vector3 &load)
  {
    auto model             = cantilevers({{Vector3::Zero(), Vector3(L, 0, 0)}});
    const unsigned int tip = vertex(*model, 0, n);
    if (bonded)
      model->add_element_family(std::make_unique<BondingConstraintFamily>(
        *model,
        std::vector<Bond>{{tip, {}, point, "tip"}}));
    else
      model->fix_components("pin",
                            tip,
                            {{true, true, true}},
                            point - Vector3(L, 0, 0));
    model->add_point_force(vertex(*model, 0, n / 2), load);
    VectorType u = solve(*model, 10);
    return {std::move(model), std::move(u)};
  }

  // P L^2 / EI = 20: the midpoint deflects by 0.05 L and the pin pulls
  // the rod by 59 N, three times the load: far from linear.
  TEST(BondingConstraints, BondToItsOwnPointIsAPin)
  {
    const Vector3 load(0, 0, -20 * EI / (L * L));
    const Vector3 point(L, 0, 0);
    const auto [bonded, u_bonded] = held_tip(true, point, load);
    const auto [pinned, u_pinned] = held_tip(false, point, load);
    const unsigned int tip        = vertex(*bonded, 0, n);
    const Vector3      force      = bond_force(*bonded, u_bonded, tip);
    const Vector3      reaction =
      pinned->reaction(pinned->supports().back(), u_pinned, 1.0);
    std::cout << "midpoint deflection "
              << displacement(*bonded, u_bonded, vertex(*bonded, 0, n / 2))[2]
              << ", bond force " << force.transpose() << ", pin reaction "
              << reaction.transpose() << std::endl;
    EXPECT_LT(largest_difference(*bonded, u_bonded, *pinned, u_pinned),
              1e-9 * L);
    EXPECT_LT((force - reaction).norm(), 1e-7 * load.norm());
    EXPECT_GT(std::abs(force[0]), 0.01 * load.norm()); // a nonlinear pull
  }

  // The tip pulled 0.3 L down and 0.1 L in: at every step on the same path
  // as under the moving support, and at the point at the end.
  TEST(BondingConstraints, GapClosesAsAMovingSupport)
  {
    const Vector3 point(0.9 * L, 0, -0.3 * L);
    const Vector3 load(0, 0.5 * EI / (L * L), 0);
    const auto [bonded, u_bonded] = held_tip(true, point, load);
    const auto [moved, u_moved]   = held_tip(false, point, load);
    const unsigned int tip        = vertex(*bonded, 0, n);
    EXPECT_LT((bonded->network().vertex(tip) +
               displacement(*bonded, u_bonded, tip) - point)
                .norm(),
              1e-10 * L);
    EXPECT_LT(largest_difference(*bonded, u_bonded, *moved, u_moved), 1e-9 * L);
    const Vector3 force = bond_force(*bonded, u_bonded, tip);
    const Vector3 reaction =
      moved->reaction(moved->supports().back(), u_moved, 1.0);
    EXPECT_LT((force - reaction).norm(), 1e-7 * reaction.norm());
  }

  // Cantilevers (0,0,0)-(L,0,0) and (2L,0,0)-(L,0,0), tips bonded, P at the
  // first tip, P L^2 / EI = 1e-4 (the shortening of the tips, of order
  // (w / L)^2 = 1e-10, is all that mirror symmetry would not share).
  TEST(BondingConstraints, TippedCantileversShareTheLoad)
  {
    const double       P     = 1e-4 * EI / (L * L);
    auto               pair  = cantilevers({{Vector3::Zero(), Vector3(L, 0, 0)},
                                            {Vector3(2 * L, 0, 0), Vector3(L, 0, 0)}});
    const unsigned int tip_0 = vertex(*pair, 0, n), tip_1 = vertex(*pair, 1, n);
    pair->add_element_family(std::make_unique<BondingConstraintFamily>(
      *pair,
      std::vector<Bond>{{tip_0, tip_1, Vector3::Zero(), "tips"}}));
    pair->add_point_force(tip_0, Vector3(0, 0, -P));
    const VectorType u_pair = solve(*pair, 1);

    auto single = cantilevers({{Vector3::Zero(), Vector3(L, 0, 0)}});
    single->add_point_force(vertex(*single, 0, n), Vector3(0, 0, -P / 2));
    const VectorType u_single = solve(*single, 1);

    const double w_single =
      displacement(*single, u_single, vertex(*single, 0, n))[2];
    for (const unsigned int tip : {tip_0, tip_1})
      EXPECT_NEAR(displacement(*pair, u_pair, tip)[2] / w_single, 1, 1e-6);
    EXPECT_NEAR(bond_force(*pair, u_pair, tip_0)[2] / (P / 2), 1, 1e-6);
  }

  /// The free motions (describe_free_motions()) of a rod (0,0,0)-(1,0,0)-
  /// (1,1,0) without supports, bonded at the vertices of @p bonds (index
  /// along the rod) to their own points.
  std::string
  free_motions_of_bonded_corner(const std::vector<unsigned int> &bonds)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod({Vector3(0, 0, 0),
                      Vector3(0.5, 0, 0),
                      Vector3(1, 0, 0),
                      Vector3(1, 0.5, 0),
                      Vector3(1, 1, 0)},
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    RodModel          model(std::move(network),
                   {std::make_shared<LinearElasticRod>(
                     RodStiffness{EA, EI, EI, GJ})});
    std::vector<Bond> list;
    for (const unsigned int k : bonds)
      list.push_back({vertex(model, 0, k),
                      {},
                      model.network().vertex(vertex(model, 0, k)),
                      ""});
    model.add_element_family(
      std::make_unique<BondingConstraintFamily>(model, list));
    model.finalize();
    return describe_free_motions(model, model.create_vector());
  }

  TEST(BondingConstraints, BondsHoldLikeSupportsInTheFreeMotionCheck)
  {
    EXPECT_EQ(free_motions_of_bonded_corner({0, 2, 4}), "");
    const std::string two = free_motions_of_bonded_corner({0, 4});
    EXPECT_NE(two.find("can rotate about the axis through (0.5, 0.5, 0) "
                       "along (0.707, 0.707, 0)"),
              std::string::npos)
      << two;
    EXPECT_EQ(two.find("translate"), std::string::npos) << two;
  }

  TEST(BondingConstraints, RodsBondedToEachOtherMoveTogether)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3::Zero(), Vector3(L, 0, 0), n),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->add_rod(generators::straight(Vector3(L, 0, 0),
                                          Vector3(L, L, 0),
                                          n),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    RodModel free_pair(std::move(network),
                       std::vector<std::shared_ptr<const RodMaterial>>(
                         2,
                         std::make_shared<LinearElasticRod>(
                           RodStiffness{EA, EI, EI, GJ})));
    free_pair.add_element_family(std::make_unique<BondingConstraintFamily>(
      free_pair,
      std::vector<Bond>{{vertex(free_pair, 0, n),
                         vertex(free_pair, 1, 0),
                         Vector3::Zero(),
                         ""}}));
    free_pair.finalize();
    const std::string message =
      describe_free_motions(free_pair, free_pair.create_vector());
    EXPECT_NE(message.find("rods 0 and 1 can translate in any direction and "
                           "rotate about any axis"),
              std::string::npos)
      << message;
  }
} // namespace
