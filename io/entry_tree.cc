#include <io/entry_tree.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <sstream>

namespace rodnet
{
  namespace
  {
    /// @p tree (a subsection of the JSON listing) as an EntryNode.
    EntryNode
    to_node(const std::string &name, const boost::property_tree::ptree &tree)
    {
      EntryNode node;
      node.name = name;
      // In the listing an entry is an object with these fields; a
      // subsection holds entries and subsections.
      if (tree.count("pattern_description") > 0)
        {
          node.is_entry      = true;
          node.value         = tree.get<std::string>("value");
          node.default_value = tree.get<std::string>("default_value");
          node.documentation = tree.get<std::string>("documentation");
          node.pattern       = tree.get<std::string>("pattern_description");
          return node;
        }
      for (const auto &[child_name, child] : tree)
        node.children.push_back(to_node(child_name, child));
      return node;
    }

    void
    visit_entries(
      const EntryNode                                                   &node,
      const std::string                                                 &prefix,
      const std::function<void(const std::string &, const EntryNode &)> &visit)
    {
      for (const EntryNode &child : node.children)
        {
          const std::string path = prefix + child.name;
          if (child.is_entry)
            visit(path, child);
          else
            visit_entries(child, path + "/", visit);
        }
    }
  } // namespace

  const EntryNode *
  EntryNode::find(const std::string &child_name) const
  {
    for (const EntryNode &child : children)
      if (child.name == child_name)
        return &child;
    return nullptr;
  }

  EntryNode
  entry_tree(const dealii::ParameterHandler &prm)
  {
    std::stringstream listing;
    prm.print_parameters(listing,
                         dealii::ParameterHandler::OutputStyle(
                           dealii::ParameterHandler::JSON |
                           dealii::ParameterHandler::KeepDeclarationOrder));
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(listing, tree);
    return to_node("", tree);
  }

  void
  for_each_entry(
    const EntryNode                                                   &node,
    const std::function<void(const std::string &, const EntryNode &)> &visit)
  {
    visit_entries(node, "", visit);
  }
} // namespace rodnet
