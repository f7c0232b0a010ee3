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

    /// The entry of global DoF @p i (locally owned or ghost). Throws
    /// std::logic_error where this process holds no entry @p i (a vector
    /// without the ghosts a stencil reads): deal.II's Release library
    /// would read 0 there.
    double
    operator[](const dealii::types::global_dof_index i) const
    {
      if (values != nullptr)
        return values[i];
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

    const dealii::TrilinosWrappers::MPI::Vector *u;
    /// The storage indexed by global DoF, or null where it is not.
    const double *values;
  };
} // namespace rodnet

#endif
