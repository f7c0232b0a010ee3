// The direct solvers of Newton's systems (TangentFactorization): the
// band LU and KLU solve a rod's tangent system to its backward
// error; "auto" takes the band for one rod, KLU where junction DoFs
// widen the band and MUMPS from TangentFactorization::min_auto_mumps_rows
// rows on; a singular tangent is reported, not solved, by MUMPS
// too (tests/solvers/mumps_factorization.cc has its own tests); a kept
// factorization (TangentFactorizationCache) is reused only for the same
// matrix, pattern and kind, and solves new values to their backward error;
// and NOX's line searches, which apply the Jacobian through our group,
// still work. KLU keeps the fill of its fill-reducing order on an
// indefinite lattice tangent, where the pivoting of Amesos KLU (before
// issue 33) broke it.

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <common/diagonal_tangent.h>
#include <common/pinned_lattices.h>
#include <common/rod_models.h>
#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>
#include <solvers/newton/epetra_entries.h>
#include <solvers/newton/newton_solver.h>
#include <solvers/newton/saddle_point_order.h>
#include <solvers/newton/tangent_factorization.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <klu.h>
#include <stdexcept>

using namespace rodnet;
using rodnet::testing::normwise_backward_error;
using rodnet::testing::pinned_square_lattice;
using rodnet::testing::RolledLattice;

namespace
{
  /// A cantilever of 20 segments under a tip force, with its tangent and
  /// residual assembled at a state off equilibrium.
  struct RodSystem
  {
    std::unique_ptr<RodModel> model;
    MatrixType                tangent;
    VectorType                residual;

    explicit RodSystem(std::unique_ptr<RodNetwork> network)
    {
      model = rodnet::testing::elastic_model(std::move(network),
                                             {1e4, 2.0, 2.0, 1.5});
      model->clamp_end("clamp", 0, true);
      model->add_point_force(model->network().rods()[0].vertices.back(),
                             Vector3(0, 0.3, 1.0));
      model->finalize();
      VectorType u = model->create_vector();
      for (unsigned int i = 0; i < u.size(); ++i)
        u[i] = 1e-3 * std::cos(0.7 * i);
      u.compress(dealii::VectorOperation::insert);
      residual = model->create_vector();
      model->initialize_matrix(tangent);
      model->assemble(u, 1.0, &residual, &tangent);
    }
  };

  /// |K x - b| / |b| for the solution x of @p kind's solver.
  double
  backward_error(RodSystem &system, const std::string &kind, VectorType &x)
  {
    const auto solver = TangentFactorization::create(system.tangent, kind);
    EXPECT_EQ(solver->name(), kind);
    solver->factorize();
    x = system.residual;
    solver->solve(system.residual, x);
    VectorType kx = x;
    system.tangent.vmult(kx, x);
    kx.add(-1.0, system.residual);
    return kx.l2_norm() / system.residual.l2_norm();
  }

  /// Three rods welded at a hub at the origin.
  std::unique_ptr<RodNetwork>
  three_rod_hub()
  {
    auto network = std::make_unique<RodNetwork>();
    for (const Vector3 &end :
         {Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1)})
      network->add_rod(generators::straight(Vector3::Zero(), end, 8),
                       false,
                       end.cross(Vector3(1, 1, 1)).normalized(),
                       "simple");
    network->add_junction("hub",
                          JunctionKind::welded,
                          {{0, true}, {1, true}, {2, true}});
    return network;
  }

  /// The 5-point Laplacian of a square grid of @p side x @p side points:
  /// a band no renumbering narrows to "auto"'s (its half-width is at
  /// least @p side).
  MatrixType
  grid_laplacian(const unsigned int side)
  {
    const unsigned int n = side * side;
    dealii::IndexSet   all(n);
    all.add_range(0, n);
    dealii::TrilinosWrappers::SparsityPattern pattern(all, MPI_COMM_WORLD);
    const auto neighbours = [side](const unsigned int i) {
      std::vector<unsigned int> near{i};
      if (i % side > 0)
        near.push_back(i - 1);
      if (i % side + 1 < side)
        near.push_back(i + 1);
      if (i >= side)
        near.push_back(i - side);
      if (i + side < side * side)
        near.push_back(i + side);
      return near;
    };
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : neighbours(i))
        pattern.add(i, j);
    pattern.compress();
    MatrixType laplacian;
    laplacian.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : neighbours(i))
        laplacian.set(i, j, i == j ? 4.0 : -1.0);
    laplacian.compress(dealii::VectorOperation::insert);
    return laplacian;
  }
} // namespace

TEST(TangentFactorization, BandAndKluSolveARodsTangent)
{
  RodSystem  rod(rodnet::testing::straight_network(20));
  VectorType band_x, klu_x;
  EXPECT_LT(backward_error(rod, "band", band_x), 1e-12);
  EXPECT_LT(backward_error(rod, "klu", klu_x), 1e-12);
  VectorType difference = band_x;
  difference.add(-1.0, klu_x);
  EXPECT_LT(difference.l2_norm(), 1e-8 * klu_x.l2_norm());
}

// The two-column solve (the midpoint rule's Newton and Sherman-Morrison
// solves at once, one pass of KLU over its factors) gives each column the
// values of a one-column solve, bit for bit, and solves both to their
// backward error.
TEST(TangentFactorization, TwoColumnSolveIsTwoSolves)
{
  for (const std::string kind : {"klu", "band"})
    {
      // KLU on a hub's tangent (junction DoFs), the band on a rod's.
      RodSystem  rod(kind == "klu" ? three_rod_hub() :
                                    std::unique_ptr<RodNetwork>(
                                      rodnet::testing::straight_network(20)));
      const auto solver = TangentFactorization::create(rod.tangent, kind);
      solver->factorize();
      const VectorType &b = rod.residual;
      VectorType        c = b;
      for (unsigned int i = 0; i < c.size(); ++i)
        c[i] = std::sin(0.3 * i + 1);
      c.compress(dealii::VectorOperation::insert);
      VectorType x = b, y = c, x1 = b, y1 = c;
      solver->solve(b, x, c, y);
      solver->solve(b, x1);
      solver->solve(c, y1);
      for (unsigned int i = 0; i < b.size(); ++i)
        {
          ASSERT_EQ(x[i], x1[i]) << kind << " row " << i;
          ASSERT_EQ(y[i], y1[i]) << kind << " row " << i;
        }
      const std::pair<const VectorType *, const VectorType *> systems[] =
        {{&b, &x}, {&c, &y}};
      for (const auto &[rhs, solution] : systems)
        {
          VectorType k_solution = *solution;
          rod.tangent.vmult(k_solution, *solution);
          k_solution.add(-1.0, *rhs);
          EXPECT_LT(k_solution.l2_norm(), 1e-11 * rhs->l2_norm()) << kind;
        }
    }
}

/// |x - x_klu| / |x_klu| between the solutions by the band LU (renumbered
/// where that narrows the band) and by KLU.
double
band_against_klu(RodSystem &system)
{
  VectorType band_x, klu_x;
  EXPECT_LT(backward_error(system, "band", band_x), 1e-12);
  EXPECT_LT(backward_error(system, "klu", klu_x), 1e-12);
  VectorType difference = band_x;
  difference.add(-1.0, klu_x);
  return difference.l2_norm() / klu_x.l2_norm();
}

TEST(TangentFactorization, AutoTakesTheBandWhereARenumberingNarrowsIt)
{
  // A rod as numbered; a small hub and an inextensible rod (its
  // multipliers numbered last) renumbered by reverse Cuthill-McKee, with
  // the solutions of KLU; KLU for a lattice, whose band stays wide.
  RodSystem rod(rodnet::testing::straight_network(20));
  EXPECT_EQ(TangentFactorization::create(rod.tangent, "auto")->name(), "band");
  RodSystem hub(three_rod_hub());
  EXPECT_EQ(TangentFactorization::create(hub.tangent, "auto")->name(), "band");
  EXPECT_LT(band_against_klu(hub), 1e-8);
  auto inextensible_rod = rodnet::testing::straight_network(20);
  inextensible_rod->create_triangulation();
  inextensible_rod->set_inextensible(0);
  RodSystem inextensible(std::move(inextensible_rod));
  EXPECT_EQ(TangentFactorization::create(inextensible.tangent, "auto")->name(),
            "band");
  EXPECT_LT(band_against_klu(inextensible), 1e-8);
  RodSystem lattice(
    build_rod_network(network_generators::square_lattice(6, 6, 1.0),
                      4,
                      "simple")
      .network);
  EXPECT_EQ(TangentFactorization::create(lattice.tangent, "auto")->name(),
            "klu");
  EXPECT_THROW(TangentFactorization::create(rod.tangent, "cholesky"),
               std::invalid_argument);
}

TEST(TangentFactorization, AutoTakesMumpsForLargeWideBandedTangents)
{
  // Grids of just fewer and just as many rows as the threshold.
  const auto side = static_cast<unsigned int>(
    std::ceil(std::sqrt(TangentFactorization::min_auto_mumps_rows)));
  ASSERT_LT((side - 1) * (side - 1),
            unsigned(TangentFactorization::min_auto_mumps_rows));
  EXPECT_EQ(
    TangentFactorization::create(grid_laplacian(side - 1), "auto")->name(),
    "klu");
  const MatrixType laplacian = grid_laplacian(side);
  const auto       solver    = TangentFactorization::create(laplacian, "auto");
  EXPECT_EQ(solver->name(), "mumps");
  // It solves: L x = L 1 gives x = 1.
  VectorType ones(laplacian.locally_owned_range_indices(), MPI_COMM_WORLD);
  ones           = 1.0;
  VectorType rhs = ones, x = ones;
  laplacian.vmult(rhs, ones);
  solver->factorize();
  solver->solve(rhs, x);
  x -= ones;
  EXPECT_LT(x.linfty_norm(), 1e-12);
}

TEST(TangentFactorization, AKeptFactorizationServesTheSamePatternOnly)
{
  RodSystem                 rod(rodnet::testing::straight_network(20));
  TangentFactorizationCache cache;
  for (const std::string kind : {"band", "klu", "mumps"})
    {
      const auto first = cache.get(rod.tangent, kind);
      EXPECT_EQ(first->name(), kind);
      EXPECT_EQ(cache.get(rod.tangent, kind), first) << kind;

      // New values, the same pattern: the kept factorization solves them.
      VectorType u = rod.model->create_vector();
      for (unsigned int i = 0; i < u.size(); ++i)
        u[i] = 2e-3 * std::sin(1.3 * i);
      u.compress(dealii::VectorOperation::insert);
      rod.model->assemble(u, 0.5, &rod.residual, &rod.tangent);
      const auto kept = cache.get(rod.tangent, kind);
      EXPECT_EQ(kept, first) << kind;
      kept->factorize();
      VectorType x = rod.residual;
      kept->solve(rod.residual, x);
      VectorType kx = x;
      rod.tangent.vmult(kx, x);
      kx.add(-1.0, rod.residual);
      EXPECT_LT(kx.l2_norm(), 1e-12 * rod.residual.l2_norm()) << kind;
    }
  // Another kind, another matrix, another pattern: a new factorization.
  const auto klu = cache.get(rod.tangent, "klu");
  EXPECT_NE(cache.get(rod.tangent, "band"), klu);
  RodSystem  longer(rodnet::testing::straight_network(30));
  const auto band = cache.get(rod.tangent, "band");
  EXPECT_NE(cache.get(longer.tangent, "band"), band);
  RodSystem hub(three_rod_hub());
  hub.model->initialize_matrix(rod.tangent); // same object, new pattern
  const auto after = cache.get(rod.tangent, "klu");
  EXPECT_NE(after, klu);
  EXPECT_EQ(cache.get(rod.tangent, "klu"), after);
}

namespace
{
  /// The entries of the L and U of @p tangent by KLU with its own order
  /// (AMD on K + K^T, block triangular form), rows scaled by KLU's
  /// @p scale and pivot tolerance @p tolerance.
  double
  klu_fill(const MatrixType &tangent, const int scale, const double tolerance)
  {
    const Epetra_CrsMatrix &m = tangent.trilinos_matrix();
    std::vector<int>        offsets(m.NumMyRows() + 1, 0), columns;
    std::vector<double>     values;
    for_each_entry(m, [&](const int row, const int column, const double v) {
      ++offsets[row + 1];
      columns.push_back(column);
      values.push_back(v);
    });
    for (std::size_t row = 0; row + 1 < offsets.size(); ++row)
      offsets[row + 1] += offsets[row];
    klu_common common;
    klu_defaults(&common);
    common.scale    = scale;
    common.tol      = tolerance;
    const int     n = m.NumMyRows();
    klu_symbolic *symbolic =
      klu_analyze(n, offsets.data(), columns.data(), &common);
    klu_numeric *numeric = klu_factor(offsets.data(),
                                      columns.data(),
                                      values.data(),
                                      symbolic,
                                      &common);
    const double fill    = numeric == nullptr ?
                             std::nan("") :
                             double(numeric->lnz) + numeric->unz + numeric->nzoff;
    klu_free_numeric(&numeric, &common);
    klu_free_symbolic(&symbolic, &common);
    return fill;
  }

  /// The fill of @p tangent as Trilinos Amesos KLU factorized it before
  /// issue 33: rows unscaled (Amesos_Control's ScaleMethod 0), KLU's pivot
  /// tolerance 1e-3.
  double
  amesos_klu_fill(const MatrixType &tangent)
  {
    return klu_fill(tangent, 0, 1e-3);
  }
} // namespace

TEST(TangentFactorization, KluKeepsItsFillOnAnIndefiniteLatticeTangent)
{
  RolledLattice lattice;
  // Flat, the tangent is positive definite: the fill of the order (its
  // diagonal pivots), a small multiple of the tangent's entries.
  lattice.assemble_rolled(0);
  const auto klu = TangentFactorization::create(lattice.tangent, "klu");
  klu->factorize();
  const double entries = lattice.tangent.n_nonzero_elements();
  const double order   = klu->factor_entries();
  EXPECT_LT(order, 2.5 * entries);
  EXPECT_EQ(amesos_klu_fill(lattice.tangent), order);

  // Rolled: no more than the order's fill, and a backward stable solve
  // (9e-22 measured).
  lattice.assemble_rolled(1);
  klu->factorize();
  EXPECT_LE(klu->factor_entries(), 1.01 * order);
  VectorType b = lattice.model->create_vector();
  for (unsigned int i = 0; i < b.size(); ++i)
    b[i] = std::sin(0.37 * i + 1);
  b.compress(dealii::VectorOperation::insert);
  EXPECT_LT(normwise_backward_error(*klu, lattice.tangent, b), 1e-15);
  // Amesos's pivoting leaves the diagonal here and fills far beyond the
  // order (1.72 times measured): the factorization of 3641289.
  EXPECT_GT(amesos_klu_fill(lattice.tangent), 1.3 * order);
}

namespace
{
  /**
   * A welded square lattice of 3 x 3 cells of side 1 in inextensible rods
   * of 40 segments per beam (the ribbon of Figs. 9-10: EI1 = 1,
   * EI2 = 0.01, GJ = 0.04; 4936 DoFs, 960 of them multipliers) pinned at
   * its corners, and its tangent, a KKT matrix whose multipliers' diagonal
   * is zero, at a state off equilibrium: every DoF, the multipliers too,
   * moved by 0.1 cos(0.7 i).
   */
  struct InextensibleLattice
  {
    static constexpr unsigned int cells = 3;

    std::unique_ptr<RodModel> model;
    MatrixType                tangent;

    InextensibleLattice()
    {
      model = pinned_square_lattice(cells, 1, 40, {1e4, 1, 0.01, 0.04}, true);
      rodnet::testing::assemble_shaken(*model, tangent, 0.1);
    }
  };

  /// Whether each row of @p tangent with a zero diagonal entry comes after
  /// every row it couples in saddle_point_order(), which is a permutation.
  bool
  multipliers_follow_their_rows(const MatrixType &tangent)
  {
    const Epetra_CrsMatrix &m = tangent.trilinos_matrix();
    const int               n = m.NumMyRows();
    std::vector<int>        offsets(n + 1, 0), columns;
    std::vector<bool>       zero_diagonal(n, true);
    for_each_entry(m, [&](const int row, const int column, const double v) {
      ++offsets[row + 1];
      columns.push_back(column);
      if (row == column && v != 0)
        zero_diagonal[row] = false;
    });
    for (int row = 0; row < n; ++row)
      offsets[row + 1] += offsets[row];
    const std::vector<int> order =
      saddle_point_order(offsets, columns, zero_diagonal);
    std::vector<int> place(n, -1);
    for (int k = 0; k < int(order.size()); ++k)
      place.at(order[k]) = k;
    bool follow = std::count(place.begin(), place.end(), -1) == 0;
    for (int row = 0; row < n; ++row)
      for (int k = offsets[row]; k < offsets[row + 1] && zero_diagonal[row];
           ++k)
        follow = follow &&
                 (zero_diagonal[columns[k]] || place[columns[k]] < place[row]);
    return follow;
  }
} // namespace

TEST(TangentFactorization, KluKeepsItsFillOnAnInextensibleNetworksTangent)
{
  InextensibleLattice lattice;
  EXPECT_TRUE(multipliers_follow_their_rows(lattice.tangent));
  const auto klu = TangentFactorization::create(lattice.tangent, "klu");
  klu->factorize();
  // 2.24 times the tangent's entries measured. KLU's own order (AMD on
  // K + K^T), with the pivots of issue 33 or KLU's default tolerance, filled
  // 2.95 times as much: a multiplier it eliminates before the rows it
  // couples has a zero pivot. The solve below left 1.9e-7 of b there.
  const double entries = lattice.tangent.n_nonzero_elements();
  const double fill    = klu->factor_entries();
  EXPECT_LT(fill, 2.5 * entries);
  EXPECT_GT(klu_fill(lattice.tangent, 2, 1e-8), 2 * fill);
  EXPECT_GT(klu_fill(lattice.tangent, 2, 1e-3), 2 * fill);

  // A backward stable solve: 9e-20 and |K x - b| = 6e-12 |b| measured
  // (1.4e-10 unrefined, 4.2e-10 unrefined with the tolerance of issue 33).
  VectorType b = lattice.model->create_vector();
  for (unsigned int i = 0; i < b.size(); ++i)
    b[i] = std::sin(0.37 * i + 1);
  b.compress(dealii::VectorOperation::insert);
  EXPECT_LT(normwise_backward_error(*klu, lattice.tangent, b), 1e-17);
  VectorType x = b;
  klu->solve(b, x);
  VectorType kx = x;
  lattice.tangent.vmult(kx, x);
  kx.add(-1.0, b);
  EXPECT_LT(kx.l2_norm(), 1e-10 * b.l2_norm());
}

TEST(TangentFactorization, ASingularTangentIsReported)
{
  // A 3 x 3 matrix whose last row and column are zero.
  dealii::IndexSet all(3);
  all.add_range(0, 3);
  dealii::TrilinosWrappers::SparsityPattern pattern(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      pattern.add(i, j);
  pattern.compress();
  MatrixType singular;
  singular.reinit(pattern);
  singular.set(0, 0, 2.0);
  singular.set(0, 1, 1.0);
  singular.set(1, 0, 1.0);
  singular.set(1, 1, 2.0);
  singular.compress(dealii::VectorOperation::insert);
  for (const std::string kind : {"band", "klu", "mumps"})
    {
      const auto solver = TangentFactorization::create(singular, kind);
      try
        {
          solver->factorize();
          ADD_FAILURE() << kind << " factorized a singular matrix";
        }
      catch (const SingularTangent &e)
        {
          EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos)
            << e.what();
        }
    }
}

TEST(TangentFactorization, NoxLineSearchesApplyTheJacobianThroughOurGroup)
{
  // r_i(y) = y_i^3 + y_i - c_i from y = 3: the full Newton step
  // overshoots; NOX's line searches (the polynomial one takes the slope
  // F^T J d from applyJacobian) must converge to the root.
  const unsigned int        n = 4;
  const std::vector<double> c = {0.5, 1.0, 2.0, 10.0};
  NewtonSolver::Problem     problem;
  problem.residual = [&](const VectorType &y, VectorType &r) {
    for (unsigned int i = 0; i < n; ++i)
      r[i] = y[i] * y[i] * y[i] + y[i] - c[i];
    r.compress(dealii::VectorOperation::insert);
  };
  problem.tangent = [&](const VectorType &y, MatrixType &k) {
    for (unsigned int i = 0; i < n; ++i)
      k.set(i, i, 3 * y[i] * y[i] + 1);
    k.compress(dealii::VectorOperation::insert);
  };
  for (const std::string search : {"full step", "backtrack", "polynomial"})
    for (const std::string kind : {"band", "klu", "mumps"})
      {
        MatrixType tangent;
        rodnet::testing::diagonal_tangent(n, tangent);
        VectorType x(tangent.locally_owned_domain_indices(), MPI_COMM_WORLD);
        x = 3.0;
        NewtonSolver::Parameters parameters;
        parameters.tolerance     = 1e-12;
        parameters.line_search   = search;
        parameters.linear_solver = kind;
        const auto result = NewtonSolver(parameters).solve(problem, x, tangent);
        EXPECT_TRUE(result.converged)
          << search << ", " << kind << ": " << result.failure;
        for (unsigned int i = 0; i < n; ++i)
          EXPECT_NEAR(x[i] * x[i] * x[i] + x[i], c[i], 1e-11)
            << search << ", " << kind;
      }
}
