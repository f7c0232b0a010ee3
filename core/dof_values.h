#ifndef RODNET_CORE_DOF_VALUES_H
#define RODNET_CORE_DOF_VALUES_H

#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_vector.h>

namespace rodnet
{
  /**
   * Read access to the entries of a DoF vector by global index. On one
   * process, where the vector's map is contiguous from 0, entries are read
   * straight from its storage; otherwise through the vector's operator(),
   * which looks each global index up in the map. The storage check is made
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
    }

    /// The entry of global DoF @p i (locally owned or ghost).
    double
    operator[](const dealii::types::global_dof_index i) const
    {
      return values != nullptr ? values[i] : (*u)[i];
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

    const dealii::TrilinosWrappers::MPI::Vector *u;
    /// The storage indexed by global DoF, or null where it is not.
    const double *values;
  };
} // namespace rodnet

#endif
