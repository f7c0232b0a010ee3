#ifndef RODNET_CORE_INTERNAL_VARIABLES_H
#define RODNET_CORE_INTERNAL_VARIABLES_H

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Committed internal variables of the history-dependent materials of a
   * network (e.g. viscous strains): one block per hinge, per junction
   * element and per segment, sized by the material of its rod (junction
   * elements carry the hinge variables of their rod's material, since the
   * same hinge law acts on them). Blocks of elastic materials are empty.
   *
   * It is plain storage in the order of the DofLayout's stencil lists; the
   * RodModel decides when values change (only on commit after a converged
   * step, see RodMaterial).
   */
  class InternalVariables
  {
  public:
    /// Kind of stencil a block belongs to.
    enum class Owner
    {
      hinge,
      junction_element,
      segment
    };

    InternalVariables() = default;

    /**
     * One block of @p sizes[o][i] values, all zero, for stencil i of kind
     * o (indexed by the Owner's value).
     */
    explicit InternalVariables(
      const std::vector<std::vector<unsigned int>> &sizes);

    /// Whether any stencil stores a value.
    bool
    empty() const
    {
      return values.empty();
    }

    /// Number of values in the block of stencil @p i of kind @p owner.
    unsigned int
    size(Owner owner, unsigned int i) const
    {
      const auto &o = offsets[static_cast<unsigned int>(owner)];
      return o[i + 1] - o[i];
    }

    /// The block of stencil @p i of kind @p owner.
    const double *
    block(Owner owner, unsigned int i) const
    {
      return values.data() + offsets[static_cast<unsigned int>(owner)][i];
    }

    double *
    block(Owner owner, unsigned int i)
    {
      return values.data() + offsets[static_cast<unsigned int>(owner)][i];
    }

  private:
    /// Per owner kind: start of each stencil's block, plus the end.
    std::vector<std::vector<unsigned int>> offsets;
    std::vector<double>                    values;
  };
} // namespace rodnet

#endif
