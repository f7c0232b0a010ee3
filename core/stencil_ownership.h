#ifndef RODNET_CORE_STENCIL_OWNERSHIP_H
#define RODNET_CORE_STENCIL_OWNERSHIP_H

#include <deal.II/base/index_set.h>

#include <core/element_family.h>

#include <memory>
#include <vector>

namespace rodnet
{
  /**
   * The stencils of one family that a process evaluates when the DoFs are
   * distributed over several processes. A process evaluates every stencil
   * that couples one of its DoFs and adds the stencil's rows of its own
   * DoFs only, so that no matrix row is written by another process and the
   * assembly needs no communication but the ghost values of the state. A
   * stencil on the border of two processes is evaluated by both, each
   * keeping its rows; its energy is counted by one, the owner of its
   * anchor (its first DoF).
   */
  struct OwnedStencils
  {
    /// The stencils, in increasing order.
    std::vector<unsigned int> stencils;
    /// Per entry of stencils: whether this process owns the anchor, and so
    /// counts the stencil's energy.
    std::vector<bool> counts_energy;
  };

  /// The stencils of each of @p families that couple a DoF of
  /// @p owned_dofs (see OwnedStencils).
  std::vector<OwnedStencils>
  stencils_coupling(const std::vector<std::unique_ptr<ElementFamily>> &families,
                    const dealii::IndexSet &owned_dofs);

  /// @p owned_dofs and every DoF that @p stencils couple: the entries of
  /// the state a process reads (the ghosts of its vectors).
  dealii::IndexSet
  dofs_read_by(const std::vector<std::unique_ptr<ElementFamily>> &families,
               const std::vector<OwnedStencils>                  &stencils,
               const dealii::IndexSet                            &owned_dofs);

  /**
   * The DoFs 0 .. @p n_dofs - 1 cut into @p n_processes contiguous ranges
   * of sizes that differ by one at most; the range of process @p rank.
   * Trilinos' maps and MUMPS' distributed input take contiguous rows.
   */
  dealii::IndexSet
  contiguous_share(dealii::types::global_dof_index n_dofs,
                   unsigned int                    n_processes,
                   unsigned int                    rank);
  /**
   * The DoFs 0 .. @p n_dofs - 1 cut into @p n_processes contiguous ranges
   * (as contiguous_share()) that evaluate about as many stencils of
   * @p families each (a process evaluates every stencil that couples one
   * of its DoFs: stencils_coupling()); the range of process @p rank. The
   * junctions' quaternions are numbered after all positions and twists,
   * so the last range, which holds them and evaluates every junction
   * stencil, is the shortest. Every range has one DoF at least. The
   * count is exact for ranges longer than a sixteenth of an even share.
   */
  dealii::IndexSet
  balanced_share(const std::vector<std::unique_ptr<ElementFamily>> &families,
                 dealii::types::global_dof_index                    n_dofs,
                 unsigned int                                       n_processes,
                 unsigned int                                       rank);
} // namespace rodnet

#endif
