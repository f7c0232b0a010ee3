// The dynamic-relaxation beam element (elements/dr_beam_kernel.h,
// materials/dr_beam_energy.h):
// - pull_back() against central finite differences of every strain and of
//   the energy, on random elements near and far from their rest state, with
//   normals in both branches of eqs. 12-13 and nodes that are or are not
//   their own reference element;
// - zero strains at rest and invariance under rigid motions;
// - known values on a circular arc bent about and towards the normals and
//   on a uniformly twisted straight rod, against beam theory;
// - the refusals of dr_beam_reference().
//
// Error norm as in junction_derivatives.cc: max_i |analytic_i - fd_i| /
// max(1, max_i |analytic_i|), per strain and for the energy gradient,
// maximized over all configurations; h = 1e-6 keeps truncation O(h^2) and
// round-off O(eps / h) far below the 1e-6 tolerance.

#include <elements/dr_beam_kernel.h>
#include <materials/dr_beam_energy.h>

#include "common/relative_error.h"
#include "hinge_configurations.h"
#include <algorithm>
#include <gtest/gtest.h>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double       dr_step      = 1e-6;
  constexpr double       dr_tolerance = 1e-6;
  constexpr unsigned int n_elements   = 60;

  using StrainVector = Eigen::Matrix<double, 6, 1>;
  using NodeVector   = Eigen::Matrix<double, n_dr_node_dofs, 1>;

  const RodStiffness stiffness = {40.0, 2.0, 3.0, 1.5};

  StrainVector
  as_vector(const DrBeamStrains &s)
  {
    StrainVector v;
    v << s.stretch, s.twist, s.tilt[0], s.tilt[1], s.turn[0], s.turn[1];
    return v;
  }

  /// The stress that is 1 on strain @p k and 0 elsewhere.
  DrBeamStress
  unit_stress(const unsigned int k)
  {
    StrainVector v = StrainVector::Zero();
    v[k]           = 1;
    return {v[0], v[1], {{v[2], v[3]}}, {{v[4], v[5]}}};
  }

  StrainVector
  strains(const DrElementVector &dofs, const DrBeamReference &reference)
  {
    return as_vector(DrBeamKinematics(dofs, reference).strains());
  }

  double
  energy(const DrElementVector &dofs, const DrBeamReference &reference)
  {
    return dr_beam_energy(stiffness,
                          reference.rest_length,
                          DrBeamKinematics(dofs, reference).strains());
  }

  /// Stored components (n_x, n_y) of the unit normal @p n with n_z >= 0:
  /// inside the unit circle, or scaled by @p rho > 1 for a horizontal one.
  Eigen::Vector2d
  stored_normal(const Vector3 &n, const double rho = 1.5)
  {
    return n[2] > 0 ? Eigen::Vector2d(n[0], n[1]) :
                      Eigen::Vector2d(rho * n[0], rho * n[1]);
  }

  NodeVector
  node(const Vector3 &x, const Eigen::Vector2d &normal, const double rotation)
  {
    NodeVector u;
    u << x, normal, rotation;
    return u;
  }

  /// Where the stored normal (n_x, n_y) is at least @p margin away from
  /// the switch of eqs. 12-13 at n_x^2 + n_y^2 = 1.
  bool
  clear_of_branch_switch(const DrElementVector &dofs, const double margin)
  {
    for (const unsigned int block : {dr_dof::node_a, dr_dof::node_b})
      {
        const double rho = dofs.segment<2>(block + dr_dof::normal_x).norm();
        if (std::abs(rho - 1.0) < margin)
          return false;
      }
    return true;
  }

  /// Where every vector the element normalizes, and every cross product
  /// it normalizes, is clear of zero (sines at least @p margin).
  bool
  well_conditioned(const DrElementVector &dofs, const double margin)
  {
    const Vector3 t1 =
      (dofs.segment<3>(dr_dof::node_b) - dofs.segment<3>(dr_dof::node_a))
        .normalized();
    Vector3 normal_sum = Vector3::Zero();
    for (const auto &[block, far] : {std::pair(dr_dof::node_a, dr_dof::far_a),
                                     std::pair(dr_dof::node_b, dr_dof::far_b)})
      {
        const Vector3 n = dr_normal(dofs[block + dr_dof::normal_x],
                                    dofs[block + dr_dof::normal_y]);
        const Vector3 r =
          (dofs.segment<3>(far) - dofs.segment<3>(block)).normalized();
        if (n.cross(t1).norm() < margin || n.cross(r).norm() < margin)
          return false;
        normal_sum += n;
      }
    return normal_sum.norm() > margin &&
           normal_sum.normalized().cross(t1).norm() > margin;
  }

  /// How the element's ends find their reference elements.
  enum class ReferenceKind
  {
    own_both,
    distinct_both,
    own_a_distinct_b
  };

  struct ElementCase
  {
    DrElementVector rest;
    DrElementVector dofs;
    DrBeamReference reference;
    ReferenceKind   kind;
  };

  /// Points the far-node entries at the other end where the element is its
  /// node's own reference.
  void
  apply_kind(DrElementVector &dofs, const ReferenceKind kind)
  {
    if (kind != ReferenceKind::distinct_both)
      dofs.segment<3>(dr_dof::far_a) = dofs.segment<3>(dr_dof::node_b);
    if (kind == ReferenceKind::own_both)
      dofs.segment<3>(dr_dof::far_b) = dofs.segment<3>(dr_dof::node_a);
  }

  /// A random unit normal with n_z >= 0, horizontal with probability
  /// @p horizontal, otherwise with n_z >= 0.45 (n_x^2 + n_y^2 <= 0.8).
  Vector3
  random_normal(std::mt19937 &rng, const double horizontal)
  {
    if (uniform(rng, 0, 1) < horizontal)
      {
        const double angle = uniform(rng, -pi, pi);
        return Vector3(std::cos(angle), std::sin(angle), 0);
      }
    for (;;)
      {
        const Vector3 n = random_unit_vector(rng);
        if (std::abs(n[2]) >= 0.45)
          return n[2] > 0 ? n : Vector3(-n);
      }
  }

  /**
   * A random element: rest state with chord length in [0.5, 2], random
   * normals (a third of them horizontal when @p horizontal > 0) and
   * rotations, far nodes at [0.5, 2] from their node; the current state
   * moves every DoF by up to @p amplitude (far nodes and rotations by
   * twice that). Rejects states close to a singularity of the element or
   * to the branch switch of the normal.
   */
  ElementCase
  random_element(std::mt19937       &rng,
                 const ReferenceKind kind,
                 const double        amplitude,
                 const double        horizontal)
  {
    for (;;)
      {
        ElementCase c;
        c.kind            = kind;
        const Vector3 x_a = uniform(rng, -1, 1) * random_unit_vector(rng);
        const Vector3 x_b =
          x_a + uniform(rng, 0.5, 2) * random_unit_vector(rng);
        const Vector3 n_a = random_normal(rng, horizontal);
        const Vector3 n_b = random_normal(rng, horizontal);
        c.rest << node(x_a,
                       stored_normal(n_a, uniform(rng, 1.2, 2)),
                       uniform(rng, -1, 1)),
          node(x_b,
               stored_normal(n_b, uniform(rng, 1.2, 2)),
               uniform(rng, -1, 1)),
          x_a + uniform(rng, 0.5, 2) * random_unit_vector(rng),
          x_b + uniform(rng, 0.5, 2) * random_unit_vector(rng);
        apply_kind(c.rest, kind);

        c.dofs = c.rest;
        for (unsigned int i = 0; i < n_dr_element_dofs; ++i)
          c.dofs[i] += amplitude * uniform(rng, -1, 1);
        for (const unsigned int i : {dr_dof::node_a + dr_dof::rotation,
                                     dr_dof::node_b + dr_dof::rotation})
          c.dofs[i] += amplitude * uniform(rng, -1, 1);
        apply_kind(c.dofs, kind);

        if (!well_conditioned(c.rest, 0.3) || !well_conditioned(c.dofs, 0.2) ||
            !clear_of_branch_switch(c.dofs, 0.1) ||
            !clear_of_branch_switch(c.rest, 0.1))
          continue;
        c.reference = dr_beam_reference(c.rest);
        return c;
      }
  }

  TEST(DrNormal, BranchesAndJacobian)
  {
    std::mt19937 rng(20);
    double       max_error = 0;
    for (unsigned int n = 0; n < n_elements; ++n)
      {
        const double rho =
          n % 2 ? uniform(rng, 0, 0.95) : uniform(rng, 1.05, 3);
        const double  angle = uniform(rng, -pi, pi);
        const double  n_x = rho * std::cos(angle), n_y = rho * std::sin(angle);
        const Vector3 normal = dr_normal(n_x, n_y);
        EXPECT_NEAR(normal.norm(), 1.0, 1e-15);
        EXPECT_GE(normal[2], 0.0);
        if (rho > 1)
          EXPECT_EQ(normal[2], 0.0);
        else
          EXPECT_EQ(normal.head<2>(), Eigen::Vector2d(n_x, n_y));

        Eigen::Matrix<double, 3, 2> fd;
        fd.col(0) =
          (dr_normal(n_x + dr_step, n_y) - dr_normal(n_x - dr_step, n_y)) /
          (2 * dr_step);
        fd.col(1) =
          (dr_normal(n_x, n_y + dr_step) - dr_normal(n_x, n_y - dr_step)) /
          (2 * dr_step);
        max_error =
          std::max(max_error, relative_error(dr_normal_jacobian(n_x, n_y), fd));
      }
    std::cout << "dr_normal_jacobian: max relative FD error " << max_error
              << std::endl;
    EXPECT_LT(max_error, dr_tolerance);
  }

  TEST(DrBeamDerivatives, FiniteDifferences)
  {
    std::mt19937        rng(21);
    StrainVector        max_strain_error = StrainVector::Zero();
    double              max_energy_error = 0;
    const ReferenceKind kinds[]          = {ReferenceKind::own_both,
                                            ReferenceKind::distinct_both,
                                            ReferenceKind::own_a_distinct_b};
    unsigned int        n_horizontal     = 0;

    for (unsigned int n = 0; n < n_elements; ++n)
      {
        // Near (1e-3) and far (0.5) from the rest state; every other
        // element has a third of its normals horizontal (eq. 12-13, second
        // branch).
        const double      amplitude = n % 4 < 2 ? 1e-3 : 0.5;
        const ElementCase c =
          random_element(rng, kinds[n % 3], amplitude, n % 2 ? 0.4 : 0.0);
        for (const unsigned int block : {dr_dof::node_a, dr_dof::node_b})
          if (c.dofs.segment<2>(block + dr_dof::normal_x).norm() > 1)
            ++n_horizontal;

        const DrBeamKinematics kinematics(c.dofs, c.reference);
        Eigen::Matrix<double, 6, n_dr_element_dofs> fd;
        Eigen::Matrix<double, n_dr_element_dofs, 1> fd_energy;
        for (unsigned int i = 0; i < n_dr_element_dofs; ++i)
          {
            DrElementVector plus = c.dofs, minus = c.dofs;
            plus[i] += dr_step;
            minus[i] -= dr_step;
            fd.col(i) =
              (strains(plus, c.reference) - strains(minus, c.reference)) /
              (2 * dr_step);
            fd_energy[i] =
              (energy(plus, c.reference) - energy(minus, c.reference)) /
              (2 * dr_step);
          }

        for (unsigned int k = 0; k < 6; ++k)
          {
            DrElementVector gradient;
            kinematics.pull_back(unit_stress(k), gradient);
            max_strain_error[k] =
              std::max(max_strain_error[k],
                       relative_error(gradient,
                                      DrElementVector(fd.row(k).transpose())));
          }

        DrBeamStress stress;
        dr_beam_energy(stiffness,
                       c.reference.rest_length,
                       kinematics.strains(),
                       &stress);
        DrElementVector gradient;
        kinematics.pull_back(stress, gradient);
        max_energy_error =
          std::max(max_energy_error, relative_error(gradient, fd_energy));
      }

    std::cout << "dr beam: max relative FD error of the strain gradients "
                 "(stretch, twist, tilt a, tilt b, turn a, turn b) "
              << max_strain_error.transpose() << "; energy gradient "
              << max_energy_error << "; " << n_horizontal
              << " horizontal normals" << std::endl;
    EXPECT_GT(n_horizontal, 10u);
    EXPECT_LT(max_strain_error.maxCoeff(), dr_tolerance);
    EXPECT_LT(max_energy_error, dr_tolerance);
  }

  Vector3
  normal(const DrElementVector &dofs, const unsigned int block)
  {
    return dr_normal(dofs[block + dr_dof::normal_x],
                     dofs[block + dr_dof::normal_y]);
  }

  /// Applies the rotation @p rotation to the element's positions (about
  /// the origin) and normals; the normals must keep n_z >= 0.
  DrElementVector
  rotated(const DrElementVector &dofs, const Matrix3 &rotation)
  {
    DrElementVector result = dofs;
    for (const unsigned int block : {dr_dof::node_a, dr_dof::node_b})
      {
        const Vector3 n = rotation * normal(dofs, block);
        EXPECT_GE(n[2], 0.0);
        result.segment<2>(block + dr_dof::normal_x) =
          stored_normal(n, dofs.segment<2>(block + dr_dof::normal_x).norm());
      }
    for (const unsigned int block :
         {dr_dof::node_a, dr_dof::node_b, dr_dof::far_a, dr_dof::far_b})
      result.segment<3>(block) = rotation * dofs.segment<3>(block);
    return result;
  }

  TEST(DrBeamInvariance, RestStateAndRigidMotions)
  {
    std::mt19937        rng(22);
    const ReferenceKind kinds[]  = {ReferenceKind::own_both,
                                    ReferenceKind::distinct_both,
                                    ReferenceKind::own_a_distinct_b};
    double              max_rest = 0, max_motion = 0;
    for (unsigned int n = 0; n < n_elements; ++n)
      {
        // Normals about x turn only where none is horizontal.
        const bool  about_x = n % 2;
        ElementCase c;
        do
          c = random_element(rng, kinds[n % 3], 0.4, about_x ? 0.0 : 0.4);
        while (about_x && std::min(normal(c.dofs, dr_dof::node_a)[2],
                                   normal(c.dofs, dr_dof::node_b)[2]) < 0.15);
        // The offsets alpha make the supplement's in-plane angle itself
        // vanish at rest, not only its difference from the rest value.
        max_rest = std::max({max_rest,
                             strains(c.rest, c.reference).cwiseAbs().maxCoeff(),
                             std::abs(c.reference.rest_turn[0]),
                             std::abs(c.reference.rest_turn[1])});

        const StrainVector reference = strains(c.dofs, c.reference);
        DrElementVector    moved     = c.dofs;
        const Vector3      shift = uniform(rng, 0, 3) * random_unit_vector(rng);
        for (const unsigned int block :
             {dr_dof::node_a, dr_dof::node_b, dr_dof::far_a, dr_dof::far_b})
          moved.segment<3>(block) += shift;
        max_motion = std::max(
          max_motion,
          (strains(moved, c.reference) - reference).cwiseAbs().maxCoeff());

        const Vector3 axis = about_x ? Vector3::UnitX() : Vector3::UnitZ();
        const double  angle =
          about_x ? uniform(rng, -0.1, 0.1) : uniform(rng, -pi, pi);
        // |angle| <= 0.1 keeps n_z >= 0 where it was at least 0.15.
        moved = rotated(c.dofs, rotation_about(axis, angle).toRotationMatrix());
        max_motion = std::max(
          max_motion,
          (strains(moved, c.reference) - reference).cwiseAbs().maxCoeff());
      }
    std::cout << "dr beam: max |strain| and |rest turn| at rest " << max_rest
              << ", max change under rigid motions " << max_motion << std::endl;
    EXPECT_LT(max_rest, 1e-14);
    EXPECT_LT(max_motion, 1e-13);
  }

  /**
   * A chain of elements from node 0 to node N along the rest line
   * X_j = (j h, 0, 0) with normals +z and no rotations. Node j refers to
   * the element on its right for even j and on its left for odd j (node 0
   * and node N to their only element), so interior nodes are the own
   * reference of one of their elements and not of the other.
   */
  class Chain
  {
  public:
    Chain(const unsigned int n_elements, const double h)
        : nodes(n_elements + 1)
    {
      for (unsigned int j = 0; j < nodes.size(); ++j)
        nodes[j] = node(Vector3(j * h, 0, 0), Eigen::Vector2d::Zero(), 0);
      for (unsigned int k = 0; k < n_elements; ++k)
        references.push_back(dr_beam_reference(element_dofs(k)));
    }

    /// The far node c_j of node j's reference element.
    unsigned int
    far_node(const unsigned int j) const
    {
      if (j == 0)
        return 1;
      if (j + 1 == nodes.size() || j % 2 == 1)
        return j - 1;
      return j + 1;
    }

    DrElementVector
    element_dofs(const unsigned int k) const
    {
      DrElementVector dofs;
      dofs << nodes[k], nodes[k + 1], nodes[far_node(k)].head<3>(),
        nodes[far_node(k + 1)].head<3>();
      return dofs;
    }

    DrBeamStrains
    strains(const unsigned int k) const
    {
      return DrBeamKinematics(element_dofs(k), references[k]).strains();
    }

    double
    energy() const
    {
      double sum = 0;
      for (unsigned int k = 0; k < references.size(); ++k)
        sum += dr_beam_energy(stiffness, references[k].rest_length, strains(k));
      return sum;
    }

    std::vector<NodeVector>      nodes;
    std::vector<DrBeamReference> references;
  };

  constexpr unsigned int n_chain_elements = 20;
  constexpr double       chain_step       = 0.05;
  // Strains agree with the beam-theory angles to second order, i.e. up to
  // a few (angle)^3.
  constexpr double kappa           = 1.0;
  constexpr double end_angle       = kappa * chain_step / 2;
  constexpr double angle_tolerance = 8 * end_angle * end_angle * end_angle;
  // The arcs of curvature kappa whose chords keep the rest length h: each
  // element spans this angle, and the arc is this long.
  const double element_angle = 2 * std::asin(kappa * chain_step / 2);
  const double arc_length    = n_chain_elements * element_angle / kappa;

  /// Expects the strains @p expected on every element of @p chain: to
  /// @p tolerance where they are nonzero (second-order approximations), to
  /// round-off where they vanish. Then the energy against beam theory.
  void
  expect_strains_and_energy(const Chain        &chain,
                            const StrainVector &expected,
                            const double        dr_tolerance,
                            const double        exact_energy,
                            const std::string  &name)
  {
    for (unsigned int k = 0; k < chain.references.size(); ++k)
      {
        const StrainVector s = as_vector(chain.strains(k));
        for (unsigned int i = 0; i < 6; ++i)
          EXPECT_NEAR(s[i],
                      expected[i],
                      expected[i] == 0 ? 1e-14 : dr_tolerance)
            << name << ": element " << k << ", strain " << i;
      }
    std::cout << name << ": energy " << chain.energy() << ", beam theory "
              << exact_energy << std::endl;
    EXPECT_NEAR(chain.energy() / exact_energy, 1.0, 1e-3);
  }

  TEST(DrBeamKnownValues, ArcBentAboutTheNormals)
  {
    // The arc X = R (sin psi, 1 - cos psi, 0), R = 1/kappa: its tangent at
    // node j has turned by psi_j about z. n_r of node j is the turn of the
    // node's frame relative to its reference chord, which has turned by
    // psi_j +- element_angle / 2.
    Chain chain(n_chain_elements, chain_step);
    for (unsigned int j = 0; j < chain.nodes.size(); ++j)
      {
        const double psi = j * element_angle;
        chain.nodes[j].head<3>() =
          Vector3(std::sin(psi), 1 - std::cos(psi), 0) / kappa;
        chain.nodes[j][dr_dof::rotation] =
          chain.far_node(j) > j ? -element_angle / 2 : element_angle / 2;
      }
    StrainVector expected;
    expected << 0, 0, 0, 0, -end_angle, end_angle;
    expect_strains_and_energy(chain,
                              expected,
                              angle_tolerance,
                              stiffness.EI1 * kappa * kappa * arc_length / 2,
                              "arc bent about the normals");
  }

  TEST(DrBeamKnownValues, ArcBentTowardsTheNormals)
  {
    // The arc X = R (sin phi, 0, cos phi) in the xz plane with the outward
    // normals (sin phi, 0, cos phi), n_z > 0: the node frames turn about y
    // with the tangent, so no rotation about the normals.
    Chain chain(n_chain_elements, chain_step);
    for (unsigned int j = 0; j < chain.nodes.size(); ++j)
      {
        const double phi = (j - 0.5 * n_chain_elements) * element_angle;
        chain.nodes[j].head<3>() =
          Vector3(std::sin(phi), 0, std::cos(phi)) / kappa;
        chain.nodes[j][dr_dof::normal_x] = std::sin(phi);
      }
    StrainVector expected;
    expected << 0, 0, -end_angle, end_angle, 0, 0;
    expect_strains_and_energy(chain,
                              expected,
                              angle_tolerance,
                              stiffness.EI2 * kappa * kappa * arc_length / 2,
                              "arc bent towards the normals");
  }

  TEST(DrBeamKnownValues, UniformTwist)
  {
    // The straight rod with normals turned right-handedly about x by
    // tau x: n = (0, -sin(tau x), cos(tau x)). The supplement's
    // theta_1b - theta_1a is -2 sin(tau h / 2), of the opposite sign.
    constexpr double tau = 1.0;
    Chain            chain(n_chain_elements, chain_step);
    for (unsigned int j = 0; j < chain.nodes.size(); ++j)
      chain.nodes[j][dr_dof::normal_y] = -std::sin(tau * j * chain_step);
    const double twist = tau * chain_step;
    StrainVector expected;
    expected << 0, -twist, 0, 0, 0, 0;
    expect_strains_and_energy(chain,
                              expected,
                              twist * twist * twist,
                              stiffness.GJ * tau * tau * n_chain_elements *
                                chain_step / 2,
                              "uniform twist");
  }

  TEST(DrBeamReference, RefusesDegenerateElements)
  {
    // A sound element along x with normals +z, its own reference.
    DrElementVector sound;
    sound << node(Vector3(0, 0, 0), Eigen::Vector2d(0, 0), 0),
      node(Vector3(1, 0, 0), Eigen::Vector2d(0, 0), 0), Vector3(1, 0, 0),
      Vector3(0, 0, 0);
    EXPECT_NO_THROW(dr_beam_reference(sound));

    DrElementVector zero_length = sound;
    zero_length.segment<3>(dr_dof::node_b).setZero();
    zero_length.segment<3>(dr_dof::far_a).setZero();
    EXPECT_THROW(dr_beam_reference(zero_length), std::invalid_argument);

    // The chord along z, parallel to both normals.
    DrElementVector vertical            = sound;
    vertical.segment<3>(dr_dof::node_b) = Vector3(0, 0, 1);
    vertical.segment<3>(dr_dof::far_a)  = Vector3(0, 0, 1);
    EXPECT_THROW(dr_beam_reference(vertical), std::invalid_argument);

    // Node a's distinct reference element along its normal.
    DrElementVector reference_along_normal           = sound;
    reference_along_normal.segment<3>(dr_dof::far_a) = Vector3(0, 0, -1);
    EXPECT_THROW(dr_beam_reference(reference_along_normal),
                 std::invalid_argument);

    // Normals +-45 degrees from z in the xz plane: their mean is along z,
    // and along the chord when that is vertical.
    DrElementVector symmetric = vertical;
    symmetric.segment<2>(dr_dof::node_a + dr_dof::normal_x) =
      Eigen::Vector2d(std::sqrt(0.5), 0);
    symmetric.segment<2>(dr_dof::node_b + dr_dof::normal_x) =
      Eigen::Vector2d(-std::sqrt(0.5), 0);
    EXPECT_THROW(dr_beam_reference(symmetric), std::invalid_argument);
  }
} // namespace
