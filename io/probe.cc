#include <io/probe.h>

#include <stdexcept>

namespace rodnet
{
  Registry<Probe, const ProbeWords &, const ModelBase &> &
  probe_kind_registry()
  {
    // Built on first use, before any registration can reach it.
    static Registry<Probe, const ProbeWords &, const ModelBase &> registry(
      "probe kind", "probe kinds");
    return registry;
  }

  unsigned int
  probe_component(const ProbeWords &words)
  {
    if (words.second == "x")
      return 0;
    if (words.second == "y")
      return 1;
    if (words.second == "z")
      return 2;
    throw std::invalid_argument(words.context + ": component \"" +
                                words.second + "\" is not x, y or z");
  }

  void
  require_probe_arguments(const ProbeWords  &words,
                          const unsigned int n_arguments,
                          const std::string &syntax)
  {
    const unsigned int given = !words.first.empty() + !words.second.empty() +
                               !words.extra.empty();
    if (given != n_arguments)
      throw std::invalid_argument(words.context + ": expected \"" + syntax +
                                  "\"");
  }
} // namespace rodnet
