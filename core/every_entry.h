#ifndef RODNET_CORE_EVERY_ENTRY_H
#define RODNET_CORE_EVERY_ENTRY_H

#include <deal.II/lac/trilinos_vector.h>

#include <optional>

namespace rodnet
{
  /**
   * Every entry of a DoF vector, readable on this process: the vector
   * itself where this process holds all its entries (one process, or a
   * replica already), otherwise a replica of it on MPI_COMM_SELF, gathered
   * from the processes of the vector's communicator. What reads DoFs
   * anywhere in the network (the solvers' checks, probes, output) reads
   * through it, so that it works on a model distributed over processes
   * (doc/architecture.md, "Several processes") and costs nothing on one.
   * The constructor is collective where the vector is distributed; it costs
   * O(size) memory and communication per process there.
   */
  class EveryEntry
  {
  public:
    /// @p vector must outlive this object.
    explicit EveryEntry(const dealii::TrilinosWrappers::MPI::Vector &vector);

    /// The vector with every entry.
    const dealii::TrilinosWrappers::MPI::Vector &
    operator*() const
    {
      return *entries;
    }

    /// Whether @p vector has entries that this process does not hold.
    static bool
    distributed(const dealii::TrilinosWrappers::MPI::Vector &vector);

  private:
    std::optional<dealii::TrilinosWrappers::MPI::Vector> gathered;
    const dealii::TrilinosWrappers::MPI::Vector         *entries;
  };

  /// Every entry of a state of type @p State (EveryEntry): the state
  /// itself for a type that one process always holds whole.
  template <class State>
  class EveryEntryOf
  {
  public:
    /// @p state must outlive this object.
    explicit EveryEntryOf(const State &state)
        : state(state)
    {
    }

    const State &
    operator*() const
    {
      return state;
    }

  private:
    const State &state;
  };

  /// A Trilinos vector may be distributed: EveryEntry.
  template <>
  class EveryEntryOf<dealii::TrilinosWrappers::MPI::Vector> : public EveryEntry
  {
  public:
    using EveryEntry::EveryEntry;
  };
} // namespace rodnet

#endif
