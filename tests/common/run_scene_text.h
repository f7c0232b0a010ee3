#ifndef RODNET_TESTS_RUN_SCENE_TEXT_H
#define RODNET_TESTS_RUN_SCENE_TEXT_H

#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>
#include <io/scene_file.h>
#include <app/scene_runner.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rodnet::testing
{
  /// Runs the scene given as .prm text through the library's scene runner,
  /// writing into @p output_directory, silently.
  inline RunSummary
  run_scene_text(const std::string &prm_text,
                 const std::string &output_directory)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm, prm_text, "scene", false);
    const Scene scene(prm);
    return run_scene(scene, output_directory, nullptr);
  }

  /// The shipped scene scenes/@p name with each "set <entry> = ..." line of
  /// @p changes (entry, value) replaced; throws naming an entry the scene
  /// does not set.
  inline std::string
  shipped_scene(const std::string                                      &name,
                const std::vector<std::pair<std::string, std::string>> &changes)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/" + name);
    std::stringstream scene;
    scene << file.rdbuf();
    std::string text = scene.str();
    for (const auto &[entry, value] : changes)
      {
        const std::size_t start = text.find("set " + entry + " =");
        if (start == std::string::npos)
          throw std::invalid_argument("scenes/" + name + " sets no \"" + entry +
                                      "\"");
        const std::size_t end = text.find('\n', start);
        text.replace(start, end - start, "set " + entry + " = " + value);
      }
    return text;
  }

  /// The column of probe @p name in @p summary's rows.
  inline std::size_t
  probe_column(const RunSummary &summary, const std::string &name)
  {
    for (std::size_t i = 0; i < summary.probe_names.size(); ++i)
      if (summary.probe_names[i] == name)
        return i + 1;
    throw std::invalid_argument("no probe " + name);
  }

  /// The values of column @p name of the probes.csv in @p directory, one
  /// per row (columns that RunSummary leaves out, such as "jump").
  inline std::vector<double>
  probes_csv_column(const std::string &directory, const std::string &name)
  {
    std::ifstream csv(directory + "/probes.csv");
    std::string   line, field;
    std::getline(csv, line);
    std::istringstream header(line);
    std::size_t        column = 0;
    while (std::getline(header, field, ',') && field != name)
      ++column;
    if (field != name)
      throw std::invalid_argument("no column " + name + " in " + directory +
                                  "/probes.csv");
    std::vector<double> values;
    while (std::getline(csv, line))
      {
        std::istringstream row(line);
        for (std::size_t c = 0; c <= column; ++c)
          std::getline(row, field, ',');
        values.push_back(std::strtod(field.c_str(), nullptr));
      }
    return values;
  }
} // namespace rodnet::testing

#endif
