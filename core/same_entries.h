#ifndef RODNET_CORE_SAME_ENTRIES_H
#define RODNET_CORE_SAME_ENTRIES_H

#include <deal.II/lac/trilinos_vector.h>

namespace rodnet
{
  /**
   * Whether @p a and @p b hold the same entries on every process of their
   * communicator; collective. deal.II's operator== compares this process's
   * entries only: on several processes a state that changed on one of them
   * would be "the same" on the others, and a cache keyed on it would
   * assemble (a collective call) on some processes only, which waits
   * forever.
   */
  bool
  same_entries(const dealii::TrilinosWrappers::MPI::Vector &a,
               const dealii::TrilinosWrappers::MPI::Vector &b);
} // namespace rodnet

#endif
