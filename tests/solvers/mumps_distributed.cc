// MUMPS on several processes (MumpsFactorization, distributed assembled
// input): a welded lattice's tangent, built whole on every process, is
// split into contiguous rows over all processes (unevenly: process r of P
// owns (r + 1) / (1 + ... + P) of them), and the distributed factorization
// solves it as the one-process MUMPS does, counts the negative pivots that
// the one-process MUMPS and the stability check's LDL^T count, on every
// process, solves two columns as two solves, and reports a singular
// tangent by the same exception on every process. A kept factorization
// (TangentFactorizationCache) serves the same matrix and pattern on every
// process, with new values solved as a new factorization solves them, and
// is renewed on all processes together. On several processes
// "auto" takes MUMPS and "klu" and "band" are refused. Run on 1, 2 and 3
// processes (tests/CMakeLists.txt, RODNET_MPI_TESTS).

#include <deal.II/base/mpi.h>

#include <deal.II/lac/affine_constraints.h>

#include <common/pinned_lattices.h>
#include <common/split_rows.h>
#include <common/two_column_solve.h>
#include <solvers/newton/mumps_factorization.h>
#include <solvers/stability/stability.h>

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

using namespace rodnet;

namespace
{
  const MPI_Comm all_processes = MPI_COMM_WORLD;

  /**
   * A welded lattice of 6 x 6 cells of side 0.1 (4 segments per beam, the
   * rigidities of RolledLattice) pinned at its corners, built whole on
   * each process, and its tangent at every DoF moved by @p amplitude
   * cos(0.7 i): undeformed (positive definite) at 0, indefinite at 0.3.
   * The same tangent, its rows split unevenly over all processes
   * (contiguous_rows()), is the distributed matrix; where @p singular, the row
   * and column of the tenth DoF from the end (on the last process) are zero
   * there.
   */
  struct SplitLattice
  {
    std::unique_ptr<RodModel> model;
    MatrixType                serial;
    dealii::IndexSet          owned;
    MatrixType                distributed;

    explicit SplitLattice(const double amplitude, const bool singular = false)
    {
      model = rodnet::testing::pinned_square_lattice(6,
                                                     0.1,
                                                     4,
                                                     {1e5, 400, 100, 67},
                                                     false,
                                                     MPI_COMM_SELF);
      rodnet::testing::assemble_shaken(*model, serial, amplitude);
      owned = rodnet::testing::contiguous_rows(serial.m(), false);
      rodnet::testing::copy_own_rows(
        serial,
        owned,
        distributed,
        singular ? serial.m() - 10 : std::numeric_limits<unsigned int>::max());
    }

    /// @p serial's entries that this process owns, in a vector over all
    /// processes.
    VectorType
    split(const VectorType &serial) const
    {
      VectorType v(owned, all_processes);
      for (const auto i : owned)
        v[i] = serial[i];
      v.compress(dealii::VectorOperation::insert);
      return v;
    }

    /// |distributed - serial| / |serial|, @p distributed split as split()
    /// splits.
    double
    relative_difference(const VectorType &distributed,
                        const VectorType &serial) const
    {
      double squares = 0;
      for (const auto i : owned)
        squares += std::pow(distributed[i] - serial[i], 2);
      return std::sqrt(dealii::Utilities::MPI::sum(squares, all_processes)) /
             serial.l2_norm();
    }
  };

  /// A smooth right-hand side of @p model (on this process alone), with
  /// @p frequency.
  VectorType
  wave(const RodModel &model, const double frequency)
  {
    VectorType b = model.create_vector();
    for (unsigned int i = 0; i < b.size(); ++i)
      b[i] = std::sin(frequency * i + 1);
    b.compress(dealii::VectorOperation::insert);
    return b;
  }
} // namespace

TEST(MumpsDistributed, SolvesAsOneProcessDoes)
{
  // 1792 DoFs. On one process the same solution bit for bit; on 2 and 3
  // 2.3e-13 (undeformed) and 3.1e-13 (indefinite) apart measured, |K x -
  // b| / |b| = 1.0e-13 and 1.1e-13 (one process: 1.2e-13, 1.3e-13).
  for (const double amplitude : {0.0, 0.3})
    {
      SplitLattice       lattice(amplitude);
      MumpsFactorization one(lattice.serial);
      MumpsFactorization all(lattice.distributed);
      one.factorize();
      all.factorize();
      const VectorType b = wave(*lattice.model, 0.37);
      VectorType       x = b;
      one.solve(b, x);
      const VectorType b_split = lattice.split(b);
      VectorType       x_split = b_split;
      all.solve(b_split, x_split);
      EXPECT_LT(lattice.relative_difference(x_split, x), 1e-10) << amplitude;
      VectorType residual = b_split;
      lattice.distributed.vmult(residual, x_split);
      residual.add(-1.0, b_split);
      EXPECT_LT(residual.l2_norm(), 1e-10 * b_split.l2_norm()) << amplitude;
    }
}

TEST(MumpsDistributed, CountsTheNegativePivotsOnEveryProcess)
{
  SplitLattice       lattice(0.3);
  MumpsFactorization one(lattice.serial);
  MumpsFactorization all(lattice.distributed);
  one.factorize();
  all.factorize();
  const ConstrainedFactorization ldlt(lattice.serial,
                                      dealii::AffineConstraints<double>());
  // 229 of 1792 measured. The distributed factors delay other pivots than
  // the one-process ones do: 31914 entries against 31991 on 2 and 3
  // processes.
  EXPECT_GT(one.negative_pivots().value(), 0u);
  EXPECT_EQ(all.negative_pivots(), one.negative_pivots());
  EXPECT_EQ(all.negative_pivots().value(), ldlt.inertia().negative);
  // The factors of all processes, counted alike on every one.
  EXPECT_GT(all.factor_entries(), 0.5 * lattice.serial.n_nonzero_elements());
  EXPECT_EQ(dealii::Utilities::MPI::max(all.factor_entries(), all_processes),
            dealii::Utilities::MPI::min(all.factor_entries(), all_processes));
}

TEST(MumpsDistributed, TwoColumnSolveIsTwoSolves)
{
  SplitLattice       lattice(0.3);
  MumpsFactorization all(lattice.distributed);
  all.factorize();
  const VectorType b = lattice.split(wave(*lattice.model, 0.37));
  const VectorType c = lattice.split(wave(*lattice.model, 1.3));
  rodnet::testing::two_column_solve(all, b, c);
}

TEST(MumpsDistributed, ASingularTangentThrowsOnEveryProcess)
{
  SplitLattice       lattice(0.3, true);
  MumpsFactorization all(lattice.distributed);
  try
    {
      all.factorize();
      ADD_FAILURE() << "MUMPS factorized a singular matrix";
    }
  catch (const SingularTangent &e)
    {
      EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos)
        << e.what();
    }
}

TEST(MumpsDistributed, AKeptFactorizationServesTheSameMatrixOnEveryProcess)
{
  SplitLattice              lattice(0.0), shaken(0.3);
  TangentFactorizationCache cache;
  const auto                first = cache.get(lattice.distributed, "mumps");
  EXPECT_EQ(cache.get(lattice.distributed, "mumps"), first);
  // New values, the same pattern: kept, and it solves them as a new
  // factorization does (to their rounding).
  lattice.distributed.copy_from(shaken.distributed);
  const auto kept = cache.get(lattice.distributed, "mumps");
  EXPECT_EQ(kept, first);
  const VectorType b = lattice.split(wave(*lattice.model, 0.37));
  VectorType       x = b, fresh_x = b;
  kept->factorize();
  kept->solve(b, x);
  MumpsFactorization fresh(shaken.distributed);
  fresh.factorize();
  fresh.solve(b, fresh_x);
  x -= fresh_x;
  EXPECT_LT(x.l2_norm(), 1e-10 * fresh_x.l2_norm());
  // Another matrix: a new factorization on every process.
  EXPECT_NE(cache.get(shaken.distributed, "mumps"), first);
}

TEST(MumpsDistributed, AutoTakesMumpsOnSeveralProcesses)
{
  const unsigned int n_processes =
    dealii::Utilities::MPI::n_mpi_processes(all_processes);
  if (n_processes == 1)
    GTEST_SKIP() << "one process: auto takes the band or KLU";
  SplitLattice lattice(0.0);
  EXPECT_EQ(TangentFactorization::create(lattice.distributed, "auto")->name(),
            "mumps");
  for (const std::string kind : {"klu", "band"})
    try
      {
        TangentFactorization::create(lattice.distributed, kind);
        ADD_FAILURE() << kind << " took a distributed matrix";
      }
    catch (const std::invalid_argument &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("Linear solver = " + kind), std::string::npos);
        EXPECT_NE(message.find(std::to_string(n_processes) + " processes"),
                  std::string::npos);
        EXPECT_NE(message.find("mumps"), std::string::npos) << message;
      }
}
