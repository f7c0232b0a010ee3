#include <elements/classic_hinge.h>
#include <elements/frame_algebra.h>

namespace rodnet
{
  namespace
  {
    using namespace frame_algebra;

    using namespace hinge_offsets;

    /// The constant part of the hinge: its two reference frames and twist.
    struct HingeSegments
    {
      explicit HingeSegments(const HingeReference &reference)
          : prev(reference.frame_prev)
          , next(reference.frame_next)
          , twist(reference.twist)
      {
      }

      SegmentReference prev, next;
      double           twist;
    };

    template <typename Number>
    std::array<Number, 3>
    hinge_strains(const std::array<Number, n_hinge_dofs> &u,
                  const HingeSegments                    &reference)
    {
      const auto position = [&u](const int offset) {
        return Vec<Number>{{u[offset], u[offset + 1], u[offset + 2]}};
      };
      const Vec<Number> t_prev =
        unit_edge(position(prev_vertex), position(vertex));
      const Vec<Number> t_next =
        unit_edge(position(vertex), position(next_vertex));
      return classic_strains(
        reference.prev,
        segment_directors(reference.prev, t_prev, u[prev_twist]),
        reference.next,
        segment_directors(reference.next, t_next, u[next_twist]),
        reference.twist);
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
    const HingeSegments reference_segments(reference);
    return evaluate_values<3, n_hinge_dofs>(
      dofs,
      [&reference_segments](const auto &u) {
        return hinge_strains(u, reference_segments);
      });
  }


  void
  ClassicHinge::evaluate(const HingeVector    &dofs,
                         const HingeReference &reference,
                         HingeStrains         &result,
                         const bool            with_hessian) const
  {
    const HingeSegments reference_segments(reference);
    differentiate<3, n_hinge_dofs>(
      dofs,
      [&reference_segments](const auto &u) {
        return hinge_strains(u, reference_segments);
      },
      result.kappa,
      result.gradient,
      with_hessian ? &result.hessian : nullptr);
  }

  RODNET_REGISTER_HINGE_KERNEL(
    ClassicHinge,
    "classic",
    "Lestringant & Kochmann (2020): curvature binormal and reference twist")
} // namespace rodnet
