#ifndef RODNET_IO_PROBLEM_SIZE_H
#define RODNET_IO_PROBLEM_SIZE_H

#include <string>

namespace rodnet
{
  /**
   * The size of a model before it is built, in doubles (counts of a model
   * too big to build may overflow an unsigned int), and the memory a run
   * of it takes, so that what cannot fit is refused up front instead of
   * ending in std::bad_alloc after minutes.
   */
  struct ProblemSize
  {
    double rods     = 0;
    double segments = 0;
    /// Triangulation vertices: every rod end has its own, also at a
    /// junction.
    double vertices = 0;
    /// Junctions with a rotation (pinned ones have none).
    double junctions = 0;
    /// DoFs of constraints (DofLayout): a Lagrange multiplier per segment
    /// of an inextensible rod, three more per hinge of a developable
    /// ribbon.
    double constraint_dofs = 0;
    /// Peak memory per DoF of the solution method, bytes (see
    /// memory_per_dof()).
    double bytes_per_dof = 0;

    /// DoFs of the RodModel (DofLayout): 3 per vertex, a twist per
    /// segment, 4 quaternion components per junction with a rotation, and
    /// the constraint DoFs.
    double
    dofs() const;

    /// Estimated peak memory of a run: a fixed 200 MB of libraries and
    /// MPI, and bytes_per_dof per DoF.
    double
    memory() const;
  };

  /**
   * Peak memory per DoF measured on straight rods and a square lattice of
   * 1e5 to 4e6 DoFs (Release build): Newton 1.6 kB (the tangent, its
   * unconstrained copy, KLU's factors: 0.62 kB; the sparse LDL^T that
   * checks the stability of every converged state: 1 kB), dynamic time
   * stepping 0.95 kB (the mass matrix and the integrator's vectors
   * besides), quasi-static time stepping as Newton, dynamic relaxation
   * 0.24 kB; VTU output adds 0.13 kB. The values returned round these up.
   * @p static_checks: Newton or quasi-static steps, whose states are
   * checked for stability.
   */
  double
  memory_per_dof(bool static_checks, bool time_stepping, bool vtu);

  /// @p n_rods rods of @p n_segments segments in all, @p n_closed of them
  /// closed (a closed rod has as many vertices as segments).
  ProblemSize
  rods_size(double n_rods, double n_segments, double n_closed = 0);

  /// A network of @p n_beams beams tied at @p n_junctions junctions with
  /// a rotation, each beam a rod of @p segments_per_beam segments.
  ProblemSize
  network_size(double n_beams, double n_junctions, double segments_per_beam);

  /// MemAvailable of /proc/meminfo in bytes; 0 where it cannot be read.
  double
  available_memory();

  /// "1.5 GB", "230 MB".
  std::string
  format_bytes(double bytes);

  /**
   * Throws std::invalid_argument naming @p entry (the entry that sets the
   * size) when the estimated memory of @p size exceeds @p available bytes
   * (nothing is checked when @p available is 0, unknown).
   */
  void
  check_memory(const ProblemSize &size,
               double             available,
               const std::string &entry);
} // namespace rodnet

#endif
