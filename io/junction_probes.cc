// Probes of a junction's rotation: its angle about an axis and the moment
// it transmits (or the reaction moment of a clamped rod end).
#include <deal.II/base/utilities.h>

#include <core/vertex_selector.h>
#include <io/probe.h>

#include <cmath>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /**
     * The junction named by a probe's first word: it must carry a rotation
     * of its own; a clamped rod end (a clamp, no junction) is accepted where
     * @p clamp_allowed, and then its support is kept. Throws naming the
     * probe otherwise.
     */
    struct ProbedJunction
    {
      ProbedJunction(const ProbeWords  &words,
                     const ModelBase   &model,
                     const std::string &syntax,
                     const bool         clamp_allowed)
      {
        require_probe_arguments(words, 2, syntax);
        const RotationTarget target =
          select_rotation_target(model.network(), words.first, words.context);
        if (!model.has_junction_rotations())
          throw std::invalid_argument(
            words.context + ": junction rotations and moments are those of "
                            "the discrete rods' quaternions; the dynamic "
                            "relaxation element has none");
        const Support *clamp = model.clamp_at(target.vertex);
        if (clamp_allowed && clamp != nullptr)
          clamp_support = clamp->name;
        else if (!target.junction)
          throw std::invalid_argument(
            words.context + ": \"" + words.first + "\" is no junction" +
            (clamp_allowed ? " or clamped end" : ""));
        else if (!model.has_rotation(*target.junction))
          throw std::invalid_argument(words.context + ": junction \"" +
                                      words.first +
                                      "\" is pinned and has no rotation");
        junction = target.junction.value_or(0);
      }

      unsigned int junction;
      /// The clamp of a rod end, for a moment probe there.
      std::string clamp_support;
    };

    /// The unit axis "ax,ay,az" of a rotation probe.
    Vector3
    probe_axis(const ProbeWords &words)
    {
      Vector3    axis;
      const auto xyz = dealii::Utilities::split_string_list(words.second, ',');
      try
        {
          if (xyz.size() != 3)
            throw std::invalid_argument("");
          const auto v = dealii::Utilities::string_to_double(xyz);
          axis         = Vector3(v[0], v[1], v[2]);
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(words.context + ": the axis \"" +
                                      words.second +
                                      "\" is not three numbers ax,ay,az");
        }
      if (!(axis.norm() > 0))
        throw std::invalid_argument(words.context + ": the axis is zero");
      return axis.normalized();
    }

    /// "rotation <junction> <ax>,<ay>,<az>": the angle of the junction's
    /// rotation about the axis, continuous over the steps.
    class RotationProbe : public Probe
    {
    public:
      RotationProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
          , junction(
              ProbedJunction(words, model, "rotation <junction> <ax>,<ay>,<az>", false)
                .junction)
          , axis(probe_axis(words))
      {
      }

      std::string
      unit() const override
      {
        return "rad";
      }

      /// The twist part of the rotation about the axis (swing-twist split):
      /// exact for rotations about the axis, in (-2 pi, 2 pi].
      double
      value(const ProbedState &state) const override
      {
        const Quaternion q = state.junction_rotation(junction);
        return 2.0 * std::atan2(q.vec().dot(axis), q.w());
      }

      /// A rotation is known modulo one turn: the value nearest the one of
      /// the step before, which holds as long as the rotation changes by
      /// less than half a turn between recorded steps.
      double
      continued(const double value, const double previous) const override
      {
        const double turn = 2 * M_PI;
        return value + turn * std::round((previous - value) / turn);
      }

    private:
      unsigned int junction;
      Vector3      axis;
    };

    /// "moment <junction> <x|y|z>": a component of the moment a junction's
    /// rotation transmits, or of a clamped rod end's reaction moment about
    /// its end vertex.
    class MomentProbe : public Probe
    {
    public:
      MomentProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
          , target(words, model, "moment <junction> <x|y|z>", true)
          , component(probe_component(words))
      {
      }

      std::string
      unit() const override
      {
        return "N m";
      }

      double
      value(const ProbedState &state) const override
      {
        return (target.clamp_support.empty() ?
                  state.reaction_moment(target.junction) :
                  state.reaction_moment(
                    state.model.support(target.clamp_support)))[component];
      }

    private:
      ProbedJunction target;
      unsigned int   component;
    };
  } // namespace

  RODNET_REGISTER_PROBE_KIND(RotationProbe,
                             "rotation",
                             "rotation <junction> <ax>,<ay>,<az> [rad]: the "
                             "angle of a junction's rotation about the axis, "
                             "continuous over the steps")
  RODNET_REGISTER_PROBE_KIND(MomentProbe,
                             "moment",
                             "moment <junction> <x|y|z> [N m]: the moment a "
                             "junction transmits, or the reaction moment of "
                             "a clamped rod end")
} // namespace rodnet
