#include <elements/classic_hinge.h>
#include <elements/parallel_transport.h>

#include <Sacado.hpp>
#include <cmath>

namespace rodnet
{
  namespace
  {
    // Offsets of the hinge stencil in the local DoF vector (hinge_kernel.h).
    constexpr int prev_vertex = 0;
    constexpr int prev_twist  = 3;
    constexpr int vertex      = 4;
    constexpr int next_twist  = 7;
    constexpr int next_vertex = 8;

    // The strains are written once, for doubles and for Sacado's forward
    // types; a plain array keeps Eigen out of the AD expressions.
    template <typename Number>
    using Vec = std::array<Number, 3>;

    template <typename Number, typename A, typename B>
    Number
    dot(const Vec<A> &a, const Vec<B> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    template <typename Number, typename A, typename B>
    Vec<Number>
    cross(const Vec<A> &a, const Vec<B> &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

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

    Vec<double>
    to_vec(const Vector3 &v)
    {
      return {{v[0], v[1], v[2]}};
    }

    /// The constant part of the hinge: reference directors and what the
    /// holonomy needs of them.
    struct ReferenceVectors
    {
      explicit ReferenceVectors(const HingeReference &reference)
          : d1_prev(to_vec(reference.frame_prev * Vector3::UnitX()))
          , d2_prev(to_vec(reference.frame_prev * Vector3::UnitY()))
          , tangent_prev(to_vec(reference.frame_prev * Vector3::UnitZ()))
          , d1_next(to_vec(reference.frame_next * Vector3::UnitX()))
          , d2_next(to_vec(reference.frame_next * Vector3::UnitY()))
          , tangent_next(to_vec(reference.frame_next * Vector3::UnitZ()))
          , d1_prev_in_space(
              transport<double>(tangent_prev, tangent_next, d1_prev))
          , twist(reference.twist)
      {
      }

      Vec<double> d1_prev, d2_prev, tangent_prev;
      Vec<double> d1_next, d2_next, tangent_next;
      /// P_{T^{i-1}}^{T^i} D_1^{i-1}: the first leg of the space-then-time
      /// path of the holonomy.
      Vec<double> d1_prev_in_space;
      double      twist;
    };

    /**
     * Transverse directors d_1, d_2 of eq. 2.8: rotating D_I by phi about T
     * and transporting afterwards equals transporting D_I and rotating by
     * phi about t, which needs each transport only once.
     */
    template <typename Number>
    void
    directors(const Vec<double> &reference_tangent,
              const Vec<double> &reference_d1,
              const Vec<double> &reference_d2,
              const Vec<Number> &tangent,
              const Number      &twist_increment,
              Vec<Number>       &transported_d1,
              Vec<Number>       &d1,
              Vec<Number>       &d2)
    {
      using std::cos;
      using std::sin;
      transported_d1 =
        transport<Number>(reference_tangent, tangent, reference_d1);
      const Vec<Number> transported_d2 =
        transport<Number>(reference_tangent, tangent, reference_d2);
      const Number c = cos(twist_increment);
      const Number s = sin(twist_increment);
      for (unsigned int i = 0; i < 3; ++i)
        {
          d1[i] = c * transported_d1[i] + s * transported_d2[i];
          d2[i] = c * transported_d2[i] - s * transported_d1[i];
        }
    }

    template <typename Number>
    std::array<Number, 3>
    classic_strains(const std::array<Number, n_hinge_dofs> &u,
                    const ReferenceVectors                 &reference)
    {
      const auto position = [&u](const int offset) {
        return Vec<Number>{{u[offset], u[offset + 1], u[offset + 2]}};
      };
      const Vec<Number> t_prev =
        unit_edge(position(prev_vertex), position(vertex));
      const Vec<Number> t_next =
        unit_edge(position(vertex), position(next_vertex));

      Vec<Number> transported_d1_prev, d1_prev, d2_prev;
      Vec<Number> transported_d1_next, d1_next, d2_next;
      directors(reference.tangent_prev,
                reference.d1_prev,
                reference.d2_prev,
                t_prev,
                u[prev_twist],
                transported_d1_prev,
                d1_prev,
                d2_prev);
      directors(reference.tangent_next,
                reference.d1_next,
                reference.d2_next,
                t_next,
                u[next_twist],
                transported_d1_next,
                d1_next,
                d2_next);

      // L&K eq. 11.
      const Number scale =
        2.0 / checked_one_plus_cosine<Number>(t_prev, t_next);
      const Vec<Number> binormal = cross<Number>(t_prev, t_next);
      Vec<Number>       mean_d1, mean_d2;
      for (unsigned int i = 0; i < 3; ++i)
        {
          mean_d1[i] = 0.5 * scale * (d1_prev[i] + d1_next[i]);
          mean_d2[i] = 0.5 * scale * (d2_prev[i] + d2_next[i]);
        }

      // L&K eq. 12. The holonomy gamma_i of the loop (T^{i-1}, T^i, t^i,
      // t^{i-1}) is the rotation about t^i that closes it: the same vector
      // D_1^{i-1}, carried T^{i-1} -> t^{i-1} -> t^i (time, then space
      // transport) and T^{i-1} -> T^i -> t^i (space, then time), ends up
      // turned by gamma_i. By Gauss-Bonnet this is the signed spherical area
      // enclosed by the geodesic quadrilateral, for |gamma_i| < pi.
      const Vec<Number> time_then_space =
        transport<Number>(t_prev, t_next, transported_d1_prev);
      const Vec<Number> space_then_time =
        transport<Number>(reference.tangent_next,
                          t_next,
                          reference.d1_prev_in_space);
      using std::atan2;
      const Number holonomy =
        atan2(dot<Number>(cross<Number>(time_then_space, space_then_time),
                          t_next),
              dot<Number>(time_then_space, space_then_time));

      return {{dot<Number>(binormal, mean_d1),
               dot<Number>(binormal, mean_d2),
               reference.twist + u[next_twist] - u[prev_twist] + holonomy}};
    }
  } // namespace


  std::string
  ClassicHinge::name() const
  {
    return "classic";
  }


  Vector3
  ClassicHinge::strains(const HingeVector    &dofs,
                        const HingeReference &reference) const
  {
    std::array<double, n_hinge_dofs> u;
    for (unsigned int i = 0; i < n_hinge_dofs; ++i)
      u[i] = dofs[i];
    const std::array<double, 3> kappa =
      classic_strains(u, ReferenceVectors(reference));
    return Vector3(kappa[0], kappa[1], kappa[2]);
  }


  void
  ClassicHinge::evaluate(const HingeVector    &dofs,
                         const HingeReference &reference,
                         HingeStrains         &result,
                         const bool            with_hessian) const
  {
    using Gradient = Sacado::Fad::SFad<double, n_hinge_dofs>;
    const ReferenceVectors reference_vectors(reference);

    if (!with_hessian)
      {
        std::array<Gradient, n_hinge_dofs> u;
        for (unsigned int i = 0; i < n_hinge_dofs; ++i)
          u[i] = Gradient(n_hinge_dofs, i, dofs[i]);
        const std::array<Gradient, 3> kappa =
          classic_strains(u, reference_vectors);
        for (unsigned int c = 0; c < 3; ++c)
          {
            result.kappa[c] = kappa[c].val();
            for (unsigned int i = 0; i < n_hinge_dofs; ++i)
              result.gradient(c, i) = kappa[c].dx(i);
          }
        return;
      }

    // Forward over forward: dx(i).dx(j) is d^2 / dx_i dx_j.
    using Hessian = Sacado::Fad::SFad<Gradient, n_hinge_dofs>;
    std::array<Hessian, n_hinge_dofs> u;
    for (unsigned int i = 0; i < n_hinge_dofs; ++i)
      u[i] = Hessian(n_hinge_dofs, i, Gradient(n_hinge_dofs, i, dofs[i]));
    const std::array<Hessian, 3> kappa = classic_strains(u, reference_vectors);
    for (unsigned int c = 0; c < 3; ++c)
      {
        result.kappa[c] = kappa[c].val().val();
        for (unsigned int i = 0; i < n_hinge_dofs; ++i)
          {
            result.gradient(c, i) = kappa[c].dx(i).val();
            for (unsigned int j = 0; j < n_hinge_dofs; ++j)
              result.hessian[c](i, j) = kappa[c].dx(i).dx(j);
          }
        // The two orders of differentiation differ by round-off only.
        result.hessian[c] =
          0.5 * (result.hessian[c] + result.hessian[c].transpose()).eval();
      }
  }
} // namespace rodnet
