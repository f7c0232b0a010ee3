#ifndef RODNET_CORE_DOF_VALUES_H
#define RODNET_CORE_DOF_VALUES_H

#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_vector.h>

#include <stdexcept>
#include <string>

namespace rodnet
{
  /**
   * Read access to the entries of a DoF vector by global index. On one
   * process, where the vector's map is contiguous from 0, entries are read
   * straight from its storage. On several, the process's own contiguous
   * share is read straight from its place in the storage too, and only the
   * ghost entries are looked up in the vector's map: a ghosted vector's map
   * lists the ghosts below the share first, which leaves Epetra a hash
   * lookup for every entry (8 % of the second process's time on the welded
   * lattice of 1.1e6 DoFs, doc/performance.md). The storage checks are made
   * once, when the reader is made from the vector (implicitly, so that a
   * function taking a DofValues takes the vector too): an assembly makes
   * one for all its stencils, not one per entry.
   */
  class DofValues
  {
  public:
    DofValues(const dealii::TrilinosWrappers::MPI::Vector &u)
        : u(&u)
        , values(contiguous_storage(u))
    {
      if (values == nullptr)
        find_own_share();
    }

    /// The entry of global DoF @p i (locally owned or ghost). Throws
    /// std::logic_error where this process holds no entry @p i (a vector
    /// without the ghosts a stencil reads): deal.II's Release library
    /// would read 0 there.
    double
    operator[](const dealii::types::global_dof_index i) const
    {
      if (values != nullptr)
        return values[i];
      // Unsigned: an index below the share wraps past its size.
      if (i - share_begin < share_size)
        return share_values[i - share_begin];
      const int local = u->trilinos_vector().Map().LID(
        static_cast<dealii::TrilinosWrappers::types::int_type>(i));
      if (local < 0)
        throw std::logic_error(
          "DoF " + std::to_string(i) +
          " is not held on this process: the state given to a model on "
          "several processes must have the ghost entries its stencils read");
      return u->trilinos_vector()[0][local];
    }

  private:
    static const double *
    contiguous_storage(const dealii::TrilinosWrappers::MPI::Vector &u)
    {
      const Epetra_BlockMap &map = u.trilinos_vector().Map();
      return map.LinearMap() && map.MinMyGID() == 0 &&
                 map.NumMyElements() == map.NumGlobalElements() ?
               u.trilinos_vector()[0] :
               nullptr;
    }

    /// Where the vector's own entries form one contiguous range, laid out
    /// in order in its storage: that range and its place in the storage.
    void
    find_own_share()
    {
      const dealii::IndexSet owned = u->locally_owned_elements();
      if (!owned.is_contiguous() || owned.n_elements() == 0)
        return;
      const dealii::types::global_dof_index begin = owned.nth_index_in_set(0);
      const dealii::types::global_dof_index size  = owned.n_elements();
      const Epetra_BlockMap                &map   = u->trilinos_vector().Map();
      using Index     = dealii::TrilinosWrappers::types::int_type;
      const int first = map.LID(static_cast<Index>(begin));
      const int last  = map.LID(static_cast<Index>(begin + size - 1));
      if (first < 0 || last - first + 1 != static_cast<int>(size))
        return;
      share_begin  = begin;
      share_size   = size;
      share_values = u->trilinos_vector()[0] + first;
    }

    const dealii::TrilinosWrappers::MPI::Vector *u;
    /// The storage indexed by global DoF, or null where it is not.
    const double *values;
    /// The own share's first DoF, its size and its place in the storage.
    dealii::types::global_dof_index share_begin  = 0;
    dealii::types::global_dof_index share_size   = 0;
    const double                   *share_values = nullptr;
  };
} // namespace rodnet

#endif
