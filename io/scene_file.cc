#include <io/entry_tree.h>
#include <io/scene.h>
#include <io/scene_file.h>
#include <io/scene_help.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    using boost::property_tree::ptree;

    /// The contents of @p path without a leading UTF-8 byte-order mark.
    std::string
    read_text(const std::string &path)
    {
      std::error_code error;
      if (!std::filesystem::exists(path, error))
        throw std::invalid_argument("the scene file does not exist");
      if (std::filesystem::is_directory(path, error))
        throw std::invalid_argument(
          "this is a directory, not a scene file; give a SCENE.prm or "
          "SCENE.json file (scenes/ has examples)");
      std::ifstream in(path, std::ios::binary);
      if (!in)
        throw std::invalid_argument(std::string("the scene file cannot be "
                                                "read: ") +
                                    std::strerror(errno));
      std::ostringstream text;
      text << in.rdbuf();
      const std::string bom      = "\xEF\xBB\xBF";
      std::string       contents = text.str();
      if (contents.compare(0, bom.size(), bom) == 0)
        contents.erase(0, bom.size());
      return contents;
    }

    [[noreturn]] void
    refuse_empty()
    {
      throw std::invalid_argument(
        "the scene sets no entry; a scene needs at least a material, "
        "supports and loads: start from scenes/elastica.prm (rodnet-run "
        "--help lists every entry)");
    }

    bool
    is_array(const ptree &tree)
    {
      return !tree.empty() && tree.front().first.empty();
    }

    /// Throws naming the entry where @p given does not have the shape of
    /// the declared subsection @p declared; counts the entries given.
    void
    check_json_shape(const ptree       &given,
                     const EntryNode   &declared,
                     const std::string &prefix,
                     unsigned int      &n_entries)
    {
      for (const auto &[name, value] : given)
        {
          const std::string path = prefix + name;
          const EntryNode  *node = declared.find(name);
          if (node == nullptr)
            throw std::invalid_argument(
              "\"" + path +
              "\" is no subsection or entry of a scene (rodnet-run --help "
              "lists them)");
          if (!node->is_entry)
            {
              if (value.empty() || is_array(value))
                throw std::invalid_argument(
                  "\"" + path +
                  "\" is a subsection: give an object of its entries, e.g. "
                  "\"Geometry\": {\"Segments\": \"50\"}");
              check_json_shape(value, *node, path + "/", n_entries);
              continue;
            }
          // deal.II's own JSON listing writes an entry as an object with
          // its "value" (and its default, help and pattern).
          const bool listing_form = !value.empty() &&
                                    value.count("value") == 1 &&
                                    value.get_child("value").empty();
          if (!value.empty() && !listing_form)
            throw std::invalid_argument(
              "entry \"" + path + "\" takes one string or number (e.g. \"" +
              (node->default_value.empty() ? "..." : node->default_value) +
              "\"), not a JSON " + (is_array(value) ? "array" : "object"));
          ++n_entries;
        }
    }

    void
    parse_json(dealii::ParameterHandler &prm, const std::string &text)
    {
      ptree tree;
      try
        {
          std::istringstream in(text);
          boost::property_tree::read_json(in, tree);
        }
      catch (const boost::property_tree::json_parser_error &e)
        {
          throw std::invalid_argument("the file is not valid JSON: line " +
                                      std::to_string(e.line()) + ": " +
                                      e.message());
        }
      if (is_array(tree) || (tree.empty() && !tree.data().empty()))
        throw std::invalid_argument(
          "the scene is a JSON array or value; it must be an object of "
          "subsections, e.g. {\"Geometry\": {\"Segments\": \"50\"}}");
      std::vector<std::string> titles;
      for (const auto &[name, value] : tree)
        titles.push_back(name);
      Scene::declare_named_subsections(prm, titles);
      unsigned int n_entries = 0;
      check_json_shape(tree, entry_tree(prm), "", n_entries);
      if (n_entries == 0)
        refuse_empty();
      std::istringstream in(text);
      prm.parse_input_from_json(in);
    }

    /// The titles of the subsections at the top level of the .prm @p text
    /// ("Material soft", "Group x-beams", "Geometry", ...).
    std::vector<std::string>
    top_level_subsections(const std::string &text)
    {
      std::vector<std::string> titles;
      std::istringstream       lines(text);
      int                      depth = 0;
      for (std::string line; std::getline(lines, line);)
        {
          line = line.substr(0, line.find('#'));
          std::istringstream words(line);
          std::string        first;
          words >> first;
          if (first == "subsection")
            {
              std::string title;
              std::getline(words >> std::ws, title);
              if (depth++ == 0)
                titles.push_back(
                  title.substr(0, title.find_last_not_of(" \t\r") + 1));
            }
          else if (first == "end")
            --depth;
        }
      return titles;
    }

    /// deal.II's message for an entry whose value does not match its
    /// pattern ("Line <5> of file <f>: The entry value -1 for the entry
    /// named Mass per length does not match the given pattern: [Double
    /// 0...MAX_DOUBLE (inclusive)]") in our words, naming the line, the
    /// entry, its value and what it asks for; any other message unchanged.
    std::string
    readable_parse_error(const std::string &message)
    {
      std::smatch parts;
      if (!std::regex_match(
            message,
            parts,
            std::regex(
              R"(Line <(\d+)> of file <(.*)>: The entry value (.*) for )"
              R"(the entry named (.*) does not match the given )"
              R"(pattern: \[(.*)\])")))
        return message;
      return "line " + parts[1].str() + ": entry \"" + parts[4].str() +
             "\" cannot be \"" + parts[3].str() +
             "\"; it takes: " + describe_pattern("[" + parts[5].str() + "]");
    }

    /// True if a line of the .prm @p text sets an entry.
    bool
    sets_an_entry(const std::string &text)
    {
      std::istringstream lines(text);
      std::string        line;
      while (std::getline(lines, line))
        {
          std::istringstream words(line);
          std::string        first;
          words >> first;
          if (first == "set" || first == "include")
            return true;
        }
      return false;
    }
  } // namespace

  void
  read_scene_text(dealii::ParameterHandler &prm,
                  const std::string        &text,
                  const std::string        &name,
                  const bool                json)
  {
    try
      {
        if (json)
          return parse_json(prm, text);
        if (!sets_an_entry(text))
          refuse_empty();
        Scene::declare_named_subsections(prm, top_level_subsections(text));
        std::istringstream in(text);
        prm.parse_input(in, name);
      }
    catch (const dealii::ExceptionBase &e)
      {
        // What deal.II's parser found, without its source location, in
        // our words where it is a value outside its entry's pattern.
        throw std::invalid_argument(readable_parse_error(error_message(e)));
      }
  }

  void
  read_scene_file(dealii::ParameterHandler &prm, const std::string &path)
  {
    read_scene_text(prm,
                    read_text(path),
                    path,
                    std::filesystem::path(path).extension() == ".json");
  }
} // namespace rodnet
