// The natural frequencies of a scene's model: the generalized eigenproblem
// K x = omega^2 M x on the free DoFs, K the tangent of the undeformed,
// unloaded state, M the consistent mass matrix (with the rotary inertia and
// the rigid bodies; tests/validation/stated_inertia.cc, rayleigh_beam.cc,
// rigid_bodies.cc).
#ifndef RODNET_TESTS_NATURAL_FREQUENCIES_H
#define RODNET_TESTS_NATURAL_FREQUENCIES_H

#include <deal.II/base/parameter_handler.h>

#include <core/mass_matrix.h>
#include <io/scene.h>
#include <io/scene_file.h>

#include <Eigen/Eigenvalues>
#include <string>
#include <vector>

namespace rodnet::testing
{
  /// The entries of @p matrix on the DoFs that @p constraints leave free.
  inline Eigen::MatrixXd
  free_block(const MatrixType                        &matrix,
             const dealii::AffineConstraints<double> &constraints)
  {
    std::vector<int> index(matrix.m(), -1);
    int              n = 0;
    for (unsigned int i = 0; i < matrix.m(); ++i)
      if (!constraints.is_constrained(i))
        index[i] = n++;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    for (unsigned int i = 0; i < matrix.m(); ++i)
      if (index[i] >= 0)
        for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
          if (index[e->column()] >= 0)
            dense(index[i], index[e->column()]) = e->value();
    return dense;
  }

  /// The eigenvalues omega^2 (increasing) of the scene @p text; those of
  /// free rigid motions are zero to round-off.
  inline Eigen::VectorXd
  squared_natural_frequencies(const std::string &text)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm, text, "scene", false);
    const Scene scene(prm);
    const auto  model = scene.build_model();
    MatrixType  tangent, mass;
    model->initialize_matrix(tangent);
    model->assemble(model->create_vector(), 0., nullptr, &tangent);
    assemble_mass_matrix(*model, scene.inertia(), MassKind::consistent, mass);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      free_block(tangent, model->constraints()),
      free_block(mass, model->constraints()),
      Eigen::EigenvaluesOnly);
    return solver.eigenvalues();
  }

  /// The natural frequencies omega (increasing) of a scene @p text
  /// without free rigid motions.
  inline Eigen::VectorXd
  natural_frequencies(const std::string &text)
  {
    return squared_natural_frequencies(text).cwiseMax(0).cwiseSqrt();
  }
} // namespace rodnet::testing

#endif
