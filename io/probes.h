#ifndef RODNET_IO_PROBES_H
#define RODNET_IO_PROBES_H

#include <core/dr_model.h>
#include <core/rod_model.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace rodnet
{
  /// One scalar recorded at every converged step.
  struct Probe
  {
    enum class Kind
    {
      position,   ///< a component of a vertex's current position
      reaction,   ///< a component of a support's reaction force
      energy,     ///< the total elastic energy
      eigenvalue, ///< the lowest eigenvalue of the constrained tangent
      rotation,   ///< a junction's rotation angle about an axis
      moment      ///< a component of a junction's reaction moment
    };
    std::string  name;
    Kind         kind;
    unsigned int vertex    = 0;
    unsigned int component = 0;
    /// For reactions, and moments of a clamped rod end: the support's name.
    std::string  support;
    unsigned int junction = 0; ///< for rotations and moments of junctions
    Vector3      axis     = Vector3::UnitZ(); ///< for rotations
  };

  /// The unit of a probe kind's values: "m", "N", "J", "rad", "N m", and
  /// "mixed" for the eigenvalue (the tangent's DoFs are positions and
  /// angles).
  std::string
  unit(Probe::Kind kind);

  /// Every probe kind with its arguments and unit, for help texts and
  /// messages: "position <vertex> <x|y|z> [m], reaction ...".
  std::string
  probe_kinds_description();

  /**
   * Makes the rotation probes among @p values continuous from @p previous
   * (the values of the step before, empty for the first step, when the
   * reference is 0): a rotation is known modulo one turn, so the value
   * nearest the previous one is taken. This holds as long as a probed
   * rotation changes by less than half a turn between recorded steps.
   */
  void
  unwrap_rotations(const std::vector<Probe>  &probes,
                   const std::vector<double> &previous,
                   std::vector<double>       &values);

  /**
   * Parses a probe list `name: kind args; name: kind args; ...` with kinds
   * `position <vertex> <x|y|z>`, `reaction <vertex> <x|y|z>` (the support
   * holding that vertex), `energy`, `eigenvalue`, `rotation <junction>
   * <ax>,<ay>,<az>` (angle of the junction's rotation about the axis, rad,
   * in (-2 pi, 2 pi]; see unwrap_rotations()) and `moment <junction>
   * <x|y|z>` (reaction moment, N m; also of a clamped rod end, about its
   * end vertex). Vertices as in select_vertex(), junctions by name or as a
   * vertex of theirs (select_rotation_target()). @p model is a RodModel or a
   * DrModel (which has no rotations, moments or eigenvalue). Throws
   * std::invalid_argument naming @p entry and the offending probe.
   */
  template <class Model>
  std::vector<Probe>
  parse_probes(const std::string &text,
               const Model       &model,
               const std::string &entry);

  /**
   * Values of @p probes at the converged state @p u of @p model (a
   * RodModel or a DrModel) at @p load_factor; @p lowest_eigenvalue is the
   * value of eigenvalue probes (which parse_probes() allows only for a
   * model with a tangent).
   */
  template <class State>
  std::vector<double>
  evaluate_probes(const std::vector<Probe> &probes,
                  const Model<State>       &model,
                  const State              &u,
                  double                    load_factor,
                  double                    lowest_eigenvalue = std::nan(""));

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
               const std::vector<Probe>       &probes,
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
