// Krylov solvers with ML's algebraic multigrid against MUMPS on a welded
// lattice's tangent (issue 37: "which solver for which structure"; run it
// under mpirun -np P for P processes).
//
// The lattice of mumps_processes: n x n cells, beams of length 0.1 in 10
// segments, EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67, pinned at the four
// corners, its tangent at the flat state (positive definite; Newton's first
// tangent under gravity). Right-hand side of entries cos(0.3 i). Each solver
// is timed once on rank 0 after a barrier, set-up and solve apart:
//  - MUMPS (MumpsFactorization): analysis and factorization, then its solve;
//  - GMRES (AztecOO, restarted every 200) to |K x - b| < 1e-10 |b|, at most
//    --max-iterations, preconditioned by ML's smoothed aggregation
//    (ML_Epetra::SetDefaults("SA"), two sweeps of the smoother, KLU on the
//    coarsest level) with
//    - ML's default near null space, one constant per row;
//    - the six rigid motions of the network as the near null space: three
//      translations of every vertex and three infinitesimal rotations e_a,
//      which move a vertex at x by e_a x x, turn a segment of unit tangent
//      t by e_a . t (its twist) and a junction's quaternion at the identity
//      by e_a / 2 (its vector part); multipliers and inert DoFs do not move
//      (solvers/time/rigid_motion_split.h has the same motions, part by
//      part);
//    with symmetric Gauss-Seidel and with Chebyshev smoothing.
// Printed per solver: set-up, solve, iterations ("none": not converged in
// --max-iterations; "lost": AztecOO stopped on a loss of precision) and
// |K x - b| / |b|.
//
// Usage: mpirun -np P iterative_solvers [--cells n] [--max-iterations n]
// (defaults 10 and 2000).
#include <deal.II/base/mpi.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <solvers/checks/dof_roles.h>
#include <solvers/newton/mumps_factorization.h>

#include <Teuchos_ParameterList.hpp>
#include <bench/options.h>
#include <bench/timing.h>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <ml_MultiLevelPreconditioner.h>
#include <tests/common/pinned_lattices.h>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads        = 1;
    unsigned int cells          = 10;
    unsigned int max_iterations = 2000;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--cells", cells, 1),
              bench::number("--max-iterations", max_iterations, 1)};
    }
  };

  /// The six rigid motions of @p model's network at its reference state on
  /// this process's rows @p owned, column by column (ML's layout of
  /// "null space: vectors"; the header says which motion moves what).
  std::vector<double>
  rigid_motions(const RodModel &model, const dealii::IndexSet &owned)
  {
    using Kind                  = DofRoles::Kind;
    const DofRoles      roles   = DofRoles(model);
    const RodNetwork   &network = model.network();
    const std::size_t   n       = owned.n_elements();
    std::vector<double> motions(6 * n, 0.0);
    std::size_t         row = 0;
    for (const auto d : owned)
      {
        double *rotation = &motions[3 * n + row];
        if (roles.kind(d) == Kind::position)
          {
            const unsigned int c = roles.component(d);
            const Vector3      x = network.vertex(roles.owner(d));
            motions[c * n + row] = 1;
            for (unsigned int a = 0; a < 3; ++a)
              rotation[a * n] = Vector3::Unit(a).cross(x)[c];
          }
        else if (roles.kind(d) == Kind::twist)
          {
            const auto [rod, k] = roles.cell_place(roles.owner(d));
            const auto   &chain = network.rods()[rod].vertices;
            const Vector3 t = (network.vertex(chain[(k + 1) % chain.size()]) -
                               network.vertex(chain[k]))
                                .normalized();
            for (unsigned int a = 0; a < 3; ++a)
              rotation[a * n] = t[a];
          }
        else if (roles.kind(d) == Kind::quaternion)
          rotation[(roles.component(d) - 1) * n] = 0.5;
        ++row;
      }
    return motions;
  }

  /// One line of the table.
  void
  report(const std::string &solver,
         const double       setup,
         const double       solve,
         const std::string &iterations,
         const double       relative_residual)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::cout << std::left << std::setw(34) << solver << std::right
              << std::setw(10) << std::setprecision(3) << setup << std::setw(10)
              << solve << std::setw(8) << iterations << std::setw(12)
              << relative_residual << std::endl;
  }

  /// |K x - b| / |b|.
  double
  relative_residual(const MatrixType &K,
                    const VectorType &x,
                    const VectorType &b)
  {
    VectorType r = b;
    K.vmult(r, x);
    r.add(-1.0, b);
    return r.l2_norm() / b.l2_norm();
  }

  /// ML's smoothed aggregation with two sweeps of @p smoother and KLU on
  /// the coarsest level; with @p motions (rigid_motions()) as its near null
  /// space, else ML's default, a constant per row.
  Teuchos::ParameterList
  ml_parameters(const std::string &smoother, std::vector<double> *motions)
  {
    Teuchos::ParameterList parameters;
    ML_Epetra::SetDefaults("SA", parameters);
    parameters.set("ML output", 0);
    parameters.set("smoother: type", smoother);
    parameters.set("smoother: sweeps", 2);
    parameters.set("coarse: type", "Amesos-KLU");
    parameters.set("PDE equations", 1);
    if (motions != nullptr)
      {
        parameters.set("null space: type", "pre-computed");
        parameters.set("null space: dimension", 6);
        parameters.set("null space: vectors", motions->data());
      }
    return parameters;
  }

  /// GMRES with ML set up by @p parameters.
  void
  gmres_with_ml(const std::string     &name,
                const MatrixType      &K,
                const VectorType      &b,
                Teuchos::ParameterList parameters,
                const Options         &options)
  {
    dealii::TrilinosWrappers::PreconditionAMG ml;
    const double                              setup =
      bench::timed_together([&] { ml.initialize(K, parameters); });
    VectorType x = b;
    x            = 0;
    dealii::SolverControl control(options.max_iterations, 1e-10 * b.l2_norm());
    dealii::TrilinosWrappers::SolverGMRES gmres(
      control,
      dealii::TrilinosWrappers::SolverGMRES::AdditionalData(false, 200));
    std::string  outcome = "";
    const double solve   = bench::timed_together([&] {
      try
        {
          gmres.solve(K, x, b, ml);
          outcome = std::to_string(control.last_step());
        }
      catch (const dealii::SolverControl::NoConvergence &)
        {
          outcome = "none";
        }
      catch (const std::exception &)
        {
          // AztecOO's own stop, "loss of precision" (error code -3).
          outcome = "lost";
        }
    });
    report(name, setup, solve, outcome, relative_residual(K, x, b));
  }

  void
  iterative_solvers(const Options &options)
  {
    const auto model =
      rodnet::testing::pinned_square_lattice(options.cells,
                                             0.1,
                                             10,
                                             {1e5, 400, 100, 67},
                                             false);
    MatrixType K;
    model->initialize_matrix(K);
    model->assemble(model->create_vector(), 0.0, nullptr, &K);
    const dealii::IndexSet owned = K.locally_owned_range_indices();
    VectorType             b(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      b[i] = std::cos(0.3 * i);
    b.compress(dealii::VectorOperation::insert);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "lattice " << options.cells << " x " << options.cells << "  "
                << K.m() << " DoFs  "
                << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                << " process(es)\nsolver                              set-up "
                   "s   solve s   its  |Kx-b|/|b|\n";

    std::unique_ptr<MumpsFactorization> mumps;
    VectorType                          x     = b;
    const double                        setup = bench::timed_together([&] {
      mumps = std::make_unique<MumpsFactorization>(K);
      mumps->factorize();
    });
    const double solve = bench::timed_together([&] { mumps->solve(b, x); });
    report("MUMPS", setup, solve, "-", relative_residual(K, x, b));

    std::vector<double> motions = rigid_motions(*model, owned);
    for (const bool rigid : {false, true})
      for (const std::string smoother : {"symmetric Gauss-Seidel", "Chebyshev"})
        gmres_with_ml(std::string("GMRES, ML ") + (rigid ? "rigid" : "const") +
                        ", " +
                        (smoother == "Chebyshev" ? "Chebyshev" : "sym. GS"),
                      K,
                      b,
                      ml_parameters(smoother, rigid ? &motions : nullptr),
                      options);
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("iterative_solvers",
                              argc,
                              argv,
                              iterative_solvers);
}
