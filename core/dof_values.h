#ifndef RODNET_CORE_DOF_VALUES_H
#define RODNET_CORE_DOF_VALUES_H

#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_vector.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Read access to the entries of a DoF vector by global index. On one
   * process, where the vector's map is contiguous from 0, entries are read
   * straight from its storage. On several, the run of consecutive global
   * indices in the middle of the vector's map (the process's own share,
   * find_middle_run()) is read straight from its place in
   * the storage too, and only the other entries are looked up in the map: a
   * ghosted vector's map lists the ghosts below the share first, which
   * leaves Epetra a hash lookup for every entry (8 % of the second process's
   * time on the welded lattice of 1.1e6 DoFs, doc/performance.md). The run
   * is found from the map alone, not from locally_owned_elements(), which
   * deal.II's Debug library refuses for a vector made from one overlapping
   * index set. The storage checks are made once, when the reader is made
   * from the vector (implicitly, so that a function taking a DofValues takes
   * the vector too): an assembly makes one for all its stencils, not one per
   * entry.
   */
  class DofValues
  {
  public:
    DofValues(const dealii::TrilinosWrappers::MPI::Vector &u)
        : u(&u)
        , values(contiguous_storage(u))
    {
      if (values == nullptr)
        find_middle_run();
    }

    /**
     * As above, with @p places the place in @p u's storage of each global
     * DoF (-1 where @p u holds none), read for the entries outside the run:
     * one more load instead of Epetra's hash lookup. A network's junctions
     * give the rods' end vertices the DoFs of their junction's vertex,
     * numbered with another rod, often on another process: these lookups
     * took 2.6 % of each process's time on the welded lattice of 1.1e6 DoFs
     * (doc/performance.md). @p places must outlive the reader.
     */
    DofValues(const dealii::TrilinosWrappers::MPI::Vector &u,
              const std::vector<int>                      &places)
        : DofValues(u)
    {
      if (values == nullptr)
        this->places = places.data();
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
      // Unsigned: an index below the run wraps past its size.
      if (i - run_begin < run_size)
        return run_values[i - run_begin];
      const int local =
        places != nullptr ?
          places[i] :
          u->trilinos_vector().Map().LID(
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

    /// The run of consecutive global indices around the map's middle entry:
    /// its first global index, its length and its place in the storage. A
    /// deal.II vector's map lists its indices sorted (they come from an
    /// IndexSet), so gid[k] - k never decreases and each run of consecutive
    /// indices is where it stays constant: two binary searches find the run,
    /// which is the own share wherever that holds more than half the entries.
    /// Implicit conversions make a reader per call, so this must stay
    /// O(log n).
    void
    find_middle_run()
    {
      const Epetra_BlockMap &map = u->trilinos_vector().Map();
      const long long        n   = map.NumMyElements();
      if (n == 0)
        return;
      if (map.LinearMap()) // Epetra would build the index list of a linear
        return set_run(map.MinMyGID64(), 0, n); // map on first use.
      const auto *gids   = dealii::TrilinosWrappers::my_global_elements(map);
      const auto  offset = [gids](const long long k) {
        return static_cast<long long>(gids[k]) - k;
      };
      const long long middle = offset(n / 2);
      // The first k in [lo, hi) where the non-decreasing offset(k) > limit.
      const auto first_above =
        [&](long long lo, long long hi, long long limit) {
          while (lo < hi)
            {
              const long long k = lo + (hi - lo) / 2;
              if (offset(k) > limit)
                hi = k;
              else
                lo = k + 1;
            }
          return lo;
        };
      const long long first = first_above(0, n / 2, middle - 1);
      const long long end   = first_above(n / 2, n, middle);
      // A guard, should a map ever come unsorted: the ends must match.
      if (gids[end - 1] - gids[first] == end - 1 - first)
        set_run(gids[first], first, end - first);
    }

    void
    set_run(const long long begin, const long long place, const long long size)
    {
      run_begin  = begin;
      run_size   = size;
      run_values = u->trilinos_vector()[0] + place;
    }

    const dealii::TrilinosWrappers::MPI::Vector *u;
    /// The storage indexed by global DoF, or null where it is not.
    const double *values;
    /// The run of consecutive global indices read from the storage.
    dealii::types::global_dof_index run_begin  = 0;
    dealii::types::global_dof_index run_size   = 0;
    const double                   *run_values = nullptr;
    /// The places of the global DoFs in the storage, or null.
    const int *places = nullptr;
  };
} // namespace rodnet

#endif
