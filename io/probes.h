#ifndef RODNET_IO_PROBES_H
#define RODNET_IO_PROBES_H

#include <core/every_entry.h>
#include <core/model.h>
#include <io/probe.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /// The probes of a scene, in the order of their columns.
  using ProbeList = std::vector<std::unique_ptr<Probe>>;

  /// Every registered probe kind with its arguments, unit and meaning, for
  /// help texts: "eigenvalue [mixed]: ...; energy [J]: ...; ...".
  std::string
  probe_kinds_description();

  /**
   * Parses a probe list `name: kind args; name: kind args; ...`, each kind
   * a registered probe kind (probe_kind_registry(): position, reaction,
   * energy, eigenvalue, rotation, moment; probe_kinds_description()).
   * Vertices as in select_vertex(), junctions by name or as a vertex of
   * theirs (select_rotation_target()). Throws std::invalid_argument naming
   * @p entry and the offending probe.
   */
  ProbeList
  parse_probes(const std::string &text,
               const ModelBase   &model,
               const std::string &entry);

  /// Whether any of @p probes reads the lowest eigenvalue of the tangent.
  bool
  needs_lowest_eigenvalue(const ProbeList &probes);

  /// The first of @p probes that reads the Motion of the state, or null.
  const Probe *
  first_motion_probe(const ProbeList &probes);

  /**
   * Makes @p values continuous from @p previous, the values of the step
   * before (empty for the first step, when every reference is 0): each
   * probe's Probe::continued().
   */
  void
  continue_probes(const ProbeList           &probes,
                  const std::vector<double> &previous,
                  std::vector<double>       &values);

  /**
   * Values of @p probes at the converged state @p u of @p model at
   * @p load_factor; @p lowest_eigenvalue is what eigenvalue probes read,
   * @p motion what the energy and momentum probes of dynamics read.
   */
  template <class State>
  std::vector<double>
  evaluate_probes(const ProbeList    &probes,
                  const Model<State> &model,
                  const State        &u,
                  const double        load_factor,
                  const double        lowest_eigenvalue = std::nan(""),
                  const Motion       *motion            = nullptr)
  {
    // Probes read DoFs anywhere in the network (collective on several
    // processes).
    const EveryEntryOf<State>  every_entry(u);
    const ProbedStateOf<State> state(model,
                                     *every_entry,
                                     load_factor,
                                     lowest_eigenvalue,
                                     motion);
    std::vector<double>        values;
    for (const auto &probe : probes)
      values.push_back(probe->value(state));
    return values;
  }

  /**
   * The file `probes.csv`: a header `step,<abscissa>,<probe names>` and one
   * row per converged step, flushed at once so that a later failure loses
   * nothing. The abscissa is the load factor of load stepping
   * ("load_factor") or the time of time stepping ("time"). The solver's
   * checks of each state follow the probes as further columns
   * (@p check_columns, e.g. "stable" and "in_range", 1 or 0).
   */
  class ProbeTable
  {
  public:
    ProbeTable(const std::string              &path,
               const ProbeList                &probes,
               const std::string              &abscissa      = "load_factor",
               const std::vector<std::string> &check_columns = {});

    /// A row: the probes' @p values, then the @p checks.
    void
    add_row(unsigned int               step,
            double                     abscissa,
            const std::vector<double> &values,
            const std::vector<double> &checks = {});

  private:
    std::ofstream file;
  };
} // namespace rodnet

#endif
