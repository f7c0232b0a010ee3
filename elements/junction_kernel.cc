#include <elements/central_chart.h>
#include <elements/frame_algebra.h>
#include <elements/junction_kernel.h>
#include <elements/simple_junction.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    using namespace frame_algebra;

    /// The constant part of a junction.
    struct JunctionSegments
    {
      explicit JunctionSegments(const JunctionReference &reference)
          : segment(reference.segment_frame)
          , ghost(reference.ghost_frame)
          , ghost_first(reference.ghost_first)
          , twist(reference.twist)
      {
      }

      SegmentReference segment, ghost;
      bool             ghost_first;
      double           twist;
    };

    /**
     * Spin angle of the ghost segment. By eq. 6, p = P_{t~}^{t~*} R is a
     * rotation about t~*, whose angle is read off its quaternion
     * p = +-(cos(w~/2), sin(w~/2) t~*). This is smooth where t~ -> t~*,
     * unlike eq. 26 whose binormal is undefined there, and it covers the
     * special case of appendix B. Eq. 27 as printed (cos w~ = a,
     * sin w~ = |(b, c, d)|) would give half the angle without its sign:
     * for q = (cos(w/2), sin(w/2) t~*) the spin is w.
     */
    template <typename Number>
    Number
    ghost_spin(const Quat<Number> &rotation,
               const Vec<Number>  &ghost_tangent,
               const Vec<double>  &reference_tangent,
               const GhostSpin     spin)
    {
      const Quat<Number> p =
        transport_quaternion<Number>(ghost_tangent, reference_tangent) *
        rotation;
      const Number sine_half = dot<Number>(p.v, reference_tangent);
      // Eq. 8: half the contraction of the rotation matrix of p with
      // (t~*)_x, 2 Re(p) Im(p).t~*, which is sin(w~).
      if (spin == GhostSpin::small_rotation)
        return 2.0 * p.w * sine_half;
      // The hemisphere Re(p) >= 0 puts w~ in [-pi, pi].
      using std::atan2;
      const double sign = Sacado::ScalarValue<Number>::eval(p.w) < 0 ? -1 : 1;
      const Number y    = sign * sine_half;
      const Number x    = sign * p.w;
      return 2.0 * atan2(y, x);
    }

    /// The strains (L&K end of section 2.3) from the unit tangent of the
    /// physical segment, its twist increment and the junction's unit
    /// rotation.
    template <typename Number>
    std::array<Number, 3>
    junction_strains(const Vec<Number>      &tangent,
                     const Number           &twist,
                     const Quat<Number>     &rotation,
                     const JunctionSegments &reference,
                     const bool              simple,
                     const GhostSpin         spin)
    {
      // Eq. 5.
      const Vec<Number> ghost_tangent =
        rotate(rotation, reference.ghost.tangent);
      const Number ghost_twist =
        ghost_spin(rotation, ghost_tangent, reference.ghost.tangent, spin);

      const SegmentReference &reference_prev =
        reference.ghost_first ? reference.ghost : reference.segment;
      const SegmentReference &reference_next =
        reference.ghost_first ? reference.segment : reference.ghost;
      const Vec<Number> &tangent_prev =
        reference.ghost_first ? ghost_tangent : tangent;
      const Vec<Number> &tangent_next =
        reference.ghost_first ? tangent : ghost_tangent;
      const Number &twist_prev = reference.ghost_first ? ghost_twist : twist;
      const Number &twist_next = reference.ghost_first ? twist : ghost_twist;

      if (simple)
        return simple_strains(
          segment_frame(reference_prev, tangent_prev, twist_prev),
          segment_frame(reference_next, tangent_next, twist_next));
      return classic_strains(
        reference_prev,
        segment_directors(reference_prev, tangent_prev, twist_prev),
        reference_next,
        segment_directors(reference_next, tangent_next, twist_next),
        reference.twist);
    }

    /**
     * The reduced variables of a junction: no strain depends on the length
     * of the physical segment or on the norm of the quaternion, so the 11
     * DoFs enter through 6 variables, the central-chart coordinates of the
     * unit tangent (2) and of the unit rotation (3) about their current
     * values, and the twist increment. Differentiating in these costs
     * about (12 / 7)^2 = 2.9 times less at second order than in the DoFs.
     */
    namespace reduced_junction
    {
      constexpr int n_variables = 6;
      constexpr int tangent     = 0;
      constexpr int twist       = 2;
      constexpr int rotation    = 3;
      using Vector              = Eigen::Matrix<double, n_variables, 1>;
      using Jacobian = Eigen::Matrix<double, n_variables, n_junction_dofs>;
    } // namespace reduced_junction

    /// The charts of a junction's tangent and rotation at its DoFs.
    class JunctionCharts
    {
    public:
      explicit JunctionCharts(const JunctionVector &dofs)
          : edge(dofs.segment<3>(junction_dofs::second_vertex) -
                 dofs.segment<3>(junction_dofs::first_vertex))
          , rotation(dofs.segment<4>(junction_dofs::rotation))
          , twist_increment(dofs[junction_dofs::twist])
      {
      }

      /// The reduced variables at the DoFs.
      reduced_junction::Vector
      variables() const
      {
        reduced_junction::Vector y = reduced_junction::Vector::Zero();
        y[reduced_junction::twist] = twist_increment;
        return y;
      }

      /// The strains as a function of the reduced variables @p y.
      template <typename Number>
      std::array<Number, 3>
      strains(const std::array<Number, reduced_junction::n_variables> &y,
              const JunctionSegments &reference,
              const bool              simple,
              const GhostSpin         spin) const
      {
        const std::array<Number, 3> t =
          edge.unit(&y[reduced_junction::tangent]);
        const std::array<Number, 4> r =
          rotation.unit(&y[reduced_junction::rotation]);
        return junction_strains(Vec<Number>{{t[0], t[1], t[2]}},
                                y[reduced_junction::twist],
                                Quat<Number>{r[0], {{r[1], r[2], r[3]}}},
                                reference,
                                simple,
                                spin);
      }

      /// dy / du (6 x 11).
      reduced_junction::Jacobian
      jacobian() const
      {
        using namespace reduced_junction;
        Jacobian                          j                  = Jacobian::Zero();
        const Eigen::Matrix<double, 2, 3> edge_jacobian      = edge.jacobian();
        j.block<2, 3>(tangent, junction_dofs::second_vertex) = edge_jacobian;
        j.block<2, 3>(tangent, junction_dofs::first_vertex)  = -edge_jacobian;
        j(reduced_junction::twist, junction_dofs::twist)     = 1.0;
        j.block<3, 4>(reduced_junction::rotation, junction_dofs::rotation) =
          rotation.jacobian();
        return j;
      }

      /// sum_k g_k d^2 y_k / du^2 for the weights @p g (the twist enters
      /// linearly; the edge e = x_b - x_a gives the +-1 blocks).
      HingeMatrix
      weighted_second_derivative(
        const Eigen::Matrix<double, 1, reduced_junction::n_variables> &g) const
      {
        using namespace reduced_junction;
        const Matrix3 e =
          edge.weighted_second_derivative(g.segment<2>(tangent).transpose());
        HingeMatrix            h = HingeMatrix::Zero();
        constexpr unsigned int a = junction_dofs::first_vertex;
        constexpr unsigned int b = junction_dofs::second_vertex;
        h.block<3, 3>(a, a)      = e;
        h.block<3, 3>(b, b)      = e;
        h.block<3, 3>(a, b)      = -e;
        h.block<3, 3>(b, a)      = -e;
        h.block<4, 4>(junction_dofs::rotation, junction_dofs::rotation) =
          rotation.weighted_second_derivative(
            g.segment<3>(reduced_junction::rotation).transpose());
        return h;
      }

    private:
      CentralChart<3> edge;
      CentralChart<4> rotation;
      double          twist_increment;
    };

    /// The rotation of a raw quaternion handed to the public functions.
    Quat<double>
    checked_rotation(const Eigen::Vector4d &q, const std::string &function)
    {
      if (!q.allFinite() || !(q.norm() > 0))
        throw std::invalid_argument(
          function + ": the quaternion must be finite and nonzero");
      return unit_quaternion(q[0], q[1], q[2], q[3]);
    }

    /// Refuses what no configuration can mean.
    void
    check_input(const JunctionVector &dofs)
    {
      if (!dofs.allFinite())
        throw std::invalid_argument(
          "junction element: non-finite degrees of freedom");
      if (!(dofs.segment<4>(junction_dofs::rotation).norm() > 0))
        throw std::invalid_argument(
          "junction element: the rotation quaternion is zero");
      if (!((dofs.segment<3>(junction_dofs::second_vertex) -
             dofs.segment<3>(junction_dofs::first_vertex))
              .norm() > 0))
        throw std::invalid_argument(
          "junction element: the physical segment has zero length");
    }
  } // namespace


  JunctionKernel::JunctionKernel(const std::string &measure,
                                 const GhostSpin    spin)
      : simple(measure == "simple")
      , spin(spin)
  {
    if (measure != "simple" && measure != "classic")
      throw std::invalid_argument("unknown junction measure \"" + measure +
                                  "\"; known measures: \"simple\", "
                                  "\"classic\"");
  }


  std::string
  JunctionKernel::name() const
  {
    return simple ? "simple" : "classic";
  }


  Vector3
  JunctionKernel::strains(const JunctionVector    &dofs,
                          const JunctionReference &reference) const
  {
    check_input(dofs);
    if (closed_form())
      return simple_junction::strains(dofs, reference);
    const Vector3 tangent = (dofs.segment<3>(junction_dofs::second_vertex) -
                             dofs.segment<3>(junction_dofs::first_vertex))
                              .normalized();
    const Eigen::Vector4d q =
      dofs.segment<4>(junction_dofs::rotation).normalized();
    const std::array<double, 3> kappa =
      junction_strains(to_vec(tangent),
                       dofs[junction_dofs::twist],
                       Quat<double>{q[0], {{q[1], q[2], q[3]}}},
                       JunctionSegments(reference),
                       simple,
                       spin);
    return Vector3(kappa[0], kappa[1], kappa[2]);
  }


  void
  JunctionKernel::evaluate(const JunctionVector    &dofs,
                           const JunctionReference &reference,
                           JunctionStrains         &result,
                           const bool               with_hessian) const
  {
    check_input(dofs);
    if (closed_form())
      return simple_junction::evaluate(dofs, reference, result, with_hessian);
    const JunctionSegments      reference_segments(reference);
    const JunctionCharts        charts(dofs);
    constexpr int               n = reduced_junction::n_variables;
    Eigen::Matrix<double, 3, n> reduced_gradient;
    std::array<Eigen::Matrix<double, n, n>, 3> reduced_hessian;
    differentiate<3, n>(
      charts.variables(),
      [&](const auto &y) {
        return charts.strains(y, reference_segments, simple, spin);
      },
      result.kappa,
      reduced_gradient,
      with_hessian ? &reduced_hessian : nullptr);

    // The chain rule through y(u).
    const reduced_junction::Jacobian jacobian = charts.jacobian();
    result.gradient.noalias()                 = reduced_gradient * jacobian;
    if (!with_hessian)
      return;
    for (unsigned int c = 0; c < 3; ++c)
      {
        result.hessian[c].noalias() =
          jacobian.transpose() * reduced_hessian[c] * jacobian;
        result.hessian[c] +=
          charts.weighted_second_derivative(reduced_gradient.row(c));
      }
  }


  void
  JunctionKernel::evaluate_weighted(const JunctionVector    &dofs,
                                    const JunctionReference &reference,
                                    const StrainWeights     &weights,
                                    JunctionStrains         &result,
                                    HingeMatrix             &weighted) const
  {
    if (!closed_form())
      return weighted_from_hessians(*this,
                                    dofs,
                                    reference,
                                    weights,
                                    result,
                                    weighted);
    check_input(dofs);
    simple_junction::evaluate_weighted(dofs,
                                       reference,
                                       weights,
                                       result,
                                       weighted);
  }


  Vector3
  JunctionKernel::weighted_gradient(const JunctionVector    &dofs,
                                    const JunctionReference &reference,
                                    const StrainWeights     &weights,
                                    HingeVector             &weighted) const
  {
    if (!closed_form())
      return gradient_from_jacobian(*this, dofs, reference, weights, weighted);
    check_input(dofs);
    return simple_junction::weighted_gradient(dofs,
                                              reference,
                                              weights,
                                              weighted);
  }


  std::vector<std::string>
  junction_measure_names()
  {
    return {"simple", "classic"};
  }


  double
  ghost_spin(const Eigen::Vector4d &q,
             const Vector3         &reference_tangent,
             const GhostSpin        spin)
  {
    const Quat<double> rotation = checked_rotation(q, "ghost_spin");
    const Vec<double>  tangent  = to_vec(reference_tangent.normalized());
    return ghost_spin(rotation, rotate(rotation, tangent), tangent, spin);
  }


  Quaternion
  ghost_frame(const Eigen::Vector4d &q,
              const Quaternion      &reference_frame,
              const GhostSpin        spin)
  {
    const Quat<double>     rotation = checked_rotation(q, "ghost_frame");
    const SegmentReference reference(reference_frame);
    const Vec<double>      tangent = rotate(rotation, reference.tangent);
    const Quat<double>     frame =
      segment_frame(reference,
                    tangent,
                    ghost_spin(rotation, tangent, reference.tangent, spin));
    return Quaternion(frame.w, frame.v[0], frame.v[1], frame.v[2]);
  }
} // namespace rodnet
