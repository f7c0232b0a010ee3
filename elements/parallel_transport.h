#ifndef RODNET_ELEMENTS_PARALLEL_TRANSPORT_H
#define RODNET_ELEMENTS_PARALLEL_TRANSPORT_H

#include <elements/quaternion.h>

#include <stdexcept>
#include <string>

namespace rodnet
{
  /**
   * Thrown when a parallel transport is asked between (nearly) opposite unit
   * vectors, where it is undefined (Korner et al. 2021, end of section 2b).
   * In a rod this means a segment flipped by about 180 degrees within one
   * load or time step; the solvers catch it and cut the step.
   */
  class ParallelTransportSingular : public std::runtime_error
  {
  public:
    explicit ParallelTransportSingular(const double one_plus_cosine)
        : std::runtime_error(
            "parallel transport between nearly opposite tangents (1 + a.b = " +
            std::to_string(one_plus_cosine) +
            "): a segment turned by almost 180 degrees within one step; "
            "use smaller load or time steps")
    {
    }
  };

  /// Smallest admissible 1 + a.b before the transport is declared singular.
  constexpr double parallel_transport_tolerance = 1e-10;

  /**
   * Parallel transport p_a^b from unit vector @p a to unit vector @p b as a
   * unit quaternion (Korner et al. eq. 2.3): the rotation about a x b that
   * maps a onto b.
   */
  inline Quaternion
  parallel_transport(const Vector3 &a, const Vector3 &b)
  {
    const double one_plus_cosine = 1.0 + a.dot(b);
    if (!(one_plus_cosine > parallel_transport_tolerance))
      throw ParallelTransportSingular(one_plus_cosine);
    const double  c = std::sqrt(0.5 * one_plus_cosine);
    const Vector3 v = (0.5 / c) * a.cross(b);
    return Quaternion(c, v[0], v[1], v[2]);
  }

  /**
   * Director frame of a segment in the current configuration (Korner et al.
   * eq. 2.8): d = p_T^t r_T(phi) D, where D is the reference frame, T = D*e3
   * the reference tangent, t the current unit tangent and phi the twist angle
   * measured from the reference.
   */
  inline Quaternion
  current_director_frame(const Quaternion &reference_frame,
                         const Vector3    &current_tangent,
                         const double      twist_increment)
  {
    const Vector3 T = reference_frame._transformVector(Vector3::UnitZ());
    return parallel_transport(T, current_tangent) *
           rotation_about(T, twist_increment) * reference_frame;
  }
} // namespace rodnet

#endif
