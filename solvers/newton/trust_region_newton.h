#ifndef RODNET_SOLVERS_NEWTON_TRUST_REGION_NEWTON_H
#define RODNET_SOLVERS_NEWTON_TRUST_REGION_NEWTON_H

#include <solvers/newton/newton_globalization.h>
#include <solvers/newton/newton_solver.h>

namespace rodnet
{
  /**
   * Newton's method globalized by a trust region on the potential, for
   * problems whose residual is the gradient of a potential Pi
   * (NewtonSolver::Problem::energy): `Line search = trust region`.
   *
   * Each iteration minimizes the quadratic model
   *   m(p) = Pi + g.p + 1/2 p.K p   over   |D p| <= Delta
   * (Nocedal & Wright, Numerical Optimization, 2nd ed., ch. 4) with the
   * tangent K, the gradient g (the residual) and the diagonal metric
   * D = diag(sqrt|K_ii|), kept as the running maximum over the iterations
   * (Moré, Lecture Notes in Math. 630, 1978): positions, angles and
   * quaternion components have different units, and |D p|^2 is the
   * energy the diagonal of K gives the step. In the scaled variables
   * q = D p the model's matrix is D^-1 K D^-1, with a unit diagonal. The
   * subproblem is solved as Moré & Sorensen (SIAM J. Sci. Stat. Comput.
   * 4, 1983) do, with sparse LDL^T factorizations of D^-1 K D^-1 + mu I
   * (their inertia says which mu make it positive definite): the
   * Newton step where it is inside the region, else the mu >= 0 whose step
   * has length Delta (Newton's method on 1/|q(mu)| - 1/Delta, safeguarded
   * by bisection). Where the tangent is indefinite, mu lies above minus
   * its lowest eigenvalue (the lowest eigenpair by lowest_eigenpairs()),
   * so the step turns along the direction of negative curvature; in the
   * hard case (the gradient orthogonal to that direction) the step is
   * completed along it to the boundary.
   *
   * A step is taken where the energy falls by more than 1e-4 of the
   * model's predicted decrease (ratio rho); Delta is quartered where
   * rho < 1/4 and doubled where rho > 3/4 at the boundary (N&W alg. 4.1),
   * and then the doubled step is tried at once, without a new tangent,
   * and kept while the model holds and the energy is lower (internal
   * doubling, Dennis & Schnabel 1983, alg. A6.4.5): the descent along a
   * negative curvature often goes far from where it starts.
   * The first trial is the Newton step where the tangent is positive
   * definite. Near convergence, where the predicted decrease is below the
   * energy's resolution (1e-8 of the energy: the energy of a stiff rod is
   * a sum of large terms that cancel), steps are judged by the residual
   * norm, which Newton's steps lower there.
   *
   * At a saddle: an iterate that passes the convergence test while the
   * tangent has a negative eigenvalue is not accepted; the solver steps
   * along the eigenvector, downhill, doubling the step while the energy
   * falls (from a step whose predicted decrease is 1e-6 of the energy),
   * and goes on from there. Where no step along it lowers the energy
   * beyond its resolution (a zero eigenvalue that rounding made negative: a
   * symmetry mode), the iterate is converged.
   *
   * Costs per iteration: one assembly of the tangent, one to a dozen
   * sparse factorizations (one where the Newton step is inside the
   * region), one energy evaluation per trial, and where the tangent is
   * indefinite one lowest eigenpair. One process only.
   */
  class TrustRegionNewton
  {
  public:
    using VectorType = NewtonSolver::VectorType;
    using MatrixType = NewtonSolver::MatrixType;

    struct Parameters
    {
      /// Converged when |residual|_2 <= tolerance, unless the problem
      /// brings its own test (Problem::converged).
      double tolerance = 1e-10;
      /// Iterations (tangent assemblies) at most.
      unsigned int max_iterations = 25;
      /// Trial steps (energy evaluations) per iteration at most.
      unsigned int max_trials = 30;
      /// eta: a step is taken where rho > eta.
      double acceptance = 1e-4;
      /// A step of the subproblem lies within (1 +- this) Delta.
      double boundary_accuracy = 0.1;
      /// Factorizations per subproblem at most.
      unsigned int max_shifts = 12;
      /// Relative resolution of the assembled energy: changes below this
      /// times |energy| are judged by the residual instead.
      double energy_resolution = 1e-8;
    };

    explicit TrustRegionNewton(const Parameters &parameters);

    /**
     * Minimizes the potential of @p problem from @p x, which holds the
     * minimum on return if converged (else the last accepted iterate).
     * @p tangent must have the sparsity of the problem's tangent. The
     * result counts tangent assemblies as iterations.
     */
    NewtonSolver::Result
    solve(const NewtonSolver::Problem &problem,
          VectorType                  &x,
          MatrixType                  &tangent) const;

  private:
    Parameters parameters;
  };

  /// TrustRegionNewton as Newton's globalization "trust region", with the
  /// tolerance and iterations of NewtonSolver::Parameters.
  class TrustRegionGlobalization : public NewtonGlobalization
  {
  public:
    NewtonSolver::Result
    solve(const NewtonSolve &call) const override;
  };
} // namespace rodnet

#endif
