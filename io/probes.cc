#include <deal.II/base/utilities.h>

#include <base/mpi_session.h>
#include <io/probes.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  std::string
  probe_kinds_description()
  {
    const auto &registry = probe_kind_registry();
    std::string text;
    for (const std::string &kind : registry.names())
      text += (text.empty() ? "" : "; ") + registry.description(kind);
    return text;
  }

  namespace
  {
    /// The name of the probe @p item; throws unless it is a name without
    /// spaces, commas or quotes and not among @p probes yet.
    std::string
    probe_name(const std::string &item,
               const std::string &context,
               const ProbeList   &probes)
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos)
        throw std::invalid_argument(context + ": expected \"name: kind ...\"");
      const std::string name = dealii::Utilities::trim(item.substr(0, colon));
      if (name.empty() || name.find_first_of(",\" ") != std::string::npos)
        throw std::invalid_argument(context +
                                    ": the name must be non-empty "
                                    "without spaces, commas or quotes");
      for (const auto &p : probes)
        if (p->name() == name)
          throw std::invalid_argument(context + ": the name is used twice");
      return name;
    }

    /// The words of probe @p item of @p entry.
    ProbeWords
    probe_words(const std::string &item,
                const std::string &entry,
                const ProbeList   &probes)
    {
      ProbeWords words;
      words.entry   = entry;
      words.context = "entry \"" + entry + "\", probe \"" + item + "\"";
      words.name    = probe_name(item, words.context, probes);
      std::istringstream stream(item.substr(item.find(':') + 1));
      stream >> words.kind >> words.first >> words.second >> words.extra;
      // A kind of two words ("kinetic energy", "linear momentum").
      const std::string two_words = words.kind + " " + words.first;
      if (probe_kind_registry().contains(two_words))
        {
          std::string rest;
          stream >> rest;
          words = {words.name,
                   words.entry,
                   words.context,
                   two_words,
                   words.second,
                   words.extra,
                   rest};
        }
      return words;
    }
  } // namespace

  ProbeList
  parse_probes(const std::string &text,
               const ModelBase   &model,
               const std::string &entry)
  {
    const auto &registry = probe_kind_registry();
    ProbeList   probes;
    for (const std::string &item :
         dealii::Utilities::split_string_list(text, ';'))
      {
        const ProbeWords words = probe_words(item, entry, probes);
        if (!registry.contains(words.kind))
          {
            // Each kind's syntax and unit, the part of its description
            // before the colon.
            std::string known;
            for (const std::string &kind : registry.names())
              {
                const std::string &description = registry.description(kind);
                known += (known.empty() ? "" : ", ") +
                         description.substr(0, description.find(": "));
              }
            throw std::invalid_argument(words.context +
                                        ": unknown probe kind \"" + words.kind +
                                        "\"; known: " + known);
          }
        probes.push_back(registry.create(words.kind, words, model));
      }
    return probes;
  }

  bool
  needs_lowest_eigenvalue(const ProbeList &probes)
  {
    for (const auto &probe : probes)
      if (probe->needs_lowest_eigenvalue())
        return true;
    return false;
  }

  const Probe *
  first_motion_probe(const ProbeList &probes)
  {
    for (const auto &probe : probes)
      if (probe->needs_motion())
        return probe.get();
    return nullptr;
  }

  void
  continue_probes(const ProbeList           &probes,
                  const std::vector<double> &previous,
                  std::vector<double>       &values)
  {
    for (std::size_t i = 0; i < probes.size(); ++i)
      values[i] =
        probes[i]->continued(values[i], previous.empty() ? 0.0 : previous[i]);
  }

  ProbeTable::ProbeTable(const std::string              &path,
                         const ProbeList                &probes,
                         const std::string              &abscissa,
                         const std::vector<std::string> &check_columns)
  {
    if (!writes_outputs())
      return;
    file.open(path);
    if (!file)
      throw std::runtime_error("cannot write the probe file " + path);
    file << "step," << abscissa;
    for (const auto &p : probes)
      file << ',' << p->name();
    for (const std::string &name : check_columns)
      file << ',' << name;
    file << std::endl;
  }

  void
  ProbeTable::add_row(const unsigned int         step,
                      const double               abscissa,
                      const std::vector<double> &values,
                      const std::vector<double> &checks)
  {
    file << step << ',' << std::setprecision(10) << abscissa;
    for (const double v : values)
      file << ',' << std::setprecision(12) << v;
    for (const double c : checks)
      file << ',' << c;
    file << std::endl;
  }
} // namespace rodnet
