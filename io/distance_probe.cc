// The distance between two vertices: the end-to-end distance of a rod, the
// span of an arch, the opening of a gap.
#include <core/vertex_selector.h>
#include <io/probe.h>

namespace rodnet
{
  namespace
  {
    /// "distance <vertex> <vertex>": the current distance between them.
    class DistanceProbe : public Probe
    {
    public:
      DistanceProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
      {
        require_probe_arguments(words, 2, "distance <vertex> <vertex>");
        a = select_vertex(model.network(), words.first, words.entry);
        b = select_vertex(model.network(), words.second, words.entry);
      }

      std::string
      unit() const override
      {
        return "m";
      }

      double
      value(const ProbedState &state) const override
      {
        return (state.position(a) - state.position(b)).norm();
      }

    private:
      unsigned int a;
      unsigned int b;
    };
  } // namespace

  RODNET_REGISTER_PROBE_KIND(DistanceProbe,
                             "distance",
                             "distance <vertex> <vertex> [m]: the current "
                             "distance between two vertices")
} // namespace rodnet
