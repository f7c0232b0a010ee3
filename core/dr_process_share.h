#ifndef RODNET_CORE_DR_PROCESS_SHARE_H
#define RODNET_CORE_DR_PROCESS_SHARE_H

#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <mpi.h>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * How the processes of a communicator share the elements and DoFs of an
   * explicit, matrix-free model (DrModel) whose vectors every process holds
   * whole.
   *
   * Process p evaluates the p-th of P even ranges of the elements. It
   * *touches* the DoFs of its elements' stencils and keeps those entries of
   * a state up to date; the other entries of its copy go stale, and nothing
   * on p reads them. A DoF is *owned* by the lowest rank that touches it
   * (rank 0 for one that no element touches), and sums over the DoFs
   * (norms, kinetic energy, a load's work) count each DoF on its owner
   * only, then add over the processes. A residual summed element by element
   * is complete on a process's touched DoFs once the DoFs that several
   * processes touch, and the fixed ones, whose reactions every process
   * reads, are added over the processes (add_shared()): that sum sends the
   * process boundary, not the vector. complete() makes every entry valid on
   * every process, for the outputs of a converged step.
   *
   * On one process everything is touched and owned and the sums send
   * nothing.
   */
  class DrProcessShare
  {
  public:
    /// The DoFs of element e's stencil.
    using Stencil = std::function<const unsigned int *(unsigned int e)>;

    /**
     * The share of this process of @p communicator in @p n_elements
     * elements whose stencils of @p stencil_size DoFs @p stencil gives, on
     * @p n_dofs DoFs of which @p fixed are held (their entries of a
     * residual are reactions). Collective.
     */
    DrProcessShare(MPI_Comm                 communicator,
                   unsigned int             n_elements,
                   unsigned int             stencil_size,
                   const Stencil           &stencil,
                   const std::vector<bool> &fixed);

    /// The elements this process evaluates: [first, second).
    std::pair<unsigned int, unsigned int>
    elements() const
    {
      return element_range;
    }

    /// Free DoFs that this process's elements touch, increasing: the
    /// entries an explicit update of this process changes.
    const std::vector<unsigned int> &
    touched_free_dofs() const
    {
      return touched_free;
    }

    /// Free DoFs this process owns, increasing: those it counts in sums.
    const std::vector<unsigned int> &
    owned_free_dofs() const
    {
      return owned_free;
    }

    /// Whether this process owns DoF @p i.
    bool
    owns(const unsigned int i) const
    {
      return owned[i];
    }

    /// @p value added over the processes (collective).
    double
    sum(double value) const;

    /// The entries of @p values added over the processes (collective).
    void
    sum(std::vector<double> &values) const;

    /// Largest @p value over the processes (collective).
    double
    max(double value) const;

    /// Adds the entries of @p v that several processes touch, and the
    /// fixed ones, over the processes (collective): a residual or row sum
    /// assembled from this process's elements becomes complete on its
    /// touched DoFs and on the fixed DoFs.
    void
    add_shared(dealii::Vector<double> &v) const;

    /// Every entry of @p v from its owner, on every process (collective).
    void
    complete(dealii::Vector<double> &v) const;

    /// Whether the communicator has more than one process.
    bool
    distributed() const
    {
      return n_processes > 1;
    }

  private:
    MPI_Comm                              communicator;
    unsigned int                          n_processes;
    std::pair<unsigned int, unsigned int> element_range;
    std::vector<bool>                     owned;
    std::vector<unsigned int>             touched_free;
    std::vector<unsigned int>             owned_free;
    /// DoFs touched by several processes, and the fixed ones: the same
    /// list on every process.
    std::vector<unsigned int> shared;
  };
} // namespace rodnet

#endif
