// The path of a scene followed by pseudo-arclength continuation, for the
// validation tests of tests/validation/continuation*.cc.
#ifndef RODNET_TESTS_COMMON_CONTINUATION_PATH_H
#define RODNET_TESTS_COMMON_CONTINUATION_PATH_H

#include <deal.II/base/parameter_handler.h>

#include <core/vertex_selector.h>
#include <io/scene.h>
#include <solvers/continuation/arclength_continuation.h>

#include <string>
#include <vector>

namespace rodnet::testing
{
  /// The points of a continuation run of a scene, with the positions of
  /// some vertices at each.
  struct ContinuationPath
  {
    std::vector<ArclengthContinuation::StepInfo> points;
    /// Per point, the positions of the vertices asked for, in their order.
    std::vector<std::vector<Vector3>> positions;
    std::vector<double>               bifurcations;
    std::vector<double>               limit_points;
  };

  /// Follows the scene @p prm_text (its Solver/Continuation entries) from
  /// load factor 0, recording at every point the positions of @p vertices,
  /// named as scenes name them ("10", "1:end", "@corner"). Mesh and network
  /// files are found relative to @p scene_directory.
  inline ContinuationPath
  follow(const std::string              &prm_text,
         const std::vector<std::string> &vertices,
         const std::string              &scene_directory = ".")
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    const Scene               scene(prm, scene_directory);
    const auto                model = scene.build_model();
    std::vector<unsigned int> indices;
    for (const std::string &vertex : vertices)
      indices.push_back(select_vertex(model->network(), vertex, "test"));
    ArclengthContinuation solver(*model, scene.continuation);
    VectorType            u = model->create_vector();
    ContinuationPath      path;
    solver.run(u,
               [&](const ArclengthContinuation::StepInfo &info,
                   const VectorType                      &solution) {
                 path.points.push_back(info);
                 path.positions.emplace_back();
                 for (const unsigned int v : indices)
                   path.positions.back().push_back(
                     model->position(solution, v));
               });
    path.bifurcations = solver.bifurcations();
    path.limit_points = solver.limit_points();
    return path;
  }
} // namespace rodnet::testing

#endif
