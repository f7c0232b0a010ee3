#include <deal.II/base/utilities.h>

#include <io/entry_tree.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <sstream>
#include <stdexcept>

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

  namespace
  {
    /// @p text without blanks.
    std::string
    without_blanks(const std::string &text)
    {
      std::string kept;
      for (const char c : text)
        if (!std::isspace(static_cast<unsigned char>(c)))
          kept += c;
      return kept;
    }

    /// The numbers of the list @p text ("1, 0, 0"), empty if it is not
    /// one.
    std::vector<double>
    numbers(const std::string &text)
    {
      try
        {
          return dealii::Utilities::string_to_double(
            dealii::Utilities::split_string_list(text, ','));
        }
      catch (const std::exception &)
        {
          return {};
        }
    }
  } // namespace

  bool
  EntryNode::holds_default() const
  {
    if (without_blanks(value) == without_blanks(default_value))
      return true;
    const std::vector<double> given = numbers(value);
    return !given.empty() && given == numbers(default_value);
  }

  namespace
  {
    /// The name of the JSON object that line @p line (from 1) of the
    /// listing @p text is in: the last line at or before it that opens
    /// one, "Name": {.
    std::string
    entry_at_line(const std::string &text, const unsigned long line)
    {
      std::istringstream lines(text);
      std::string        current, name = "?";
      for (unsigned long n = 1; n <= line && std::getline(lines, current); ++n)
        {
          const auto open = current.find('"');
          const auto close = current.find("\": {");
          if (open != std::string::npos && close != std::string::npos &&
              close > open)
            name = current.substr(open + 1, close - open - 1);
        }
      return name;
    }
  } // namespace

  EntryNode
  entry_tree(const dealii::ParameterHandler &prm)
  {
    std::stringstream listing;
    prm.print_parameters(listing,
                         dealii::ParameterHandler::OutputStyle(
                           dealii::ParameterHandler::JSON |
                           dealii::ParameterHandler::KeepDeclarationOrder));
    const std::string           text = listing.str();
    std::istringstream          in(text);
    boost::property_tree::ptree tree;
    try
      {
        boost::property_tree::read_json(in, tree);
      }
    catch (const boost::property_tree::json_parser_error &e)
      {
        // deal.II writes what it read; only a value that is not UTF-8
        // makes its listing unreadable (found by fuzz/scene).
        throw std::invalid_argument(
          "the value of entry \"" + entry_at_line(text, e.line()) +
          "\" is not UTF-8 text (" + e.message() +
          "); a scene is ASCII or UTF-8 text");
      }
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
