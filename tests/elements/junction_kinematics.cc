// Kinematics of the junction element (Lestringant & Kochmann 2020,
// section 2.2 and appendix B), checked against independent references:
// - the ghost spin angle against eq. 26 on random finite rotations, against
//   the rotation angle in the special case of a rotation about the
//   reference ghost tangent, and the small-rotation form (eq. 8) against
//   the sine of the exact angle;
// - the exact ghost frame against R(q) applied to the reference frame;
// - the junction strains against the strains of a regular hinge
//   (SimpleHinge, ClassicHinge) whose second segment is replaced by a ghost
//   segment carried along by the rotation of that segment's frame;
// - zero strains for straight junctions moved rigidly, invariance under
//   rigid rotations and under the scale of q;
// - refusal of bad input.

#include <elements/junction_kernel.h>

#include "common/relative_error.h"
#include "junction_configurations.h"
#include <gtest/gtest.h>
#include <iostream>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr unsigned int n_rotated_junctions = 200;

  const std::vector<std::string> measures = {"simple", "classic"};

  /// A random reference ghost tangent and finite rotation, with t~ away
  /// from t~*, where the binormal of eq. 26 is ill-conditioned.
  std::pair<Vector3, Quaternion>
  rotation_for_equation_26(std::mt19937 &rng)
  {
    while (true)
      {
        const Vector3    tangent = random_unit_vector(rng);
        const Quaternion rotation =
          rotation_about(random_unit_vector(rng), uniform(rng, -3.1, 3.1));
        if ((rotation * tangent).cross(tangent).norm() > 1e-3)
          return {tangent, rotation};
      }
  }

  TEST(GhostSpin, SmoothFormEqualsEquation26)
  {
    std::mt19937 rng(21);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_junctions; ++n)
      {
        const auto [tangent, rotation] = rotation_for_equation_26(rng);
        const double exact =
          ghost_spin(raw_quaternion(rotation, uniform(rng, -3, 3)),
                     tangent,
                     GhostSpin::exact);
        max_difference =
          std::max(max_difference,
                   std::abs(
                     angle_difference(exact,
                                      spin_by_equation_26(rotation, tangent))));
      }
    std::cout << "ghost spin vs eq. 26: max difference " << max_difference
              << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }

  // Appendix B, special case: q = (cos(w/2), sin(w/2) t~*) has the spin w.
  // Eq. 27 as printed, cos w~ = a and sin w~ = |(b, c, d)|, would give
  // |w| / 2 instead: it is wrong by a factor two and loses the sign.
  TEST(GhostSpin, RotationAboutReferenceTangent)
  {
    std::mt19937 rng(22);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_junctions; ++n)
      {
        const Vector3         tangent = random_unit_vector(rng);
        const double          angle   = uniform(rng, -3.1, 3.1);
        const Eigen::Vector4d q =
          raw_quaternion(rotation_about(tangent, angle), uniform(rng, 0.3, 3));
        max_difference =
          std::max(max_difference,
                   std::abs(ghost_spin(q, tangent, GhostSpin::exact) - angle));

        const Eigen::Vector4d unit = q.normalized();
        const double equation_27   = std::atan2(unit.tail<3>().norm(), unit[0]);
        EXPECT_NEAR(equation_27, 0.5 * std::abs(angle), 1e-12);
      }
    std::cout << "ghost spin for rotations about t~*: max difference to the "
                 "angle "
              << max_difference << std::endl;
    EXPECT_LT(max_difference, 1e-12);
    EXPECT_NEAR(ghost_spin(Eigen::Vector4d(2, 0, 0, 0),
                           Vector3(0, 0, 1),
                           GhostSpin::exact),
                0,
                1e-15);
  }

  TEST(GhostSpin, SmallRotationIsSineOfExact)
  {
    std::mt19937 rng(23);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_junctions; ++n)
      {
        const auto [tangent, rotation] = rotation_for_equation_26(rng);
        const double small = ghost_spin(raw_quaternion(rotation, 1.7),
                                        tangent,
                                        GhostSpin::small_rotation);
        max_difference =
          std::max(max_difference,
                   std::abs(small -
                            std::sin(spin_by_equation_26(rotation, tangent))));
      }
    std::cout << "small-rotation ghost spin vs sin(eq. 26): max difference "
              << max_difference << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }

  // Eq. 1 with the exact spin of eq. 6: P_{t~*}^{t~} R(t~*, w~) = R.
  TEST(GhostFrame, ExactFrameIsRotatedReference)
  {
    std::mt19937 rng(24);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_junctions; ++n)
      {
        const Quaternion reference =
          frame_with_tangent(random_unit_vector(rng), uniform(rng, -pi, pi));
        const Quaternion rotation =
          rotation_about(random_unit_vector(rng), uniform(rng, -3.1, 3.1));
        const Quaternion frame =
          ghost_frame(raw_quaternion(rotation, uniform(rng, -3, 3)),
                      reference,
                      GhostSpin::exact);
        max_difference = std::max(max_difference,
                                  (frame.toRotationMatrix() -
                                   (rotation * reference).toRotationMatrix())
                                    .cwiseAbs()
                                    .maxCoeff());
      }
    std::cout << "exact ghost frame vs R D~*: max difference " << max_difference
              << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }

  /**
   * The junction that replaces one segment of a hinge by a ghost segment
   * with the reference frame of that segment and the rotation (raw,
   * scaled by @p scale) that carries it to the segment's current frame.
   */
  JunctionCase
  junction_of_hinge(const HingeCase &c, const bool ghost_first, double scale)
  {
    JunctionCase j;
    j.reference.ghost_first = ghost_first;
    j.reference.twist       = c.reference.twist;
    if (ghost_first)
      {
        j.reference.segment_frame = c.reference.frame_next;
        j.reference.ghost_frame   = c.reference.frame_prev;
        j.dofs =
          junction_dofs_of(c.dofs.segment<3>(4),
                           c.dofs.segment<3>(8),
                           c.dofs[7],
                           raw_quaternion(c.frame_prev() *
                                            c.reference.frame_prev.conjugate(),
                                          scale));
      }
    else
      {
        j.reference.segment_frame = c.reference.frame_prev;
        j.reference.ghost_frame   = c.reference.frame_next;
        j.dofs =
          junction_dofs_of(c.dofs.segment<3>(0),
                           c.dofs.segment<3>(4),
                           c.dofs[3],
                           raw_quaternion(c.frame_next() *
                                            c.reference.frame_next.conjugate(),
                                          scale));
      }
    return j;
  }

  TEST(JunctionStrains, EqualHingeStrainsForRealGhost)
  {
    for (const std::string &measure : measures)
      {
        const auto           hinge = create_hinge_kernel(measure);
        const JunctionKernel junction(measure);
        std::mt19937         rng(25);
        double               max_difference = 0;
        for (unsigned int n = 0; n < n_rotated_junctions; ++n)
          {
            // Twist increments below pi: the ghost spin is an angle in
            // [-pi, pi], the hinge's twist increment is not wrapped.
            const HingeCase c =
              random_hinge(rng, 120 * pi / 180, 80 * pi / 180, 3);
            const Vector3 kappa = hinge->strains(c.dofs, c.reference);
            for (const bool ghost_first : {false, true})
              {
                const JunctionCase j =
                  junction_of_hinge(c, ghost_first, uniform(rng, -3, 3));
                max_difference = std::max(
                  max_difference,
                  relative_error(kappa, junction.strains(j.dofs, j.reference)));
              }
          }
        std::cout << measure << ": junction vs hinge strains, max difference "
                  << max_difference << std::endl;
        EXPECT_LT(max_difference, 1e-12) << measure;
      }
  }

  /// Both measures with both ghost spins.
  class JunctionKernels
      : public ::testing::TestWithParam<std::tuple<std::string, GhostSpin>>
  {
  protected:
    std::string
    measure() const
    {
      return std::get<0>(GetParam());
    }

    GhostSpin
    spin() const
    {
      return std::get<1>(GetParam());
    }

    std::string
    label() const
    {
      return measure() + ", ghost spin " +
             (spin() == GhostSpin::exact ? "exact" : "small_rotation");
    }
  };

  INSTANTIATE_TEST_SUITE_P(
    MeasuresAndSpins,
    JunctionKernels,
    ::testing::Combine(::testing::Values("simple", "classic"),
                       ::testing::Values(GhostSpin::exact,
                                         GhostSpin::small_rotation)));

  // A straight junction (ghost frame = segment frame in the reference)
  // rotated rigidly by q, the identity first: the segment's twist increment
  // is then the spin of q about its reference tangent, computed here by
  // eq. 26.
  TEST_P(JunctionKernels, ZeroForRigidlyRotatedStraightJunction)
  {
    const JunctionKernel junction(measure(), spin());
    std::mt19937         rng(26);
    double               max_strain = 0;
    for (unsigned int n = 0; n < n_rotated_junctions; ++n)
      {
        const Vector3 T = random_unit_vector(rng);
        JunctionCase  c;
        c.reference.segment_frame =
          frame_with_tangent(T, uniform(rng, -pi, pi));
        c.reference.ghost_frame = c.reference.segment_frame;
        c.reference.ghost_first = n % 2 == 0;
        const Vector3 x(uniform(rng, -1, 1), 0, uniform(rng, -1, 1));
        const Vector3 edge = uniform(rng, 0.5, 2) * T;

        // The small-rotation spin of the ghost is sin(w~): the
        // segment matches it with the twist increment sin(w~).
        const Quaternion rotation =
          n == 0 ? Quaternion::Identity() :
                   rotation_about(random_unit_vector(rng),
                                  uniform(rng, -2 * pi / 3, 2 * pi / 3));
        const double angle = n == 0 ? 0 : spin_by_equation_26(rotation, T);
        const double twist =
          spin() == GhostSpin::exact ? angle : std::sin(angle);
        c.dofs = junction_dofs_of(rotation * x,
                                  rotation * (x + edge),
                                  twist,
                                  raw_quaternion(rotation, 1.3));
        max_strain =
          std::max(max_strain,
                   junction.strains(c.dofs, c.reference).cwiseAbs().maxCoeff());
      }
    std::cout << label()
              << ": max strain of rigidly rotated straight junctions "
              << max_strain << std::endl;
    EXPECT_LT(max_strain, 1e-12);
  }

  TEST_P(JunctionKernels, RigidRotationAndScaleInvariance)
  {
    const JunctionKernel junction(measure(), spin());
    std::mt19937         rng(27);
    double               max_rotation = 0, max_scale = 0;
    for (unsigned int n = 0; n < n_rotated_junctions; ++n)
      {
        const JunctionCase c     = random_junction(rng,
                                               n % 2 == 0,
                                               2 * pi / 3,
                                               2 * pi / 3,
                                               80 * pi / 180,
                                               2,
                                               n % 4 == 0);
        const Vector3      kappa = junction.strains(c.dofs, c.reference);

        const Quaternion Q =
          rotation_about(random_unit_vector(rng), uniform(rng, -pi, pi));
        JunctionCase moved = c;
        for (const unsigned int offset :
             {junction_dofs::first_vertex, junction_dofs::second_vertex})
          moved.dofs.segment<3>(offset) =
            Q * c.dofs.segment<3>(offset) + Vector3(1, -2, 3);
        const Eigen::Vector4d q = c.q();
        const Quaternion      conjugated =
          Q * Quaternion(q[0], q[1], q[2], q[3]) * Q.conjugate();
        moved.dofs.segment<4>(junction_dofs::rotation) =
          raw_quaternion(conjugated, 1);
        moved.reference.segment_frame = Q * c.reference.segment_frame;
        moved.reference.ghost_frame   = Q * c.reference.ghost_frame;
        max_rotation                  = std::max(
          max_rotation,
          relative_error(kappa, junction.strains(moved.dofs, moved.reference)));

        JunctionCase scaled = c;
        scaled.dofs.segment<4>(junction_dofs::rotation) *=
          (n % 3 == 0 ? -1 : 1) * uniform(rng, 1e-3, 1e3);
        max_scale =
          std::max(max_scale,
                   relative_error(kappa,
                                  junction.strains(scaled.dofs,
                                                   scaled.reference)));
      }
    std::cout << label() << ": strains change by " << max_rotation
              << " under rigid rotations, by " << max_scale
              << " under scaling of q" << std::endl;
    EXPECT_LT(max_rotation, 1e-12);
    EXPECT_LT(max_scale, 1e-12);
  }

  TEST(JunctionKernel, RefusesBadInput)
  {
    std::mt19937       rng(28);
    const JunctionCase c = random_junction(rng,
                                           false,
                                           2 * pi / 3,
                                           2 * pi / 3,
                                           80 * pi / 180,
                                           2,
                                           false);
    JunctionStrains    s;
    for (const std::string &measure : measures)
      {
        const JunctionKernel junction(measure);

        JunctionCase zero = c;
        zero.dofs.segment<4>(junction_dofs::rotation).setZero();
        EXPECT_THROW(junction.strains(zero.dofs, zero.reference),
                     std::invalid_argument);
        EXPECT_THROW(junction.evaluate(zero.dofs, zero.reference, s, true),
                     std::invalid_argument);

        JunctionCase not_finite = c;
        not_finite.dofs[1]      = std::nan("");
        EXPECT_THROW(
          junction.evaluate(not_finite.dofs, not_finite.reference, s, false),
          std::invalid_argument);

        // The physical segment turned around with respect to its reference.
        JunctionCase flipped            = c;
        flipped.reference.segment_frame = frame_with_tangent(-c.tangent(), 0.3);
        EXPECT_THROW(
          junction.evaluate(flipped.dofs, flipped.reference, s, true),
          ParallelTransportSingular);

        // The ghost tangent turned around by a half turn of the junction.
        const Vector3 ghost_tangent =
          c.reference.ghost_frame * Vector3::UnitZ();
        JunctionCase half_turn                             = c;
        half_turn.dofs.segment<4>(junction_dofs::rotation) = raw_quaternion(
          rotation_about(ghost_tangent.cross(Vector3(1, 2, 3)).normalized(),
                         pi),
          2);
        if (measure == "classic")
          EXPECT_THROW(junction.strains(half_turn.dofs, half_turn.reference),
                       ParallelTransportSingular);
        else
          {
            // The simple measure with the exact spin needs no transport of
            // the ghost tangent: the ghost frame is R D~* (eqs. 1, 6), and
            // the strains are 2 Im(conj(d) R D~*) in the hemisphere
            // Re >= 0 (Korner et al. eqs. 2.11, 2.13).
            const Eigen::Vector4d r     = half_turn.q().normalized();
            const Quaternion      ghost = Quaternion(r[0], r[1], r[2], r[3]) *
                                     half_turn.reference.ghost_frame;
            Quaternion q = half_turn.segment_frame().conjugate() * ghost;
            if (q.w() < 0)
              q.coeffs() = -q.coeffs();
            EXPECT_LT(relative_error(Vector3(2 * q.vec()),
                                     junction.strains(half_turn.dofs,
                                                      half_turn.reference)),
                      1e-13);
          }
      }

    try
      {
        JunctionKernel("bogus");
        FAIL() << "an unknown measure was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("bogus"), std::string::npos);
        EXPECT_NE(message.find("simple"), std::string::npos);
        EXPECT_NE(message.find("classic"), std::string::npos);
      }
  }
} // namespace
