// Parallel transport (Korner et al. eq. 2.3) and its singularity: between
// (nearly) opposite tangents it throws ParallelTransportSingular, and so do
// both hinge kernels when a segment has flipped against its reference.

#include <elements/hinge_kernel.h>
#include <elements/parallel_transport.h>

#include "hinge_configurations.h"
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  TEST(ParallelTransport, MapsUnitAboutBinormal)
  {
    std::mt19937 rng(11);
    for (unsigned int n = 0; n < 1000; ++n)
      {
        const Vector3 a = random_unit_vector(rng);
        // Up to 1 + a.b = 1e-8, well inside the admissible range.
        const Vector3    b = tilt(a, uniform(rng, 0, pi - 2e-4), rng);
        const Quaternion p = parallel_transport(a, b);
        // Eq. 2.3 divides by sqrt((1 + a.b) / 2): round-off grows like
        // eps / (1 + a.b) towards opposite vectors.
        const double accuracy = 1e-14 / (1 + a.dot(b));
        EXPECT_NEAR(p.norm(), 1.0, accuracy);
        EXPECT_LT((p * a - b).norm(), 2 * accuracy);
        EXPECT_LT(p.vec().cross(a.cross(b)).norm(), 1e-14);
        EXPECT_GE(p.vec().dot(a.cross(b)), 0.0);
      }
    const Vector3 a = random_unit_vector(rng);
    EXPECT_LT((parallel_transport(a, a).coeffs() -
               Quaternion::Identity().coeffs())
                .norm(),
              1e-15);
  }

  TEST(ParallelTransport, OppositeTangentsThrow)
  {
    std::mt19937 rng(12);
    for (unsigned int n = 0; n < 100; ++n)
      {
        const Vector3 a = random_unit_vector(rng);
        EXPECT_THROW(parallel_transport(a, -a), ParallelTransportSingular);
        // 1 + a.b of about 1e-12, below the tolerance.
        EXPECT_THROW(parallel_transport(a, tilt(-a, 1.4e-6, rng)),
                     ParallelTransportSingular);
      }
  }

  TEST(ParallelTransport, DirectorFrameIsAdapted)
  {
    std::mt19937 rng(13);
    for (unsigned int n = 0; n < 100; ++n)
      {
        const Quaternion D =
          frame_with_tangent(random_unit_vector(rng), uniform(rng, -pi, pi));
        const Vector3    T   = D * Vector3::UnitZ();
        const Vector3    t   = tilt(T, uniform(rng, 0, 2.5), rng);
        const double     phi = uniform(rng, -2, 2);
        const Quaternion d   = current_director_frame(D, t, phi);
        const Quaternion d0  = current_director_frame(D, t, 0);
        EXPECT_LT((d * Vector3::UnitZ() - t).norm(), 1e-13);
        // phi turns the frame about t (eq. 2.8).
        EXPECT_NEAR(signed_angle(d0 * Vector3::UnitX(),
                                 d * Vector3::UnitX(),
                                 t),
                    phi,
                    1e-13);
      }
    const Quaternion D = frame_with_tangent(Vector3::UnitZ(), 0.3);
    EXPECT_THROW(current_director_frame(D, -Vector3::UnitZ(), 0.1),
                 ParallelTransportSingular);
  }

  class FlippedSegment : public ::testing::TestWithParam<std::string>
  {
  };

  // A hinge in which one segment is reversed with respect to its reference
  // tangent: both kernels must refuse it, from every entry point.
  TEST_P(FlippedSegment, KernelsThrow)
  {
    const auto     kernel = create_hinge_kernel(GetParam());
    HingeReference reference;
    reference.frame_prev = frame_with_tangent(Vector3::UnitX(), 0.2);
    reference.frame_next = frame_with_tangent(Vector3::UnitY(), -0.4);
    const Vector3 vertex(0.1, 0.2, 0.3);

    const HingeVector flipped_prev =
      hinge_dofs(vertex, -Vector3::UnitX(), 0.1, Vector3::UnitY(), 0.2);
    const HingeVector flipped_next =
      hinge_dofs(vertex, Vector3::UnitX(), 0.1, -Vector3::UnitY(), 0.2);
    for (const HingeVector &dofs : {flipped_prev, flipped_next})
      {
        HingeStrains result;
        EXPECT_THROW(kernel->strains(dofs, reference),
                     ParallelTransportSingular);
        EXPECT_THROW(kernel->evaluate(dofs, reference, result, false),
                     ParallelTransportSingular);
        EXPECT_THROW(kernel->evaluate(dofs, reference, result, true),
                     ParallelTransportSingular);
      }

    const HingeVector regular =
      hinge_dofs(vertex, Vector3::UnitX(), 0.1, Vector3::UnitY(), 0.2);
    EXPECT_NO_THROW(kernel->strains(regular, reference));
  }

  INSTANTIATE_TEST_SUITE_P(Kernels,
                           FlippedSegment,
                           ::testing::Values("simple", "classic"));

  // The curvature binormal of L&K eq. 11 is singular for a hinge folded back
  // onto itself; the simple kernel has no such singularity (Korner et al.
  // section 2h: |kappa| <= 2).
  TEST(FoldedHinge, OnlyClassicThrows)
  {
    HingeReference reference;
    reference.frame_prev     = frame_with_tangent(Vector3::UnitX(), 0.2);
    reference.frame_next     = frame_with_tangent(-Vector3::UnitX(), 0.5);
    const HingeVector folded = hinge_dofs(Vector3::Zero(),
                                          Vector3::UnitX(),
                                          0.1,
                                          -Vector3::UnitX(),
                                          0.2);

    EXPECT_THROW(create_hinge_kernel("classic")->strains(folded, reference),
                 ParallelTransportSingular);
    const Vector3 kappa =
      create_hinge_kernel("simple")->strains(folded, reference);
    EXPECT_TRUE(kappa.allFinite());
    EXPECT_LE(kappa.norm(), 2.0 + 1e-14);
  }
} // namespace
