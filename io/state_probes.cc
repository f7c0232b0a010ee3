// Probes of the state as a whole: the elastic energy and the lowest
// eigenvalue of the constrained tangent.
#include <io/probe.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// "energy": the total elastic energy.
    class EnergyProbe : public Probe
    {
    public:
      EnergyProbe(const ProbeWords &words, const ModelBase &)
          : Probe(words.name)
      {
        require_probe_arguments(words, 0, "energy");
      }

      std::string
      unit() const override
      {
        return "J";
      }

      double
      value(const ProbedState &state) const override
      {
        return state.elastic_energy();
      }
    };

    /// "eigenvalue": the lowest eigenvalue of the constrained tangent,
    /// which the solver computes at every recorded state.
    class EigenvalueProbe : public Probe
    {
    public:
      EigenvalueProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
      {
        require_probe_arguments(words, 0, "eigenvalue");
        if (!model.has_tangent())
          throw std::invalid_argument(
            words.context + ": dynamic relaxation has no tangent to take the "
                            "eigenvalue of");
      }

      /// The tangent's DoFs are positions and angles.
      std::string
      unit() const override
      {
        return "mixed";
      }

      double
      value(const ProbedState &state) const override
      {
        return state.lowest_eigenvalue;
      }

      bool
      needs_lowest_eigenvalue() const override
      {
        return true;
      }
    };
  } // namespace

  RODNET_REGISTER_PROBE_KIND(EnergyProbe,
                             "energy",
                             "energy [J]: the elastic energy")
  RODNET_REGISTER_PROBE_KIND(EigenvalueProbe,
                             "eigenvalue",
                             "eigenvalue [mixed]: the lowest eigenvalue of "
                             "the constrained tangent (Newton, continuation)")
} // namespace rodnet
