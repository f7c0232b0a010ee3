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
   * distributed over several processes: those whose anchor (their first
   * DoF) it owns, so that every stencil is evaluated once. The process
   * adds the stencil's rows of its own DoFs straight into its matrix and
   * vector, and sends the rows of other processes' DoFs to them
   * (ForeignRows); it counts the stencil's energy.
   */
  struct OwnedStencils
  {
    /// The stencils, in increasing order.
    std::vector<unsigned int> stencils;
  };

  /// The stencils of each of @p families whose anchor (first DoF) is in
  /// @p owned_dofs (see OwnedStencils).
  std::vector<OwnedStencils>
  stencils_anchored(const std::vector<std::unique_ptr<ElementFamily>> &families,
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
   * (as contiguous_share()) whose anchored stencils of @p families cost
   * about as much each (a process evaluates the stencils it anchors:
   * stencils_anchored(); a stencil costs its family's relative_cost());
   * the range of process @p rank. Every range has one DoF at least; the
   * costs of two ranges differ by those of the stencils that share one
   * anchor at most.
   */
  dealii::IndexSet
  balanced_share(const std::vector<std::unique_ptr<ElementFamily>> &families,
                 dealii::types::global_dof_index                    n_dofs,
                 unsigned int                                       n_processes,
                 unsigned int                                       rank);
} // namespace rodnet

#endif
