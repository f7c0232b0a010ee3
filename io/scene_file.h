#ifndef RODNET_IO_SCENE_FILE_H
#define RODNET_IO_SCENE_FILE_H

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace rodnet
{
  /**
   * Reads the scene file @p path into @p prm, whose entries
   * Scene::declare_parameters() declared: a name ending in ".json" as JSON,
   * any other as .prm text. The subsections a scene names itself,
   * "Material <name>" and "Group <name>", are declared from the file's
   * titles first (Scene::declare_named_subsections()). A UTF-8 byte-order
   * mark is skipped. Throws
   * std::invalid_argument with one line that names the problem and what to
   * do for: a missing, unreadable or directory path; a file that sets no
   * entry; JSON whose shape is not that of the scene (an array, a value
   * where a subsection belongs, an object or array where an entry's value
   * belongs, a name that is no subsection or entry), naming the entry; and
   * every error of deal.II's parsers, without their stack trace.
   */
  void
  read_scene_file(dealii::ParameterHandler &prm, const std::string &path);

  /**
   * Reads the scene @p text into @p prm as read_scene_file() reads a file's
   * contents (after its byte-order mark): as JSON if @p json, as .prm text
   * otherwise, whose messages name the file @p name. The same refusals,
   * each a std::invalid_argument with one line.
   */
  void
  read_scene_text(dealii::ParameterHandler &prm,
                  const std::string        &text,
                  const std::string        &name,
                  bool                      json);
} // namespace rodnet

#endif
