// Probes of a vertex: its position and the reaction of the support that
// holds it.
#include <core/vertex_selector.h>
#include <io/probe.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// "position <vertex> <x|y|z>": a component of the vertex's current
    /// position.
    class PositionProbe : public Probe
    {
    public:
      PositionProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
      {
        require_probe_arguments(words, 2, "position <vertex> <x|y|z>");
        vertex    = select_vertex(model.network(), words.first, words.entry);
        component = probe_component(words);
      }

      std::string
      unit() const override
      {
        return "m";
      }

      double
      value(const ProbedState &state) const override
      {
        return state.position(vertex)[component];
      }

    private:
      unsigned int vertex;
      unsigned int component;
    };

    /// "reaction <vertex> <x|y|z>": a component of the reaction force of the
    /// first support that fixes that component of the vertex.
    class ReactionProbe : public Probe
    {
    public:
      ReactionProbe(const ProbeWords &words, const ModelBase &model)
          : Probe(words.name)
      {
        require_probe_arguments(words, 2, "reaction <vertex> <x|y|z>");
        const unsigned int vertex =
          select_vertex(model.network(), words.first, words.entry);
        component = probe_component(words);
        for (const Support &s : model.supports())
          for (unsigned int k = 0; k < s.vertices.size(); ++k)
            if (s.vertices[k] == vertex && s.fixed[k][component] &&
                support.empty())
              support = s.name;
        if (support.empty())
          throw std::invalid_argument(
            words.context + ": no support fixes component " + words.second +
            " of vertex \"" + words.first + "\"");
      }

      std::string
      unit() const override
      {
        return "N";
      }

      double
      value(const ProbedState &state) const override
      {
        return state.reaction(state.model.support(support))[component];
      }

    private:
      std::string  support;
      unsigned int component;
    };
  } // namespace

  RODNET_REGISTER_PROBE_KIND(PositionProbe,
                             "position",
                             "position <vertex> <x|y|z> [m]: a component of "
                             "the vertex's current position")
  RODNET_REGISTER_PROBE_KIND(ReactionProbe,
                             "reaction",
                             "reaction <vertex> <x|y|z> [N]: a component of "
                             "the reaction force of the support that holds "
                             "it")
} // namespace rodnet
