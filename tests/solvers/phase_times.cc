// Where a run's time goes (base/phase_times.h): nested phases are charged
// exclusively (an inner phase stops the outer one's clock), so the phases
// never add up to more than the wall time; the model's assembly, a
// factorization from TangentFactorization::create() and its solves are
// charged to their phases; the table lists the phases that took time and
// the rest as "other", adding up to the total given.

#include <base/phase_times.h>
#include <common/pinned_lattices.h>
#include <solvers/newton/tangent_factorization.h>

#include <chrono>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>

using namespace rodnet;
using phase_times::Phase;

namespace
{
  using Clock = std::chrono::steady_clock;

  /// Seconds of @p phase charged so far on this thread.
  double
  charged(const Phase phase)
  {
    return phase_times::seconds()[static_cast<std::size_t>(phase)];
  }

  /// Keeps the processor busy for @p seconds of wall time (a sleep would
  /// do too; a busy wait shows what a computation is charged).
  void
  busy_for(const double seconds)
  {
    const Clock::time_point start = Clock::now();
    while (std::chrono::duration<double>(Clock::now() - start).count() <
           seconds)
      {
      }
  }
} // namespace


TEST(PhaseTimes, NestedPhasesAreChargedExclusively)
{
  phase_times::reset();
  const Clock::time_point start = Clock::now();
  {
    const phase_times::Scope outer(Phase::checks);
    busy_for(0.02);
    {
      const phase_times::Scope inner(Phase::linear_solves);
      busy_for(0.03);
    }
    busy_for(0.01);
  }
  const double wall =
    std::chrono::duration<double>(Clock::now() - start).count();
  // Each phase got at least its own busy time; an inclusive account would
  // charge the outer phase the inner one's 0.03 s as well, and the two
  // would add up to more than the wall time.
  EXPECT_GE(charged(Phase::checks), 0.03);
  EXPECT_GE(charged(Phase::linear_solves), 0.03);
  EXPECT_LE(charged(Phase::checks) + charged(Phase::linear_solves), wall);
  EXPECT_LT(charged(Phase::checks), wall - 0.03);
  // Outside every scope nothing is charged.
  const auto before = phase_times::seconds();
  busy_for(0.01);
  EXPECT_EQ(phase_times::seconds(), before);
}


TEST(PhaseTimes, AssemblyFactorizationAndSolvesAreCharged)
{
  const std::unique_ptr<RodModel> model =
    rodnet::testing::pinned_square_lattice(2, 1, 6, {1e4, 1, 0.5, 0.4}, false);
  MatrixType tangent;
  rodnet::testing::assemble_shaken(*model, tangent, 0.1);
  phase_times::reset();
  VectorType       residual = model->create_vector();
  const VectorType u        = model->create_vector();
  model->assemble(u, 1.0, &residual, &tangent);
  EXPECT_GT(charged(Phase::hessian_assembly), 0);
  EXPECT_EQ(charged(Phase::gradient_assembly), 0);
  model->assemble(u, 1.0, &residual, nullptr);
  EXPECT_GT(charged(Phase::gradient_assembly), 0);

  const auto factorization = TangentFactorization::create(tangent, "mumps");
  EXPECT_GT(charged(Phase::factorization_analysis), 0);
  EXPECT_EQ(charged(Phase::numeric_factorization), 0);
  factorization->factorize();
  EXPECT_GT(charged(Phase::numeric_factorization), 0);
  EXPECT_EQ(charged(Phase::linear_solves), 0);
  VectorType x = model->create_vector();
  factorization->solve(residual, x);
  EXPECT_GT(charged(Phase::linear_solves), 0);
  // The wrapper forwards what it is asked to the solver it times.
  EXPECT_EQ(factorization->name(), "mumps");
  EXPECT_GT(factorization->factor_entries(), 0);
  EXPECT_TRUE(factorization->negative_pivots().has_value());
}


TEST(PhaseTimes, TheTableAddsUpToTheTotal)
{
  phase_times::reset();
  {
    const phase_times::Scope phase(Phase::outputs);
    busy_for(0.02);
  }
  const double      total = 0.05;
  std::stringstream out;
  phase_times::write_table(out, total, MPI_COMM_WORLD);
  const std::string text = out.str();
  EXPECT_NE(text.find("where the time went"), std::string::npos) << text;
  // Only phases that took time are listed.
  EXPECT_EQ(text.find("Hessian assembly"), std::string::npos) << text;
  const std::regex row(
    R"(\n  (outputs|other) +([0-9.]+) +([0-9.]+) +([0-9.]+) %)");
  double       sum  = 0;
  unsigned int rows = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), row);
       it != std::sregex_iterator();
       ++it, ++rows)
    {
      EXPECT_EQ((*it)[2], (*it)[3]) << "one process: least = most";
      sum += std::stod((*it)[3]);
    }
  EXPECT_EQ(rows, 2u) << text;
  EXPECT_NEAR(sum, total, 1e-3) << text;
}
