#ifndef RODNET_ELEMENTS_FRAME_ALGEBRA_H
#define RODNET_ELEMENTS_FRAME_ALGEBRA_H

// Vectors, quaternions, director frames and the two families of hinge
// strains, written once as templates over the scalar type, so that the
// kernels that differentiate them automatically (the classic hinge, the
// junction) evaluate the very same expressions for doubles and for
// Sacado's forward types. Plain arrays keep Eigen out of the AD expressions.

#include <elements/parallel_transport.h>
#include <elements/quaternion.h>

#include <Sacado.hpp>
#include <array>
#include <cmath>

namespace rodnet
{
  namespace frame_algebra
  {
    /// A vector of R^3 over any scalar type.
    template <typename Number>
    using Vec = std::array<Number, 3>;

    /// Scalar product; the result type is given, the operands may mix.
    template <typename Number, typename A, typename B>
    Number
    dot(const Vec<A> &a, const Vec<B> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /// Vector product; the result type is given, the operands may mix.
    template <typename Number, typename A, typename B>
    Vec<Number>
    cross(const Vec<A> &a, const Vec<B> &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

    /// Unit tangent (to - from) / |to - from| of a segment.
    template <typename Number>
    Vec<Number>
    unit_edge(const Vec<Number> &from, const Vec<Number> &to)
    {
      using std::sqrt;
      const Vec<Number> e = {
        {to[0] - from[0], to[1] - from[1], to[2] - from[2]}};
      const Number inverse_length = 1.0 / sqrt(dot<Number>(e, e));
      return {
        {e[0] * inverse_length, e[1] * inverse_length, e[2] * inverse_length}};
    }

    /// 1 + a.b for unit vectors, refusing (nearly) opposite ones (Korner
    /// et al., end of section 2b).
    template <typename Number, typename A, typename B>
    Number
    checked_one_plus_cosine(const Vec<A> &a, const Vec<B> &b)
    {
      const Number one_plus_cosine = 1.0 + dot<Number>(a, b);
      if (!(one_plus_cosine > parallel_transport_tolerance))
        throw ParallelTransportSingular(
          Sacado::ScalarValue<Number>::eval(one_plus_cosine));
      return one_plus_cosine;
    }

    /**
     * Parallel transport P_a^b v of a vector: the rotation about a x b with
     * cosine a.b, in Rodrigues' form, v cos + (a x b) x v + (a x b)(a x b .
     * v) / (1 + cos), which is smooth down to a = b.
     */
    template <typename Number, typename A, typename B, typename V>
    Vec<Number>
    transport(const Vec<A> &a, const Vec<B> &b, const Vec<V> &v)
    {
      const Number      one_plus_cosine = checked_one_plus_cosine<Number>(a, b);
      const Number      cosine          = one_plus_cosine - 1.0;
      const Vec<Number> n               = cross<Number>(a, b);
      const Vec<Number> n_cross_v       = cross<Number>(n, v);
      const Number      axial           = dot<Number>(n, v) / one_plus_cosine;
      Vec<Number>       r;
      for (unsigned int i = 0; i < 3; ++i)
        r[i] = cosine * v[i] + n_cross_v[i] + axial * n[i];
      return r;
    }

    /// An Eigen vector as a plain array.
    inline Vec<double>
    to_vec(const Vector3 &v)
    {
      return {{v[0], v[1], v[2]}};
    }

    /// A quaternion (w, v) over any scalar type (Korner et al. section 2a).
    template <typename Number>
    struct Quat
    {
      Number      w;
      Vec<Number> v;
    };

    /// An Eigen quaternion as a Quat of the given scalar type.
    template <typename Number>
    Quat<Number>
    to_quat(const Quaternion &q)
    {
      return {Number(q.w()), {{Number(q.x()), Number(q.y()), Number(q.z())}}};
    }

    /// Quaternion product, Korner et al. eq. 2.1.
    template <typename Number>
    Quat<Number>
    operator*(const Quat<Number> &a, const Quat<Number> &b)
    {
      const Vec<Number> v_cross = cross<Number>(a.v, b.v);
      Quat<Number>      r;
      r.w = a.w * b.w - dot<Number>(a.v, b.v);
      for (unsigned int i = 0; i < 3; ++i)
        r.v[i] = a.w * b.v[i] + b.w * a.v[i] + v_cross[i];
      return r;
    }

    template <typename Number>
    Quat<Number>
    conjugate(const Quat<Number> &q)
    {
      return {q.w, {{-q.v[0], -q.v[1], -q.v[2]}}};
    }

    /// The unit quaternion q / |q| of a raw one (L&K eq. 19, whose |q|
    /// lacks its square root).
    template <typename Number>
    Quat<Number>
    unit_quaternion(const Number &w,
                    const Number &x,
                    const Number &y,
                    const Number &z)
    {
      using std::sqrt;
      const Number inverse_norm = 1.0 / sqrt(w * w + x * x + y * y + z * z);
      return {w * inverse_norm,
              {{x * inverse_norm, y * inverse_norm, z * inverse_norm}}};
    }

    /// Action r w r-bar of a unit quaternion on a vector, expanded as
    /// w + 2 s (v x w) + 2 v x (v x w).
    template <typename Number, typename V>
    Vec<Number>
    rotate(const Quat<Number> &r, const Vec<V> &w)
    {
      const Vec<Number> v_cross_w         = cross<Number>(r.v, w);
      const Vec<Number> v_cross_v_cross_w = cross<Number>(r.v, v_cross_w);
      Vec<Number>       result;
      for (unsigned int i = 0; i < 3; ++i)
        result[i] = w[i] + 2.0 * (r.w * v_cross_w[i] + v_cross_v_cross_w[i]);
      return result;
    }

    /// Rotation by @p angle about the unit vector @p axis (Korner eq. 2.2).
    template <typename Number>
    Quat<Number>
    rotation_about(const Vec<double> &axis, const Number &angle)
    {
      using std::cos;
      using std::sin;
      const Number s = sin(0.5 * angle);
      return {cos(0.5 * angle), {{s * axis[0], s * axis[1], s * axis[2]}}};
    }

    /// Parallel transport p_a^b as a unit quaternion (Korner eq. 2.3).
    template <typename Number, typename A, typename B>
    Quat<Number>
    transport_quaternion(const Vec<A> &a, const Vec<B> &b)
    {
      using std::sqrt;
      const Number      c = sqrt(0.5 * checked_one_plus_cosine<Number>(a, b));
      const Vec<Number> n = cross<Number>(a, b);
      const Number      f = 0.5 / c;
      return {c, {{f * n[0], f * n[1], f * n[2]}}};
    }

    /// The reference director frame of a segment, as a quaternion and as
    /// vectors (its third director is the reference tangent).
    struct SegmentReference
    {
      explicit SegmentReference(const Quaternion &reference_frame)
          : frame(reference_frame)
          , d1(to_vec(reference_frame * Vector3::UnitX()))
          , d2(to_vec(reference_frame * Vector3::UnitY()))
          , tangent(to_vec(reference_frame * Vector3::UnitZ()))
      {
      }

      Quaternion  frame;
      Vec<double> d1, d2, tangent;
    };

    /// Current directors of a segment (Korner eq. 2.8, L&K eq. 1), with the
    /// transported reference director that the holonomy needs.
    template <typename Number>
    struct SegmentDirectors
    {
      Vec<Number> tangent;
      Number      twist_increment;
      /// P_T^t D_1, the first director before the twist increment.
      Vec<Number> transported_d1;
      Vec<Number> d1, d2;
    };

    /**
     * Transverse directors of eq. 2.8: rotating D_I by phi about T and
     * transporting afterwards equals transporting D_I and rotating by phi
     * about t, which needs each transport only once.
     */
    template <typename Number>
    SegmentDirectors<Number>
    segment_directors(const SegmentReference &reference,
                      const Vec<Number>      &tangent,
                      const Number           &twist_increment)
    {
      using std::cos;
      using std::sin;
      SegmentDirectors<Number> s;
      s.tangent         = tangent;
      s.twist_increment = twist_increment;
      s.transported_d1 =
        transport<Number>(reference.tangent, tangent, reference.d1);
      const Vec<Number> transported_d2 =
        transport<Number>(reference.tangent, tangent, reference.d2);
      const Number c  = cos(twist_increment);
      const Number sn = sin(twist_increment);
      for (unsigned int i = 0; i < 3; ++i)
        {
          s.d1[i] = c * s.transported_d1[i] + sn * transported_d2[i];
          s.d2[i] = c * transported_d2[i] - sn * s.transported_d1[i];
        }
      return s;
    }

    /// Current director frame d = p_T^t r_T(phi) D as a quaternion (Korner
    /// eq. 2.8).
    template <typename Number>
    Quat<Number>
    segment_frame(const SegmentReference &reference,
                  const Vec<Number>      &tangent,
                  const Number           &twist_increment)
    {
      return transport_quaternion<Number>(reference.tangent, tangent) *
             rotation_about(reference.tangent, twist_increment) *
             to_quat<Number>(reference.frame);
    }

    /**
     * Korner et al.'s simple measures, eqs. 2.11 and 2.13: kappa = 2 Im(q)
     * for the rotation gradient q = conj(d_prev) d_next taken in the
     * hemisphere Re(q) >= 0, where the measure is smooth.
     */
    template <typename Number>
    std::array<Number, 3>
    simple_strains(const Quat<Number> &frame_prev,
                   const Quat<Number> &frame_next)
    {
      const Quat<Number> q = conjugate(frame_prev) * frame_next;
      const double       sign =
        Sacado::ScalarValue<Number>::eval(q.w) < 0 ? -2.0 : 2.0;
      return {{sign * q.v[0], sign * q.v[1], sign * q.v[2]}};
    }

    /**
     * The classic measures of Lestringant & Kochmann, eqs. 11 and 12, for
     * two consecutive segments; @p reference_twist is (tau_i)_star.
     */
    template <typename Number>
    std::array<Number, 3>
    classic_strains(const SegmentReference         &reference_prev,
                    const SegmentDirectors<Number> &prev,
                    const SegmentReference         &reference_next,
                    const SegmentDirectors<Number> &next,
                    const double                    reference_twist)
    {
      // Eq. 11.
      const Number scale =
        2.0 / checked_one_plus_cosine<Number>(prev.tangent, next.tangent);
      const Vec<Number> binormal = cross<Number>(prev.tangent, next.tangent);
      Vec<Number>       mean_d1, mean_d2;
      for (unsigned int i = 0; i < 3; ++i)
        {
          mean_d1[i] = 0.5 * scale * (prev.d1[i] + next.d1[i]);
          mean_d2[i] = 0.5 * scale * (prev.d2[i] + next.d2[i]);
        }

      // Eq. 12. The holonomy gamma_i of the loop (T^{i-1}, T^i, t^i,
      // t^{i-1}) is the rotation about t^i that closes it: the same vector
      // D_1^{i-1}, carried T^{i-1} -> t^{i-1} -> t^i (time, then space
      // transport) and T^{i-1} -> T^i -> t^i (space, then time), ends up
      // turned by gamma_i. By Gauss-Bonnet this is the signed spherical area
      // enclosed by the geodesic quadrilateral, for |gamma_i| < pi.
      const Vec<Number> time_then_space =
        transport<Number>(prev.tangent, next.tangent, prev.transported_d1);
      const Vec<double> d1_prev_in_space =
        transport<double>(reference_prev.tangent,
                          reference_next.tangent,
                          reference_prev.d1);
      const Vec<Number> space_then_time =
        transport<Number>(reference_next.tangent,
                          next.tangent,
                          d1_prev_in_space);
      using std::atan2;
      const Number holonomy =
        atan2(dot<Number>(cross<Number>(time_then_space, space_then_time),
                          next.tangent),
              dot<Number>(time_then_space, space_then_time));

      return {{dot<Number>(binormal, mean_d1),
               dot<Number>(binormal, mean_d2),
               reference_twist + next.twist_increment - prev.twist_increment +
                 holonomy}};
    }

    /**
     * Values, gradients and (if @p hessian is not null) Hessians of @p m
     * functions of @p n variables by forward automatic differentiation:
     * @p function maps a std::array<T, n> to a std::array<T, m> for any
     * scalar type T. Forward over forward gives the Hessians, whose two
     * orders of differentiation differ by round-off only; they are
     * symmetrized.
     */
    template <int m, int n, typename Function>
    void
    differentiate(const Eigen::Matrix<double, n, 1>          &x,
                  const Function                             &function,
                  Eigen::Matrix<double, m, 1>                &value,
                  Eigen::Matrix<double, m, n>                &gradient,
                  std::array<Eigen::Matrix<double, n, n>, m> *hessian)
    {
      using Gradient = Sacado::Fad::SFad<double, n>;
      if (hessian == nullptr)
        {
          std::array<Gradient, n> u;
          for (int i = 0; i < n; ++i)
            u[i] = Gradient(n, i, x[i]);
          const std::array<Gradient, m> f = function(u);
          for (int c = 0; c < m; ++c)
            {
              value[c] = f[c].val();
              for (int i = 0; i < n; ++i)
                gradient(c, i) = f[c].dx(i);
            }
          return;
        }

      using Hessian = Sacado::Fad::SFad<Gradient, n>;
      std::array<Hessian, n> u;
      for (int i = 0; i < n; ++i)
        u[i] = Hessian(n, i, Gradient(n, i, x[i]));
      const std::array<Hessian, m> f = function(u);
      for (int c = 0; c < m; ++c)
        {
          value[c]                       = f[c].val().val();
          Eigen::Matrix<double, n, n> &h = (*hessian)[c];
          for (int i = 0; i < n; ++i)
            {
              gradient(c, i) = f[c].dx(i).val();
              for (int j = 0; j < n; ++j)
                h(i, j) = f[c].dx(i).dx(j);
            }
          h = (0.5 * (h + h.transpose())).eval();
        }
    }
  } // namespace frame_algebra
} // namespace rodnet

#endif
