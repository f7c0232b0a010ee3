#ifndef RODNET_SOLVERS_RELAXATION_DYNAMIC_RELAXATION_H
#define RODNET_SOLVERS_RELAXATION_DYNAMIC_RELAXATION_H

#include <core/dr_model.h>
#include <solvers/statics/static_solver.h>

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Static equilibrium of a DrModel by dynamic relaxation with kinetic
   * damping (Barnes; Sakai, Ohsaki & Adriaenssens 2020): the load factor
   * goes from 0 to 1 in equal steps, and each step is relaxed to
   * equilibrium by explicit central-difference pseudo-dynamics
   *   v_{t+dt/2} = v_{t-dt/2} + dt M^{-1} R_t,
   *   x_{t+dt}   = x_t + dt v_{t+dt/2},
   * with R = -residual the out-of-balance force and M the lumped fictitious
   * masses of DrModel::fictitious_masses(). When the kinetic energy drops,
   * its peak has passed: the state moves back to the estimated peak
   *   x* = x_{t+dt} - 3/2 dt v_{t+dt/2} + dt^2/2 M^{-1} R_t,
   * the velocities are zeroed and the masses recomputed there. The step has
   * converged when |R| over the free DoFs is below residual_tolerance times
   * the force scale (see Parameters).
   *
   * A step is unstable when the residual or the kinetic energy becomes
   * non-finite, or when the kinetic energy grows by instability_growth over
   * at least five consecutive iterations that each raise it and reverse the
   * velocities (v_{t+dt/2} . M v_{t-dt/2} < 0): the signature of a mode
   * that central differences amplify, which flips sign every step and
   * leaves no kinetic-energy peak to damp. The state then returns to the
   * last converged step, which is retried with half the time step (kept
   * from then on). Below min_time_step_fraction of the nominal step, and
   * after max_iterations without convergence, run() throws SolverFailure;
   * the state is then the last converged one, never a non-finite one.
   *
   * On several processes (DrModel's communicator) each process moves the
   * DoFs its elements touch and counts the norms and the kinetic energy on
   * the DoFs it owns (DrProcessShare), so every process takes the same
   * decisions; a converged state is completed on every process before the
   * observer sees it.
   */
  class DynamicRelaxation
  {
  public:
    struct Parameters
    {
      /// Load steps: the load factor reaches k / n_steps at step k.
      unsigned int n_steps = 1;
      /// Pseudo-time step. The masses are those of a unit step, stable by
      /// the Gershgorin bound for time_step <= sqrt(2 mass_scaling).
      double time_step = 1;
      /// Factor (>= 1) on the fictitious masses.
      double mass_scaling = 1;
      /// Converged when |R_free| <= residual_tolerance * max(lambda |f|,
      /// |F|): the larger of the applied load and the current reaction
      /// forces of the supports (F: one 3-vector per support), which are
      /// the forces of a displacement-driven step. Or below the round-off
      /// floor eps |S|_inf L sqrt(n), S the stiffness row sums, L the size.
      double residual_tolerance = 1e-6;
      /// Iterations allowed per load step.
      unsigned int max_iterations = 1000000;
      /// Growth of the kinetic energy over consecutive velocity-reversing
      /// iterations that counts as an instability (see the class).
      double instability_growth = 1e4;
      /// Smallest time step after cuts, as a fraction of time_step.
      double min_time_step_fraction = 1.0 / 1024;
      /// Print a line (iteration, kinetic energy, residual norm) every this
      /// many iterations to the log (0: only per step).
      unsigned int progress_interval = 0;

      /// Declares the entries of these parameters (all but n_steps) in the
      /// current subsection of @p prm, with their defaults and help.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Reads the entries of declare_parameters() from the current
      /// subsection of @p prm.
      void
      parse_parameters(const dealii::ParameterHandler &prm);
    };

    struct StepInfo
    {
      unsigned int step          = 0;
      double       load_factor   = 0;
      unsigned int iterations    = 0; ///< of the converged attempt
      unsigned int peaks         = 0; ///< kinetic-damping restarts
      double       residual_norm = 0; ///< |R_free| at convergence
      double       time_step     = 0;
      double       wall_time     = 0; ///< seconds, failed attempts included
    };

    struct Result
    {
      unsigned int steps            = 0;
      unsigned int total_iterations = 0; ///< failed attempts included
      unsigned int time_step_cuts   = 0;
      double       time_step        = 0; ///< in use at the end
    };

    using Observer =
      std::function<void(const StepInfo &, const DrVector &solution)>;

    /// Throws std::invalid_argument naming an inadmissible parameter.
    DynamicRelaxation(const DrModel    &model,
                      const Parameters &parameters,
                      std::ostream     *log = nullptr);

    /**
     * Runs the load steps from the state @p u (usually zero) at load factor
     * 0, calling @p on_converged after every step. Throws SolverFailure
     * naming the load factor, the time step and the iteration when a step
     * cannot be completed.
     */
    Result
    run(DrVector &u, const Observer &on_converged);

  private:
    /// How a relaxation attempt ended.
    struct Attempt
    {
      bool         converged     = false;
      bool         unstable      = false;
      unsigned int iterations    = 0;
      unsigned int peaks         = 0;
      double       residual_norm = 0;
      std::string  reason; ///< why it did not converge
    };

    /// The fictitious motion of a relaxation: lumped masses, velocities
    /// and accelerations, and the record of the kinetic energy.
    struct Motion
    {
      DrVector     masses, velocity, acceleration;
      double       kinetic_energy_before = 0;
      bool         from_rest             = true;
      unsigned int growing               = 0; ///< iterations in a row of growth
      double       growth_base           = 0; ///< kinetic energy before them
    };

    /// Relaxes @p u at @p load_factor with time step @p dt.
    Attempt
    relax(DrVector &u, double load_factor, double dt) const;

    /**
     * One iteration of relax() from @p u with its residual @p r: a
     * leapfrog step of @p motion, kinetic damping at a peak (counted in
     * @p attempt), the residual at the new state and, every
     * progress_interval iterations, a line in the log. Returns why the
     * motion is unstable, nothing where it carries on.
     */
    std::optional<std::string>
    advance(DrVector &u,
            DrVector &r,
            double    load_factor,
            double    dt,
            Motion   &motion,
            Attempt  &attempt) const;

    /**
     * Relaxes load step @p step at @p load_factor from @p u, halving the
     * time step @p dt (and going back to @p last_converged) while the
     * motion is unstable; counts iterations and cuts in @p result. Throws
     * SolverFailure naming the step, the time step and the iteration where
     * it does not converge or the time step reaches its minimum.
     */
    Attempt
    relax_cutting_time_step(DrVector       &u,
                            const DrVector &last_converged,
                            unsigned int    step,
                            double          load_factor,
                            double         &dt,
                            Result         &result) const;

    /// The residual that rounding errors of the positions alone reach,
    /// from the fictitious @p masses.
    double
    residual_floor(const DrVector &masses) const;

    /**
     * One leapfrog step of @p u under the residual @p r; from rest the
     * first kick is half a step, so that the velocity is centred
     * (v_{-dt/2} = -v_{dt/2}). Returns the kinetic energy and stores in
     * @p reversal v_{t+dt/2} . M v_{t-dt/2}.
     */
    double
    leapfrog(DrVector       &u,
             const DrVector &r,
             double          dt,
             Motion         &motion,
             double         &reversal) const;

    /// Why the motion is unstable at @p kinetic_energy (growing while the
    /// velocities reverse), or empty.
    std::string
    instability(double kinetic_energy, double reversal, Motion &motion) const;

    /// Kinetic damping: at a peak of the kinetic energy, back to the
    /// estimated peak, at rest, with masses at the new state. Returns
    /// whether it damped.
    bool
    damp_at_peak(DrVector &u,
                 double    kinetic_energy,
                 double    dt,
                 Motion   &motion) const;

    /// |r| over the free DoFs (collective).
    double
    free_norm(const DrVector &r) const;

    /// Norm of the reaction forces of all supports for the residual @p r.
    double
    reaction_norm(const DrVector &r) const;

    const DrModel &model;
    Parameters     parameters;
    std::ostream  *log;
  };
} // namespace rodnet

#endif
