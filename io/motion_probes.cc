// Probes of a model in motion (dynamic time stepping): its kinetic,
// potential and total energy and its linear and angular momentum, read from
// ProbedState::motion (core/motion.h).
#include <io/probe.h>

#include <functional>

namespace rodnet
{
  namespace
  {
    /// A scalar of the Motion: @p read of it, in @p unit.
    class MotionProbe : public Probe
    {
    public:
      MotionProbe(const ProbeWords                     &words,
                  std::string                           unit,
                  std::function<double(const Motion &)> read)
          : Probe(words.name)
          , probe_unit(std::move(unit))
          , read(std::move(read))
      {
      }

      std::string
      unit() const override
      {
        return probe_unit;
      }

      double
      value(const ProbedState &state) const override
      {
        return read(*state.motion);
      }

      bool
      needs_motion() const override
      {
        return true;
      }

    private:
      std::string                           probe_unit;
      std::function<double(const Motion &)> read;
    };

    /// The component x, y or z that follows the kind of @p words
    /// ("linear momentum x").
    unsigned int
    motion_component(const ProbeWords &words, const std::string &syntax)
    {
      require_probe_arguments(words, 1, syntax);
      ProbeWords component = words;
      component.second     = words.first;
      return probe_component(component);
    }

    /// An energy of the Motion, in J: a probe without arguments, whose
    /// syntax is its kind ("kinetic energy", the keyword it is registered
    /// under and created by).
    template <double (*energy)(const Motion &)>
    class EnergyProbe : public MotionProbe
    {
    public:
      EnergyProbe(const ProbeWords &words, const ModelBase &)
          : MotionProbe(words, "J", energy)
      {
        require_probe_arguments(words, 0, words.kind);
      }
    };

    /// "kinetic energy": 1/2 v.Mv.
    double
    kinetic_energy_of(const Motion &m)
    {
      return m.kinetic_energy;
    }

    /// "potential energy": Pi, stored energy minus the dead loads' work.
    double
    potential_energy_of(const Motion &m)
    {
      return m.potential_energy;
    }

    /// "total energy": 1/2 v.Mv + Pi.
    double
    total_energy_of(const Motion &m)
    {
      return m.kinetic_energy + m.potential_energy;
    }

    using KineticEnergyProbe   = EnergyProbe<kinetic_energy_of>;
    using PotentialEnergyProbe = EnergyProbe<potential_energy_of>;
    using TotalEnergyProbe     = EnergyProbe<total_energy_of>;

    /// "linear momentum <x|y|z>": a component of the sum of M v.
    class LinearMomentumProbe : public MotionProbe
    {
    public:
      LinearMomentumProbe(const ProbeWords &words, const ModelBase &)
          : MotionProbe(words,
                        "N s",
                        [c =
                           motion_component(words, "linear momentum <x|y|z>")](
                          const Motion &m) { return m.linear_momentum[c]; })
      {
      }
    };

    /// "angular momentum <x|y|z>": a component of sum x_i x (M v)_i.
    class AngularMomentumProbe : public MotionProbe
    {
    public:
      AngularMomentumProbe(const ProbeWords &words, const ModelBase &)
          : MotionProbe(words,
                        "N m s",
                        [c =
                           motion_component(words, "angular momentum <x|y|z>")](
                          const Motion &m) { return m.angular_momentum[c]; })
      {
      }
    };
  } // namespace

  RODNET_REGISTER_PROBE_KIND(KineticEnergyProbe,
                             "kinetic energy",
                             "kinetic energy [J]: 1/2 v.Mv (dynamics)")
  RODNET_REGISTER_PROBE_KIND(PotentialEnergyProbe,
                             "potential energy",
                             "potential energy [J]: elastic minus load work "
                             "(dynamics)")
  RODNET_REGISTER_PROBE_KIND(TotalEnergyProbe,
                             "total energy",
                             "total energy [J]: kinetic plus potential "
                             "(dynamics)")
  RODNET_REGISTER_PROBE_KIND(LinearMomentumProbe,
                             "linear momentum",
                             "linear momentum <x|y|z> [N s]: sum of M v "
                             "(dynamics)")
  RODNET_REGISTER_PROBE_KIND(AngularMomentumProbe,
                             "angular momentum",
                             "angular momentum <x|y|z> [N m s]: about the "
                             "origin (dynamics)")
} // namespace rodnet
