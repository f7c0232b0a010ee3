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
    /// Peak memory per entry of the tangent's factorization, bytes (see
    /// memory_per_factor_entry()).
    double bytes_per_factor_entry = 0;

    /// DoFs of the RodModel (DofLayout): 3 per vertex, a twist per
    /// segment, 4 quaternion components per junction with a rotation, and
    /// the constraint DoFs.
    double
    dofs() const;

    /**
     * Estimated entries of the sparse LU of the tangent (KLU's L and U,
     * or the band of a rod): 32 per DoF, as along a rod, and the fill
     * that the junctions bring, 53 J^1.35 for J junctions. Fitted to KLU's
     * counts on welded square lattices of 441 to 25921 junctions (2, 4
     * and 10 segments per beam, 1e4 to 6.7e5 DoFs) within 4%; smaller
     * lattices are overestimated (by 30% at 36 junctions). The exponent
     * is that of planar networks; a network that fills space fills more.
     * MUMPS, which "auto" takes from 30000 DoFs, stores one triangle, about
     * half these entries, but with its fronts its peak memory came within
     * 10% of KLU's (doc/performance.md): the estimate stays KLU's.
     */
    double
    factor_entries() const;

    /// Estimated peak memory of a run: a fixed 200 MB of libraries and
    /// MPI, bytes_per_dof per DoF and bytes_per_factor_entry per entry of
    /// the factorization.
    double
    memory() const;
  };

  /**
   * Peak memory per DoF, besides the factorizations (see
   * memory_per_factor_entry()): fitted with it to the peak resident
   * memory of runs of straight rods (1.2e5 and 4e5 DoFs) and welded
   * square lattices (4e4 to 6.7e5 DoFs), Release build, VTU output on
   * (doc/performance.md, "Memory estimate"): Newton 1.3 kB and dynamic
   * time stepping 0.9 kB per DoF; quasi-static time stepping as Newton;
   * dynamic relaxation 0.25 kB (it factorizes nothing); VTU output adds
   * 0.15 kB. @p static_checks: Newton or quasi-static steps, whose states
   * are checked for stability.
   */
  double
  memory_per_dof(bool static_checks, bool time_stepping, bool vtu);

  /**
   * Peak memory per entry of the tangent's factorization
   * (ProblemSize::factor_entries()), fitted as memory_per_dof(): 16 bytes
   * with the stability check of every converged state (KLU's L and U, 14
   * bytes an entry, and the sparse LDL^T of the check, half as many
   * entries), 28 bytes for dynamic time stepping, none for dynamic
   * relaxation.
   */
  double
  memory_per_factor_entry(bool static_checks, bool time_stepping);

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
