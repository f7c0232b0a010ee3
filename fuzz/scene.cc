// Fuzz target of the scene parser: the text of a .prm or .json scene
// through ParameterHandler and the Scene constructor, and for a scene small
// enough to build quickly, what rodnet-run builds before it solves: the
// model (rods, materials, supports, loads), its probes and, for time
// stepping, the inertia and the initial state.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <io/scene.h>
#include <io/scene_file.h>

#include "fuzz_input.h"
#include <base/mpi_session.h>
#include <cstdlib>
#include <sstream>

namespace
{
  using namespace rodnet;

  /// MPI, initialized once (LLVMFuzzerInitialize()).
  MPISession *mpi_session = nullptr;

  /// Mesh and network files of a scene are relative to the test inputs.
  const std::string scene_directory = RODNET_SOURCE_DIR "/tests/input/data";


  bool
  is_json(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t\r\n");
    return first != std::string::npos && text[first] == '{';
  }

  /**
   * Whether the geometry is small: the Scene constructor generates every
   * vertex, and refusing sizes that do not fit in memory (issue 11) is not
   * what this target looks for. Larger inputs are skipped.
   */
  bool
  small_enough(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    const long segments = prm.get_integer("Segments");
    const auto cells    = dealii::Utilities::string_to_int(
      dealii::Utilities::split_string_list(prm.get("Cells"), ','));
    const auto corners =
      dealii::Utilities::split_string_list(prm.get("Points"), ';');
    prm.leave_subsection();
    return segments <= 64 && cells[0] <= 4 && cells[1] <= 4 &&
           corners.size() <= 16;
  }

  /// Builds what rodnet-run builds of @p scene before its first step.
  void
  build(const Scene &scene)
  {
    if (scene.method == SolutionMethod::dynamic_relaxation)
      {
        const auto model = scene.build_dr_model();
        scene.probes(*model);
        return;
      }
    const auto model = scene.build_model();
    scene.probes(*model);
    if (scene.method == SolutionMethod::time_stepping)
      {
        if (scene.time_stepping.dynamic())
          scene.inertia();
        VectorType u, v;
        scene.initial_state(*model, u, v);
      }
  }
} // namespace

// MPI for the Trilinos objects of the model, for the whole run; ended at
// exit (libFuzzer and the replay program end with exit()), which removes
// the process's MPI session directory (base/mpi_session.h).
extern "C" int
LLVMFuzzerInitialize(int *argc, char ***argv)
{
  mpi_session = new MPISession(*argc, *argv);
  std::atexit([] {
    delete mpi_session;
    mpi_session = nullptr;
  });
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  const std::string        text(reinterpret_cast<const char *>(data), size);
  dealii::ParameterHandler prm;
  Scene::declare_parameters(prm);
  // rodnet-run reports deal.II's exceptions of the parser and the Scene
  // alike: error_message() on one line.
  const auto as_refusal = [](const auto &step) {
    try
      {
        step();
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw std::invalid_argument(error_message(e));
      }
  };
  bool parsed = false;
  fuzz::expect_accepted_or_refused(
    [&] {
      // As rodnet-run reads a scene file (read_scene_file()).
      read_scene_text(prm, text, "fuzz input", is_json(text));
      parsed = true;
    },
    error_message);
  if (!parsed || !small_enough(prm))
    return 0;
  fuzz::expect_accepted_or_refused(
    [&] {
      as_refusal([&] {
        const Scene scene(prm, scene_directory);
        build(scene);
      });
    },
    error_message);
  return 0;
}
