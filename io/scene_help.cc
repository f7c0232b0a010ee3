#include <deal.II/base/parameter_handler.h>

#include <io/entry_tree.h>
#include <io/scene.h>
#include <io/scene_help.h>

#include <regex>
#include <sstream>
#include <vector>

namespace rodnet
{
  namespace
  {
    constexpr unsigned int line_width = 79;

    /// "from...to" bounds of an Integer or Double pattern in words.
    std::string
    range(const std::string &kind,
          const std::string &low,
          const std::string &high)
    {
      const bool no_low  = low == "-MAX_DOUBLE" || low == "-2147483648";
      const bool no_high = high == "MAX_DOUBLE" || high == "2147483647";
      if (no_low && no_high)
        return kind;
      if (no_high)
        return kind + " >= " + low;
      if (no_low)
        return kind + " <= " + high;
      return kind + " from " + low + " to " + high;
    }

    /// @p text wrapped into lines of at most line_width, each starting
    /// with @p indent.
    std::string
    wrap(const std::string &text, const std::string &indent)
    {
      std::istringstream words(text);
      std::string        word, line, out;
      while (words >> word)
        {
          if (!line.empty() &&
              indent.size() + line.size() + 1 + word.size() > line_width)
            {
              out += indent + line + "\n";
              line.clear();
            }
          line += (line.empty() ? "" : " ") + word;
        }
      if (!line.empty())
        out += indent + line + "\n";
      return out;
    }

    /// True if @p a and @p b are declared alike (name, default, help,
    /// pattern, and their children).
    bool
    same_declaration(const EntryNode &a, const EntryNode &b)
    {
      if (a.name != b.name || a.is_entry != b.is_entry ||
          a.default_value != b.default_value ||
          a.documentation != b.documentation || a.pattern != b.pattern ||
          a.children.size() != b.children.size())
        return false;
      for (std::size_t i = 0; i < a.children.size(); ++i)
        if (!same_declaration(a.children[i], b.children[i]))
          return false;
      return true;
    }

    /// The earlier sibling (among @p siblings before @p node) whose every
    /// child @p node repeats, nullptr if none.
    const EntryNode *
    repeated_sibling(const std::vector<EntryNode> &siblings,
                     const EntryNode              &node)
    {
      for (const EntryNode &earlier : siblings)
        {
          if (&earlier == &node)
            return nullptr;
          if (earlier.is_entry || earlier.children.empty())
            continue;
          bool repeats = true;
          for (const EntryNode &child : earlier.children)
            {
              const EntryNode *mine = node.find(child.name);
              repeats =
                repeats && mine != nullptr && same_declaration(child, *mine);
            }
          if (repeats)
            return &earlier;
        }
      return nullptr;
    }

    void
    print_entry(std::ostream      &out,
                const EntryNode   &entry,
                const std::string &indent)
    {
      out << indent << entry.name << " ="
          << (entry.default_value.empty() ? "" : " " + entry.default_value)
          << "\n"
          << wrap("(" + describe_pattern(entry.pattern) + ") " +
                    entry.documentation,
                  indent + "    ");
    }

    void
    print_subsection(std::ostream                 &out,
                     const EntryNode              &section,
                     const std::vector<EntryNode> &siblings,
                     const std::string            &indent)
    {
      const EntryNode *repeated = repeated_sibling(siblings, section);
      out << "\n" << indent << "subsection " << section.name << "\n";
      if (repeated != nullptr)
        out << wrap("Every entry and subsection of \"" + repeated->name +
                      "\" above, and:",
                    indent + "  ");
      for (const EntryNode &child : section.children)
        {
          if (repeated != nullptr && repeated->find(child.name) != nullptr)
            continue;
          if (child.is_entry)
            print_entry(out, child, indent + "  ");
          else
            print_subsection(out, child, section.children, indent + "  ");
        }
      out << indent << "end\n";
    }
  } // namespace

  std::string
  describe_pattern(const std::string &pattern)
  {
    static const std::regex integer(
      R"(\[Integer range (\S+)\.\.\.(\S+) \(inclusive\)\])");
    static const std::regex real(
      R"(\[Double (\S+)\.\.\.(\S+) \(inclusive\)\])");
    static const std::regex selection(R"(\[Selection (.*) \])");
    static const std::regex list(
      R"(\[List of <(.*)> of length (\d+)\.\.\.(\d+) \(inclusive\)(?: separated by <(.*)>)?\])");
    std::smatch match;
    if (pattern == "[Anything]")
      return "text";
    if (pattern == "[Bool]")
      return "true | false";
    if (std::regex_match(pattern, match, integer))
      return range("integer", match[1], match[2]);
    if (std::regex_match(pattern, match, real))
      return range("number", match[1], match[2]);
    if (std::regex_match(pattern, match, selection))
      {
        std::string values = match[1];
        return "one of: " +
               std::regex_replace(values, std::regex("\\|"), " | ");
      }
    if (std::regex_match(pattern, match, list))
      {
        const std::string length = match[2] == match[3] ?
                                     match[2].str() :
                                     match[2].str() + " to " + match[3].str();
        const std::string separator =
          match[4].matched ? match[4].str() : std::string(",");
        // "3 numbers", "2 integers >= 1", else "2 x (one of: a | b)".
        const std::string element  = describe_pattern(match[1]);
        const std::size_t kind_end = element.find(' ');
        const std::string kind     = element.substr(0, kind_end);
        const std::string items =
          kind == "number" || kind == "integer" ?
            kind + "s" +
              (kind_end == std::string::npos ? "" : element.substr(kind_end)) :
            "x (" + element + ")";
        return length + " " + items + " separated by '" + separator + "'";
      }
    return pattern;
  }

  std::string
  entry_unit(const std::string &path)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    const EntryNode   tree = entry_tree(prm);
    const EntryNode  *node = &tree;
    std::stringstream names(path);
    for (std::string name; node != nullptr && std::getline(names, name, '/');)
      node = node->find(name);
    if (node == nullptr || !node->is_entry)
      return "";
    // "... radius. [m]" or "Young's modulus E (Pa). ...": the symbols of
    // the SI units the entries use, with powers, products and quotients.
    static const std::regex bracketed(R"(\[([^\]]*)\]\s*$)");
    static const std::regex parenthesized(
      R"(\(((?:-|(?:1|m|N|Pa|rad|s|kg|J|K|deg)(?:\^-?\d+)?)"
      R"((?:[ /](?:m|N|Pa|rad|s|kg|J|K|deg)(?:\^-?\d+)?)*))\))");
    std::smatch match;
    if (std::regex_search(node->documentation, match, bracketed) ||
        std::regex_search(node->documentation, match, parenthesized))
      return match[1];
    return "";
  }

  void
  print_scene_entries(std::ostream &out)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    // A scene names these subsections itself, as many as it needs.
    Scene::declare_named_subsections(prm, {"Material <name>", "Group <name>"});
    const EntryNode tree = entry_tree(prm);
    for (const EntryNode &section : tree.children)
      if (section.is_entry)
        print_entry(out, section, "");
      else
        print_subsection(out, section, tree.children, "");
  }
} // namespace rodnet
