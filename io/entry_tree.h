#ifndef RODNET_IO_ENTRY_TREE_H
#define RODNET_IO_ENTRY_TREE_H

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * A subsection or an entry of a ParameterHandler, as declared: deal.II
   * gives no way to walk its entries but its own listing, so this is that
   * listing (print_parameters() as JSON) read back into a tree. The help
   * of rodnet-run and the checks that apply to every entry of a scene
   * (finite numbers) walk it.
   */
  struct EntryNode
  {
    std::string name;
    /// False for a subsection.
    bool is_entry = false;
    /// Entries: the current value, the default, the help text and the
    /// pattern in deal.II's machine-readable form ("[Integer range
    /// 1...2147483647 (inclusive)]", "[Selection a|b ]", ...).
    std::string value, default_value, documentation, pattern;
    /// Subsections: entries and subsections in declaration order.
    std::vector<EntryNode> children;

    /// The child called @p child_name, nullptr if there is none.
    const EntryNode *
    find(const std::string &child_name) const;

    /// Entries: true if the value is the default, written alike or not
    /// (blanks aside, or as the same numbers: "0,1,0" for "0, 1, 0",
    /// "1.0" for "1").
    bool
    holds_default() const;
  };

  /// The tree of every subsection and entry of @p prm, in declaration
  /// order, with the values it holds now.
  EntryNode
  entry_tree(const dealii::ParameterHandler &prm);

  /// Calls @p visit for every entry below @p node with its path
  /// ("Geometry/Segments"), depth first in declaration order.
  void
  for_each_entry(
    const EntryNode                                                   &node,
    const std::function<void(const std::string &, const EntryNode &)> &visit);
} // namespace rodnet

#endif
