#ifndef RODNET_TESTS_ELEMENTS_JUNCTION_CONFIGURATIONS_H
#define RODNET_TESTS_ELEMENTS_JUNCTION_CONFIGURATIONS_H

// Shared set-up of the junction kernel tests: random junctions with large
// rotations, bends and twists, quaternions stored unnormalized, and the
// ghost spin angle computed independently of the kernel, by L&K eq. 26.

#include <elements/junction_kernel.h>

#include "hinge_configurations.h"

namespace rodnet
{
  namespace testing
  {
    /// The raw DoF block (w, x, y, z) of a rotation, scaled by @p scale.
    inline Eigen::Vector4d
    raw_quaternion(const Quaternion &q, const double scale)
    {
      return scale * Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
    }

    /// The rotation of a raw DoF block.
    inline Quaternion
    unit_quaternion(const Eigen::Vector4d &q)
    {
      return Quaternion(q[0], q[1], q[2], q[3]).normalized();
    }

    /**
     * Spin angle of a ghost segment by L&K eq. 26: b = t~* x t~ / |...|,
     * cos w~ = b . R b, sin w~ = (t~ x b) . R b. Undefined where t~ = t~*.
     */
    inline double
    spin_by_equation_26(const Quaternion &rotation,
                        const Vector3    &reference_tangent)
    {
      const Vector3 t  = rotation * reference_tangent;
      const Vector3 b  = reference_tangent.cross(t).normalized();
      const Vector3 Rb = rotation * b;
      return std::atan2(t.cross(b).dot(Rb), b.dot(Rb));
    }

    /// The difference of two angles, wrapped to [-pi, pi].
    inline double
    angle_difference(const double a, const double b)
    {
      return std::remainder(a - b, 2 * pi);
    }

    struct JunctionCase
    {
      JunctionVector    dofs;
      JunctionReference reference;

      Vector3
      tangent() const
      {
        return (dofs.segment<3>(junction_dofs::second_vertex) -
                dofs.segment<3>(junction_dofs::first_vertex))
          .normalized();
      }

      Eigen::Vector4d
      q() const
      {
        return dofs.segment<4>(junction_dofs::rotation);
      }

      /// Current frame of the physical segment (Korner et al. eq. 2.8).
      Quaternion
      segment_frame() const
      {
        return current_director_frame(reference.segment_frame,
                                      tangent(),
                                      dofs[junction_dofs::twist]);
      }
    };

    /// Assembles the DoF vector of a junction.
    inline JunctionVector
    junction_dofs_of(const Vector3         &first_vertex,
                     const Vector3         &second_vertex,
                     const double           twist,
                     const Eigen::Vector4d &q)
    {
      JunctionVector dofs;
      dofs << first_vertex, second_vertex, twist, q;
      return dofs;
    }

    /**
     * A random junction: rotation of the junction by up to @p max_rotation
     * about a random axis (or about the reference ghost tangent if
     * @p about_ghost_tangent, the special case of L&K appendix B), physical
     * segment bent by up to @p max_bend from the current ghost tangent, its
     * reference tangent up to @p max_tilt away from its current one,
     * reference frames rolled at random (quaternion signs random too), twist
     * increment up to @p max_twist, raw quaternion scaled by a factor of
     * magnitude in [0.3, 3] and random sign, segment length in [0.5, 2].
     */
    inline JunctionCase
    random_junction(std::mt19937 &rng,
                    const bool    ghost_first,
                    const double  max_rotation,
                    const double  max_bend,
                    const double  max_tilt,
                    const double  max_twist,
                    const bool    about_ghost_tangent)
    {
      const auto random_sign = [&rng]() {
        return uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0;
      };
      const auto random_frame = [&](const Vector3 &tangent) {
        Quaternion frame = frame_with_tangent(tangent, uniform(rng, -pi, pi));
        frame.coeffs() *= random_sign();
        return frame;
      };

      JunctionCase c;
      c.reference.ghost_first = ghost_first;
      c.reference.twist       = uniform(rng, -1, 1);

      const Vector3 ghost_reference_tangent = random_unit_vector(rng);
      c.reference.ghost_frame = random_frame(ghost_reference_tangent);
      const Vector3 axis =
        about_ghost_tangent ? ghost_reference_tangent : random_unit_vector(rng);
      const Quaternion rotation =
        rotation_about(axis, uniform(rng, -max_rotation, max_rotation));

      const Vector3 ghost_tangent = rotation * ghost_reference_tangent;
      const Vector3 tangent =
        tilt(ghost_tangent, uniform(rng, 0, max_bend), rng);
      c.reference.segment_frame =
        random_frame(tilt(tangent, uniform(rng, 0, max_tilt), rng));

      Vector3 first_vertex;
      for (unsigned int d = 0; d < 3; ++d)
        first_vertex[d] = uniform(rng, -1, 1);
      c.dofs =
        junction_dofs_of(first_vertex,
                         first_vertex + uniform(rng, 0.5, 2) * tangent,
                         uniform(rng, -max_twist, max_twist),
                         raw_quaternion(rotation,
                                        random_sign() * uniform(rng, 0.3, 3)));
      return c;
    }
  } // namespace testing
} // namespace rodnet

#endif
