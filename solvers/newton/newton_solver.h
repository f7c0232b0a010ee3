#ifndef RODNET_SOLVERS_NEWTON_NEWTON_SOLVER_H
#define RODNET_SOLVERS_NEWTON_NEWTON_SOLVER_H

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <solvers/newton/tangent_factorization.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>

namespace rodnet
{
  class NewtonGlobalization;

  /**
   * Newton's method, globalized as Parameters::line_search says: a line
   * search run by Trilinos NOX (NoxLineSearch) or the trust region
   * (TrustRegionNewton), each registered by name in line_search_registry().
   */
  class NewtonSolver
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;
    using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

    struct Parameters
    {
      /// Converged when |residual|_2 <= tolerance (an absolute force),
      /// unless the problem brings its own test (Problem::converged).
      double       tolerance      = 1e-10;
      unsigned int max_iterations = 25;
      /// A name of line_search_registry(): "energy" (EnergyLineSearch:
      /// needs Problem::energy), "backtrack", "polynomial" (NOX's, on
      /// |residual|), "full step" or "trust region" (TrustRegionNewton:
      /// needs Problem::energy, not run by NOX).
      std::string line_search = "full step";
      /// The direct solver of the Newton systems: "auto", "klu" or "band"
      /// (TangentFactorization).
      std::string linear_solver = "auto";

      /// Whether the globalization judges steps by the problem's potential
      /// (the energy line search and the trust region): its registered
      /// trait (LineSearchTraits).
      bool
      needs_potential() const;

      /// Declares the entries of these parameters ("Line search", "Max
      /// iterations") in the current subsection of @p prm, with their defaults
      /// and help.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Reads the entries of declare_parameters() from the current
      /// subsection of @p prm.
      void
      parse_parameters(const dealii::ParameterHandler &prm);
    };

    /// Outcome of one solve.
    struct Result
    {
      bool         converged     = false;
      unsigned int iterations    = 0;
      double       residual_norm = 0;
      /// Why it failed (empty on success).
      std::string failure;
    };

    /// The nonlinear problem: residual and tangent at a given state. Both
    /// may throw (e.g. ParallelTransportSingular): the solve then fails.
    struct Problem
    {
      std::function<void(const VectorType &x, VectorType &residual)> residual;
      std::function<void(const VectorType &x, MatrixType &tangent)>  tangent;
      /**
       * Optional: for a problem whose residual is the gradient of a
       * potential, the potential at x, with the residual written into
       * @p residual (if not null) by the same assembly. Where set, the
       * residual is computed through it, and the "energy" line search
       * can judge steps by it.
       */
      std::function<double(const VectorType &x, VectorType *residual)> energy;

      /// Sets energy to @p potential and residual to its gradient, which
      /// the same function computes.
      void
      set_potential(std::function<double(const VectorType &x,
                                         VectorType       *residual)> potential)
      {
        energy   = std::move(potential);
        residual = [energy = energy](const VectorType &x, VectorType &r) {
          energy(x, &r);
        };
      }

      /**
       * Optional dense part of the Jacobian: where set, the Jacobian at x
       * is tangent + a b^T, with a and b filled by this function, called
       * right after tangent() at the same x. Linear solves then use the
       * Sherman-Morrison formula around the sparse factorization (two
       * solves per iteration); a sparse matrix cannot hold a b^T.
       */
      std::function<void(const VectorType &x, VectorType &a, VectorType &b)>
        rank_one;
      /**
       * Modified Newton: every iteration of a solve uses the Jacobian (and
       * its factorization) of the solve's first iterate, one assembly and
       * one factorization per solve. It converges linearly, at the rate of
       * the Jacobian's change over the solve: for the small corrections of
       * a time step from a good predictor, as fast as the tolerance needs.
       */
      bool reuse_first_jacobian = false;
      /**
       * Optional convergence test in place of |residual|_2 <= tolerance:
       * called with every iterate, the initial guess included, and its
       * residual; returns whether the iterate is converged. StaticSolver
       * uses it to judge forces and moments separately (ResidualCriterion).
       */
      std::function<bool(const VectorType &x, const VectorType &residual)>
        converged;
    };

    /// Refuses an unknown line search or linear solver with
    /// std::invalid_argument.
    explicit NewtonSolver(const Parameters &parameters);

    ~NewtonSolver();

    /**
     * Solves residual(x) = 0 from the initial guess @p x, which holds the
     * solution on return if converged (and the last iterate otherwise).
     * @p tangent must have the sparsity of the problem's Jacobian. With
     * @p factorizations, the factorization of @p tangent (its symbolic
     * part) is kept there for the next solve with the same tangent.
     */
    Result
    solve(const Problem             &problem,
          VectorType                &x,
          MatrixType                &tangent,
          TangentFactorizationCache *factorizations = nullptr) const;

  private:
    Parameters                                 parameters;
    std::unique_ptr<const NewtonGlobalization> globalization;
  };
} // namespace rodnet

#endif
