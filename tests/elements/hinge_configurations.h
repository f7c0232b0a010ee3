#ifndef RODNET_TESTS_ELEMENTS_HINGE_CONFIGURATIONS_H
#define RODNET_TESTS_ELEMENTS_HINGE_CONFIGURATIONS_H

// Shared set-up of the hinge kernel tests: random hinge stencils with large
// bends, twists and reference-to-current rotations, and independent
// geometric quantities (director frames, classic twist) built from
// elements/parallel_transport.h only.

#include <elements/hinge_kernel.h>
#include <elements/parallel_transport.h>

#include <cmath>
#include <random>

namespace rodnet
{
  namespace testing
  {
    constexpr double pi = 3.14159265358979323846;

    inline Vector3
    random_unit_vector(std::mt19937 &rng)
    {
      std::normal_distribution<double> normal;
      Vector3                          v(normal(rng), normal(rng), normal(rng));
      return v.normalized();
    }

    inline double
    uniform(std::mt19937 &rng, const double low, const double high)
    {
      return std::uniform_real_distribution<double>(low, high)(rng);
    }

    /// Rotates the unit vector @p v by @p angle about a random axis
    /// orthogonal to it.
    inline Vector3
    tilt(const Vector3 &v, const double angle, std::mt19937 &rng)
    {
      const Vector3 axis = v.cross(random_unit_vector(rng)).normalized();
      return rotation_about(axis, angle)._transformVector(v);
    }

    /// The frame with third director @p tangent, rolled by @p roll about it.
    inline Quaternion
    frame_with_tangent(const Vector3 &tangent, const double roll)
    {
      const Vector3 helper =
        std::abs(tangent[0]) < 0.9 ? Vector3::UnitX() : Vector3::UnitY();
      const Vector3 d1 = tangent.cross(helper).cross(tangent).normalized();
      Matrix3       m;
      m << d1, tangent.cross(d1), tangent;
      return rotation_about(tangent, roll) * Quaternion(m);
    }

    /// Signed angle about @p axis from @p a to @p b (both orthogonal to it).
    inline double
    signed_angle(const Vector3 &a, const Vector3 &b, const Vector3 &axis)
    {
      return std::atan2(a.cross(b).dot(axis), a.dot(b));
    }

    struct HingeCase
    {
      HingeVector    dofs;
      HingeReference reference;

      Vector3
      tangent_prev() const
      {
        return (dofs.segment<3>(4) - dofs.segment<3>(0)).normalized();
      }

      Vector3
      tangent_next() const
      {
        return (dofs.segment<3>(8) - dofs.segment<3>(4)).normalized();
      }

      /// d^{i-1} and d^i of Korner et al. eq. 2.8.
      Quaternion
      frame_prev() const
      {
        return current_director_frame(reference.frame_prev,
                                      tangent_prev(),
                                      dofs[3]);
      }

      Quaternion
      frame_next() const
      {
        return current_director_frame(reference.frame_next,
                                      tangent_next(),
                                      dofs[7]);
      }
    };

    /// Assembles the DoF vector of a hinge from its vertex and segments.
    inline HingeVector
    hinge_dofs(const Vector3 &vertex,
               const Vector3 &edge_prev,
               const double   twist_prev,
               const Vector3 &edge_next,
               const double   twist_next)
    {
      HingeVector dofs;
      dofs << vertex - edge_prev, twist_prev, vertex, twist_next,
        vertex + edge_next;
      return dofs;
    }

    /**
     * A random hinge: bend between the current segments up to
     * @p max_bend, current tangents up to @p max_tilt away from the
     * reference ones, reference frames arbitrary rotations (quaternion signs
     * random too), twist increments up to @p max_twist in magnitude,
     * segment lengths in [0.5, 2].
     */
    inline HingeCase
    random_hinge(std::mt19937 &rng,
                 const double  max_bend,
                 const double  max_tilt,
                 const double  max_twist)
    {
      const Vector3 t_prev = random_unit_vector(rng);
      const Vector3 t_next = tilt(t_prev, uniform(rng, 0, max_bend), rng);

      const auto reference_frame = [&](const Vector3 &t) {
        const Vector3 T     = tilt(t, uniform(rng, 0, max_tilt), rng);
        Quaternion    frame = frame_with_tangent(T, uniform(rng, -pi, pi));
        if (uniform(rng, 0, 1) < 0.5)
          frame.coeffs() = -frame.coeffs();
        return frame;
      };

      HingeCase c;
      c.reference.frame_prev = reference_frame(t_prev);
      c.reference.frame_next = reference_frame(t_next);
      c.reference.twist      = uniform(rng, -1, 1);

      Vector3 vertex;
      for (unsigned int d = 0; d < 3; ++d)
        vertex[d] = uniform(rng, -1, 1);
      const double length_prev = uniform(rng, 0.5, 2);
      const double length_next = uniform(rng, 0.5, 2);
      const double twist_prev  = uniform(rng, -max_twist, max_twist);
      const double twist_next  = uniform(rng, -max_twist, max_twist);
      c.dofs                   = hinge_dofs(vertex,
                          length_prev * t_prev,
                          twist_prev,
                          length_next * t_next,
                          twist_next);
      return c;
    }

    /**
     * The classic (spatial parallel transport) twist of a pair of frames:
     * the signed angle about the second tangent from the transported first
     * director of the first frame to that of the second.
     */
    inline double
    classic_twist(const Quaternion &frame_prev, const Quaternion &frame_next)
    {
      const Vector3 t_prev = frame_prev * Vector3::UnitZ();
      const Vector3 t_next = frame_next * Vector3::UnitZ();
      return signed_angle(parallel_transport(t_prev, t_next) *
                            (frame_prev * Vector3::UnitX()),
                          frame_next * Vector3::UnitX(),
                          t_next);
    }
  } // namespace testing
} // namespace rodnet

#endif
