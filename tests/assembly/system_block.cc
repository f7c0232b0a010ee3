// A rod model as one block of a caller's coupled system: the model's
// sparsity, residual and tangent at the rows a SystemBlock gives, added to
// the caller's own terms; a cantilever coupled through the caller's spring
// to a second, non-rod DoF, solved by the caller's Newton loop, against the
// series-spring formula with the rod's own stiffness from a separate solve.

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <common/rod_models.h>
#include <core/system_block.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <gtest/gtest.h>

using namespace rodnet;

namespace
{
  constexpr unsigned int n_block_segments = 20;
  const RodStiffness     block_stiffness{1e4, 2.0, 2.0, 1.5};

  /// A cantilever along x of length 1, clamped at x = 0, with the tip
  /// force @p force.
  std::unique_ptr<RodModel>
  cantilever(const Vector3 &force)
  {
    auto model =
      rodnet::testing::elastic_model(rodnet::testing::straight_network(
                                       n_block_segments),
                                     block_stiffness);
    model->clamp_end("clamp", 0, true);
    model->add_point_force(n_block_segments, force);
    model->finalize();
    return model;
  }

  /// A converged state of @p model under its loads.
  VectorType
  solved(RodModel &model)
  {
    VectorType               u = model.create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = 1;
    StaticSolver(model, parameters).run(u, [](const auto &, const auto &) {});
    return u;
  }

  /// A matrix of @p n rows with the model's pattern at @p block, plus the
  /// pairs of @p extra.
  void
  make_matrix(const RodModel                                   &model,
              const SystemBlock                                &block,
              const unsigned int                                n,
              const std::vector<std::pair<unsigned, unsigned>> &extra,
              MatrixType                                       &matrix)
  {
    dealii::DynamicSparsityPattern pattern(n);
    model.add_sparsity_pattern(pattern, block);
    for (const auto &[i, j] : extra)
      pattern.add(i, j);
    matrix.reinit(dealii::complete_index_set(n),
                  dealii::complete_index_set(n),
                  pattern,
                  MPI_COMM_WORLD);
  }
} // namespace

TEST(SystemBlock, RefusesARowGivenTwiceAndABlockOfTheWrongSize)
{
  EXPECT_THROW(SystemBlock({0, 3, 3}), std::invalid_argument);
  const auto model = cantilever(Vector3(0, 0, 1e-3));
  VectorType r     = model->create_vector();
  EXPECT_THROW(model->assemble_into(model->create_vector(),
                                    1.0,
                                    SystemBlock::at_offset(3, 0),
                                    &r,
                                    nullptr),
               std::invalid_argument);
}

// The block assembled at an offset is the model's own tangent and residual,
// shifted, added to what the caller's system held.
TEST(SystemBlock, AssemblesTheModelsTermsAtTheCallersRows)
{
  const auto       model = cantilever(Vector3(0, 0.3, 1.0));
  const VectorType u     = solved(*model);
  // A state off equilibrium, so that the residual is not zero.
  VectorType trial = u;
  trial[model->layout().vertex_dof(n_block_segments / 2, 1)] += 1e-2;
  trial.compress(dealii::VectorOperation::add);

  VectorType own_r = model->create_vector();
  MatrixType own_k;
  model->initialize_matrix(own_k);
  model->assemble(trial, 1.0, &own_r, &own_k);

  const unsigned int n = model->layout().n_dofs(), offset = 3, size = n + 5;
  const SystemBlock  block = SystemBlock::at_offset(n, offset);
  MatrixType         k;
  make_matrix(*model, block, size, {{0, 0}, {size - 1, 0}}, k);
  VectorType r(dealii::complete_index_set(size), MPI_COMM_WORLD);
  k.set(0, 0, 2.0); // the caller's own terms
  k.set(size - 1, 0, -1.0);
  k.compress(dealii::VectorOperation::insert);
  r[0] = 5.0;
  r.compress(dealii::VectorOperation::insert);
  const double energy = model->assemble_into(trial, 1.0, block, &r, &k);

  EXPECT_NEAR(energy,
              model->assemble(trial, 1.0, nullptr, nullptr),
              1e-13 * std::abs(energy));
  EXPECT_EQ(k.el(0, 0), 2.0);
  EXPECT_EQ(k.el(size - 1, 0), -1.0);
  EXPECT_EQ(r[0], 5.0);
  const double scale = own_k.linfty_norm();
  ASSERT_GT(own_r.linfty_norm(), 1e-6);
  for (unsigned int i = 0; i < n; ++i)
    {
      EXPECT_NEAR(r[offset + i], own_r[i], 1e-12 * own_r.linfty_norm())
        << "DoF " << i;
      const bool fixed = model->constraints().is_constrained(i);
      for (unsigned int j = 0; j < n; ++j)
        if (!fixed && !model->constraints().is_constrained(j))
          {
            EXPECT_NEAR(k.el(offset + i, offset + j),
                        own_k.el(i, j),
                        1e-12 * scale)
              << i << ", " << j;
          }
        else if (i != j)
          {
            EXPECT_EQ(k.el(offset + i, offset + j), 0.0) << i << ", " << j;
          }
      if (fixed)
        {
          EXPECT_GT(k.el(offset + i, offset + i), 0.0) << "DoF " << i;
        }
    }
}

// The caller's problem: the cantilever (DoFs 1 .. n) and a DoF s of its own
// (row 0), with the energy 1/2 k (w_tip - s)^2 + 1/2 k_g s^2. For a small
// tip force P the rod is the linear spring k_c = P / w_0 of its own solve,
// and the springs k, k_g act in series: w_tip = P / (k_c + k k_g / (k +
// k_g)).
TEST(SystemBlock, CoupledWithTheCallersSpringGivesTheSeriesSpringDeflection)
{
  const double P = 1e-3, k = 1.7, k_g = 0.9;
  auto         alone = cantilever(Vector3(0, 0, P));
  const double w_0 =
    alone->position(solved(*alone), n_block_segments)[2] - 0.0; // X_tip,z = 0
  const double k_c = P / w_0;
  // The discrete cantilever's stiffness is near 3 EI / L^3, L the length
  // beyond the midpoint of the clamped first segment.
  const double L = 1.0 - 0.5 / n_block_segments;
  EXPECT_NEAR(k_c, 3 * block_stiffness.EI2 / std::pow(L, 3), 0.01 * k_c);

  const auto         model = cantilever(Vector3(0, 0, P));
  const unsigned int n     = model->layout().n_dofs();
  const SystemBlock  block = SystemBlock::at_offset(n, 1);
  const unsigned int tip =
    block.index(model->layout().vertex_dof(n_block_segments, 2));
  MatrixType K;
  make_matrix(*model, block, n + 1, {{0, 0}, {0, tip}, {tip, 0}}, K);
  VectorType U(dealii::complete_index_set(n + 1), MPI_COMM_WORLD);
  VectorType R = U, dU = U;
  VectorType u = model->create_vector();

  double norm = 0;
  for (unsigned int iteration = 0; iteration < 10; ++iteration)
    {
      for (unsigned int i = 0; i < n; ++i)
        u[i] = U[i + 1];
      u.compress(dealii::VectorOperation::insert);
      K = 0;
      R = 0;
      model->assemble_into(u, 1.0, block, &R, &K);
      const double stretch = U[tip] - U[0];
      R[tip] += k * stretch;
      R[0] += -k * stretch + k_g * U[0];
      R.compress(dealii::VectorOperation::add);
      K.add(tip, tip, k);
      K.add(0, 0, k + k_g);
      K.add(0, tip, -k);
      K.add(tip, 0, -k);
      K.compress(dealii::VectorOperation::add);
      norm = R.l2_norm();
      // Far below the load, above the round-off floor of the stiff axial
      // terms (EA = 1e4: about 1e-10 here).
      if (norm < 1e-7 * P)
        break;
      dealii::SolverControl                  control(1, 0);
      dealii::TrilinosWrappers::SolverDirect direct(control);
      direct.solve(K, dU, R);
      U.add(-1.0, dU);
    }
  EXPECT_LT(norm, 1e-7 * P);
  const double expected = P / (k_c + k * k_g / (k + k_g));
  EXPECT_NEAR(U[tip], expected, 1e-6 * expected);
  EXPECT_NEAR(U[0], k * U[tip] / (k + k_g), 1e-6 * expected);
}
