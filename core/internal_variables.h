#ifndef RODNET_CORE_INTERNAL_VARIABLES_H
#define RODNET_CORE_INTERNAL_VARIABLES_H

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  class ElementFamily;

  /**
   * Committed internal variables of the element families of a model (e.g.
   * the viscous strains of history-dependent materials): one block per
   * stencil of every family, sized by the family
   * (ElementFamily::n_internal_variables()); a family without history has
   * no blocks and stores nothing.
   *
   * It is plain storage in the order of each family's stencils, keyed by
   * the families it was made for; the RodModel decides when values change
   * (only on commit after a converged step, see
   * RodModel::commit_internal_variables()).
   */
  class InternalVariables
  {
  public:
    InternalVariables() = default;

    /// One block of families[f]->n_internal_variables(s) values, all
    /// zero, for every stencil s of every family f.
    explicit InternalVariables(
      const std::vector<std::unique_ptr<ElementFamily>> &families);

    /// Whether any stencil stores a value.
    bool
    empty() const
    {
      return values.empty();
    }

    /// Number of values in the block of stencil @p s of @p family; 0 for a
    /// family that this storage was not made for.
    unsigned int
    size(const ElementFamily &family, unsigned int s) const
    {
      return size(place_of(family), s);
    }

    /// The block of stencil @p s of @p family; null if the family stores
    /// nothing.
    const double *
    block(const ElementFamily &family, unsigned int s) const
    {
      return block_at(place_of(family), s);
    }

    double *
    block(const ElementFamily &family, unsigned int s)
    {
      return const_cast<double *>(std::as_const(*this).block(family, s));
    }

  private:
    /// The place of @p family among the families, or their number.
    unsigned int
    place_of(const ElementFamily &family) const
    {
      unsigned int f = 0;
      while (f < families.size() && families[f] != &family)
        ++f;
      return f;
    }

    unsigned int
    size(const unsigned int f, const unsigned int s) const
    {
      if (f >= offsets.size() || offsets[f].empty())
        return 0;
      return offsets[f][s + 1] - offsets[f][s];
    }

    const double *
    block_at(const unsigned int f, const unsigned int s) const
    {
      if (f >= offsets.size() || offsets[f].empty())
        return nullptr;
      return values.data() + offsets[f][s];
    }

    /// The families the blocks belong to (owned by the model).
    std::vector<const ElementFamily *> families;
    /// Per family: start of each stencil's block, plus the end; empty for
    /// a family without internal variables.
    std::vector<std::vector<unsigned int>> offsets;
    std::vector<double>                    values;
  };
} // namespace rodnet

#endif
