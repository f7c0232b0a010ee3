#include <elements/frame_algebra.h>
#include <elements/junction_kernel.h>

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

    template <typename Number>
    std::array<Number, 3>
    junction_strains(const std::array<Number, n_junction_dofs> &u,
                     const JunctionSegments                    &reference,
                     const bool                                 simple,
                     const GhostSpin                            spin)
    {
      const auto position = [&u](const int offset) {
        return Vec<Number>{{u[offset], u[offset + 1], u[offset + 2]}};
      };
      const Vec<Number> tangent =
        unit_edge(position(junction_dofs::first_vertex),
                  position(junction_dofs::second_vertex));

      constexpr unsigned int q = junction_dofs::rotation;
      const Quat<Number>     rotation =
        unit_quaternion(u[q], u[q + 1], u[q + 2], u[q + 3]);
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
      const Number &twist_prev =
        reference.ghost_first ? ghost_twist : u[junction_dofs::twist];
      const Number &twist_next =
        reference.ghost_first ? u[junction_dofs::twist] : ghost_twist;

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
    const JunctionSegments reference_segments(reference);
    return evaluate_values<3, n_junction_dofs>(dofs, [&](const auto &u) {
      return junction_strains(u, reference_segments, simple, spin);
    });
  }


  void
  JunctionKernel::evaluate(const JunctionVector    &dofs,
                           const JunctionReference &reference,
                           JunctionStrains         &result,
                           const bool               with_hessian) const
  {
    check_input(dofs);
    const JunctionSegments reference_segments(reference);
    differentiate<3, n_junction_dofs>(
      dofs,
      [&](const auto &u) {
        return junction_strains(u, reference_segments, simple, spin);
      },
      result.kappa,
      result.gradient,
      with_hessian ? &result.hessian : nullptr);
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
