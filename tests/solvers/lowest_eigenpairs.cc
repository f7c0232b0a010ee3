// The sparse eigen-solver lowest_eigenpairs() against the dense symmetric
// eigen-decomposition of the same constrained tangent (Eigen's
// SelfAdjointEigenSolver, which the test calls itself): positive definite,
// indefinite (a column compressed far past its buckling load on its
// straight branch), singular (free rods and lattices, rigid motions) and
// with repeated eigenvalues (isotropic sections, a symmetric lattice).
#include <deal.II/base/parameter_handler.h>

#include <common/rod_models.h>
#include <io/scene.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/statics/static_solver.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;

  /// The dense eigenvalues (increasing) of the free block of @p tangent,
  /// and the largest magnitude among them into @p scale.
  Eigen::VectorXd
  dense_eigenvalues(const MatrixType                        &tangent,
                    const dealii::AffineConstraints<double> &constraints,
                    double                                  &scale)
  {
    std::vector<int> index(tangent.m(), -1);
    int              n = 0;
    for (unsigned int i = 0; i < tangent.m(); ++i)
      if (!constraints.is_constrained(i))
        index[i] = n++;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    for (unsigned int i = 0; i < tangent.m(); ++i)
      if (index[i] >= 0)
        for (auto e = tangent.begin(i); e != tangent.end(i); ++e)
          if (index[e->column()] >= 0)
            dense(index[i], index[e->column()]) = e->value();
    const Eigen::VectorXd values =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense,
                                                     Eigen::EigenvaluesOnly)
        .eigenvalues();
    scale = values.cwiseAbs().maxCoeff();
    return values;
  }

  /**
   * Checks the @p k lowest eigenpairs of @p model's tangent at (@p u,
   * @p load_factor): the values equal the dense ones to 1e-9 of the
   * largest eigenvalue, and each vector v is an eigenvector,
   * |K v - lambda v| <= 1e-7 max |lambda|, the vectors orthonormal to 1e-8.
   */
  void
  expect_dense_eigenpairs(const RodModel    &model,
                          const VectorType  &u,
                          const double       load_factor,
                          const unsigned int k)
  {
    MatrixType tangent;
    model.initialize_matrix(tangent);
    model.assemble(u, load_factor, nullptr, &tangent);
    double                scale = 0;
    const Eigen::VectorXd dense =
      dense_eigenvalues(tangent, model.constraints(), scale);
    ASSERT_GT(dense.size(), max_dense_eigenpair_dofs); // the sparse path
    const Eigenpairs pairs = lowest_eigenpairs(tangent, model.constraints(), k);
    ASSERT_EQ(pairs.values.size(), k);
    std::cout << dense.size() << " free DoFs: lowest " << pairs.values[0]
              << ", " << k << "th " << pairs.values[k - 1] << "; "
              << pairs.factorizations << " factorizations, " << pairs.solves
              << " solves" << std::endl;
    for (unsigned int i = 0; i < k; ++i)
      {
        EXPECT_NEAR(pairs.values[i], dense[i], 1e-9 * scale) << "pair " << i;
        VectorType v = model.create_vector(), kv = model.create_vector();
        for (unsigned int j = 0; j < v.size(); ++j)
          v[j] = pairs.vectors[i][j];
        tangent.vmult(kv, v);
        double residual = 0;
        for (unsigned int j = 0; j < v.size(); ++j)
          if (!model.constraints().is_constrained(j))
            residual += std::pow(kv[j] - pairs.values[i] * v[j], 2);
        EXPECT_LT(std::sqrt(residual), 1e-7 * scale) << "pair " << i;
        for (unsigned int m = 0; m <= i; ++m)
          {
            double dot = 0;
            for (unsigned int j = 0; j < v.size(); ++j)
              dot += pairs.vectors[i][j] * pairs.vectors[m][j];
            EXPECT_NEAR(dot, m == i ? 1.0 : 0.0, 1e-8);
          }
      }
  }

  /// A rod of length 1 along x in @p n segments with rigidities EA = 1e4,
  /// EI1 = 1, EI2 = @p EI2, GJ = 1, clamped at its start unless @p free.
  std::unique_ptr<RodModel>
  clamped_or_free_rod(const unsigned int n,
                      const double       EI2,
                      const bool         free = false)
  {
    auto model = rodnet::testing::elastic_model(
      rodnet::testing::straight_network(n,
                                        Vector3(0, 0, 0),
                                        Vector3(1, 0, 0),
                                        true),
      RodStiffness{1e4, 1, EI2, 1});
    if (!free)
      model->clamp_end("clamp", 0, true);
    return model;
  }

  TEST(LowestEigenpairs, PositiveDefiniteCantilever)
  {
    auto model = clamped_or_free_rod(120, 2.0);
    model->finalize();
    expect_dense_eigenpairs(*model, model->create_vector(), 0.0, 6);
  }

  TEST(LowestEigenpairs, IsotropicCantileverHasPairs)
  {
    // EI1 = EI2: every bending eigenvalue is double.
    auto model = clamped_or_free_rod(120, 1.0);
    model->finalize();
    expect_dense_eigenpairs(*model, model->create_vector(), 0.0, 7);
  }

  TEST(LowestEigenpairs, ColumnFarPastBuckling)
  {
    // 200 P_cr on the straight branch: 14 negative eigenvalues (the
    // inertia test of stability_and_strain.cc), the lowest far from zero.
    auto model = clamped_or_free_rod(120, 1.0);
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           Vector3(-200 * M_PI * M_PI / 4, 0, 0));
    const VectorType u = rodnet::testing::solve_in_one_step(*model);
    expect_dense_eigenpairs(*model, u, 1.0, 6);
  }

  TEST(LowestEigenpairs, FreeRodHasSixRigidMotions)
  {
    auto model = clamped_or_free_rod(120, 2.0, true);
    model->finalize();
    expect_dense_eigenpairs(*model, model->create_vector(), 0.0, 8);
  }

  TEST(LowestEigenpairs, FreeSymmetricLattice)
  {
    // A 3 x 3 square lattice of welded laths, free: rigid motions and
    // eigenvalues repeated by the square's symmetry.
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Geometry\n  set Generator = square lattice\n"
      "  set Cells = 3, 3\n  set Beam length = 0.3\n  set Segments = 4\n"
      "end\n"
      "subsection Material\n  subsection linear elastic\n"
      "    set Stiffness input = direct\n    set EA = 1000\n"
      "    set EI1 = 4\n    set EI2 = 1\n    set GJ = 1\n  end\nend\n");
    const Scene scene(prm);
    auto        model = scene.build_model();
    expect_dense_eigenpairs(*model, model->create_vector(), 0.0, 12);
  }

  TEST(LowestEigenpairs, MissedMultiplicityIsASolverFailure)
  {
    // 400 free DoFs (the sparse path), the lowest eigenvalue 1 repeated 100
    // times, the others 2, 3, ..., 301: a block Lanczos run spans at most
    // its block size of an eigenspace, and blocks of 3, 6 and 12 leave most
    // of it out, which the inertia check finds. A lattice of many identical
    // members can do this mid-run: the solver must stop (exit code 2, the
    // steps so far kept), not end as if the scene were wrong (exit code 1:
    // the eigen-solver once threw a plain std::runtime_error).
    const unsigned int                     n = 400;
    dealii::TrilinosWrappers::SparseMatrix tangent(n, n, 1u);
    for (unsigned int i = 0; i < n; ++i)
      tangent.set(i, i, i < 100 ? 1.0 : 2.0 + (i - 100));
    tangent.compress(dealii::VectorOperation::insert);
    dealii::AffineConstraints<double> none;
    none.close();
    EXPECT_THROW(lowest_eigenpairs(tangent, none, 1), SolverFailure);
  }
} // namespace
