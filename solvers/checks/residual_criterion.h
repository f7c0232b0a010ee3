#ifndef RODNET_SOLVERS_CHECKS_RESIDUAL_CRITERION_H
#define RODNET_SOLVERS_CHECKS_RESIDUAL_CRITERION_H

#include <core/solvable_model.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/newton/newton_solver.h>

#include <functional>
#include <string>
#include <vector>

namespace rodnet
{
  /// The two parts of a residual (or of a scale for it) that carry different
  /// units.
  struct ResidualParts
  {
    /// Position rows: forces (N).
    double force = 0;
    /// Twist rows and junction rotations: moments (N m).
    double moment = 0;
  };

  /// Rounding noise of a residual (ResidualCriterion::roundoff_noise()).
  struct RoundoffNoise
  {
    /// Twice the larger noise norm of two realizations, per part (N, N m):
    /// the residual Newton can be expected to reach.
    ResidualParts floor;
    /// One realization of the noise, per DoF.
    std::vector<double> rows;
  };

  /// A Newton solve judged by a ResidualCriterion: Newton's result, the
  /// parts of the final residual, and what judged it.
  struct JudgedResult : NewtonSolver::Result
  {
    ResidualParts residual;
    /// The loads' scales and the rounding noise of the solve.
    ResidualParts scale;
    RoundoffNoise noise;
    /// Whether a floor is not well below the loads in some part
    /// (ResidualCriterion::inconclusive()): the residual then cannot show
    /// equilibrium alone.
    bool rounding_limited = false;
  };

  /**
   * When a residual of a SolvableModel counts as converged (doc/user_guide.md,
   * "Convergence"). The residual has two parts in different units: the
   * position rows are forces (N); the twist rows are moments about the
   * segment tangents (N m), and the rows of a junction's quaternion are a
   * generalized force that spatial_moment() turns into the moment vector it
   * represents (N m). Each part is judged on its own:
   *   |r_F| <= max(rtol S, floor_F),  |r_M| <= max(rtol S L, floor_M),
   * with L the model's length scale and S the force scale of the loads: the
   * largest of the applied forces, the support reactions, and the applied
   * and reaction moments divided by L (a moment M on a structure of size L
   * is carried by forces of order M / L, and a force F by moments F L).
   * Where no load acts and the reactions are rounding, S is the scale of
   * the internal forces instead (judging_scale()).
   *
   * The floors are what rounding lets a residual reach, measured rather
   * than bounded: every DoF x_j is known to eps |x_j| at best (positions
   * are absolute coordinates), and the change of the residual under random
   * perturbations of that size is the noise Newton's iterates carry
   * (roundoff_noise()). A stiff segment, whose strain |e| / l - 1 rounds to
   * eps |x| / l, makes it large on its rows. Where a floor is not well
   * below the loads, a residual that small does not show equilibrium by
   * itself: the solvers then check the Newton correction K^-1 r of the
   * accepted state, the distance to the exact discrete equilibrium, and
   * warn where it exceeds a limit (rounding_hint() names the segment where
   * the noise is largest).
   */
  class ResidualCriterion
  {
  public:
    /// @p model must be finalized and outlive the criterion.
    explicit ResidualCriterion(const SolvableModel &model);

    /// Force and moment norms of the residual @p r at the state @p u
    /// (constrained rows and unused DoFs do not count).
    ResidualParts
    norms(const VectorType &u, const VectorType &r) const;

    /**
     * Scales of the loads at (@p u, @p load_factor), in N and N m (see the
     * class documentation): applied forces and moments (with the further
     * dead force @p extra_force), the net force and moment of every
     * support, the reaction moments of fixed twists and clamped junctions.
     * Costs two residual assemblies.
     */
    ResidualParts
    load_scale(const VectorType &u,
               double            load_factor,
               const VectorType *extra_force = nullptr) const;

    /**
     * Scales of the internal forces at (@p u, @p load_factor), in N and
     * N m: per row that the residual counts, the generalized forces the
     * stencils exert on it summed without their signs, sum_s |g_s,i| (the
     * forces of a vertex's segments and hinges on it, the moments on a
     * twist; the moments that a junction's rotation rows stand for), which
     * the residual sums to (near) zero at an equilibrium. The force scale
     * is the largest of these forces and of these moments over L, as for
     * the loads. One evaluation of every stencil's gradient.
     */
    ResidualParts
    internal_scale(const VectorType &u, double load_factor) const;

    /**
     * The scales a residual at (@p u, @p load_factor) is judged against:
     * those of the loads (load_scale()), unless the loads vanish: no
     * applied force or moment at all (exactly), and reactions within the
     * rounding floor @p floor (in forces, a moment over L). Then they are
     * those of the internal forces (internal_scale()): a prestressed ring
     * without loads is in equilibrium when its residual is far below the
     * forces its elements exert on each other, not below the rounding of
     * its reactions (issue 33). An applied load, however small, keeps the
     * loads' scales: a residual below the floor cannot show how the
     * structure carries it, and the solvers check the Newton correction.
     * @p loaded, if not null, is the model's unconstrained residual at
     * (@p u, @p load_factor, @p extra_force), which the caller has already
     * assembled: it is taken instead of assembling it again.
     */
    ResidualParts
    judging_scale(const VectorType    &u,
                  double               load_factor,
                  const ResidualParts &floor,
                  const VectorType    *extra_force = nullptr,
                  const VectorType    *loaded      = nullptr) const;

    /**
     * The rounding noise of the residual at (@p u, @p load_factor), with
     * the further dead force @p extra_force: its change under two random
     * perturbations of every DoF by eps |x_j| (in [-1, 1] times that).
     * Costs three residual assemblies.
     */
    RoundoffNoise
    roundoff_noise(const VectorType &u,
                   double            load_factor,
                   const VectorType *extra_force = nullptr) const;

    /// Largest entry of a change of the state: positions over the model
    /// size, angles in rad (a quaternion increment v turns by 2 |v|).
    double
    state_change(const std::vector<double> &change) const;

    /**
     * Why rounding limits the accuracy, in one line: the part of the
     * residual whose floor (of @p noise) is largest against the loads
     * (@p scale), the floor and the loads, and the row where the noise is
     * largest, with its rod and segment, its stiffness in the constrained
     * @p tangent and the ratio to the median stiffness, and what to do.
     */
    std::string
    rounding_hint(const MatrixType    &tangent,
                  const RoundoffNoise &noise,
                  const ResidualParts &scale) const;

    /// The tolerance max(@p rtol scale, floor) of each part (never zero).
    static ResidualParts
    tolerance(const ResidualParts &scale,
              const ResidualParts &floor,
              double               rtol);

    /// Whether a @p floor exceeds @p limit times its @p scale in some part
    /// (a part without loads has nothing to compare with): a residual that
    /// small does not show equilibrium by itself.
    static bool
    inconclusive(const ResidualParts &floor,
                 const ResidualParts &scale,
                 double               limit)
    {
      return (scale.force > 0 && floor.force > limit * scale.force) ||
             (scale.moment > 0 && floor.moment > limit * scale.moment);
    }

    /// Whether both parts of @p norms are within @p tolerance.
    static bool
    within(const ResidualParts &norms, const ResidualParts &tolerance)
    {
      return norms.force <= tolerance.force && norms.moment <= tolerance.moment;
    }

    /// "force residual 1.2e-03 N against a tolerance of ...": for failure
    /// messages.
    static std::string
    describe(const ResidualParts &norms, const ResidualParts &tolerance);

    /// What stall_aware_test() reads and updates during one load step.
    struct StepTolerance
    {
      /// The rounding noise of the step (raised where it is measured again).
      RoundoffNoise &noise;
      /// max(rtol scale, floor) per part (recomputed with the noise).
      ResidualParts &tolerance;
      /// The loads' scales and the relative tolerance.
      const ResidualParts &scale;
      double               rtol;
      /// Where the residual is measured: the load factor and a further
      /// dead force (may be null).
      double            load_factor;
      const VectorType *extra_force;
      /// Excess (largest norm / tolerance of the parts) of the last two
      /// iterates, and whether the noise was measured again this step.
      double excess_before_last = 0, excess_last = 0;
      bool   measured_again = false;
    };

    /**
     * NewtonSolver::Problem::converged for this model: stores the norms of
     * every iterate's residual in @p reached and compares them with the
     * step's tolerance (read at each call, so the caller may change it
     * between solves); measures the rounding floor again where Newton
     * stalls. The floor of a step is measured at its start; at the
     * solution it can be larger (the positions have moved, and a stiff
     * segment's strain rounds to eps |x| / l). Newton then stalls on noise
     * above a floor that no longer holds and the step is cut for nothing
     * (P1 at N = 1000: 25 iterations and four cut steps). When an iterate
     * is at most 1e3 times its tolerance and has not halved its excess over
     * the last two iterations, the noise is measured at that iterate (three
     * residual assemblies, once per step) and the floor raised to it. A
     * genuinely unconverged iterate stays refused: its residual is above
     * the noise measured where it stands.
     */
    std::function<bool(const VectorType &, const VectorType &)>
    stall_aware_test(StepTolerance &step, ResidualParts &reached) const;

    /// What each DoF is, and names for messages.
    const DofRoles &
    roles() const
    {
      return dof_roles;
    }

  private:
    /// Norms of the applied generalized forces and of the reactions.
    struct LoadParts
    {
      ResidualParts applied;
      ResidualParts reactions;
    };

    /// The parts of load_scale() before they are combined.
    LoadParts
    load_parts(const VectorType &u,
               double            load_factor,
               const VectorType *extra_force,
               const VectorType *known_loaded = nullptr) const;

    /// load_parts() from the @p applied generalized forces and the
    /// unconstrained residual @p loaded at @p u, each a vector with every
    /// entry (EveryEntry).
    LoadParts
    parts_of(const VectorType &u,
             const VectorType &applied,
             const VectorType &loaded) const;

    /// Adds to @p force2 and @p moment2 the squared net reaction force of
    /// every support in the unconstrained residual @p loaded at @p u, and
    /// its squared moment about the support's first vertex.
    void
    add_support_reactions(const VectorType &u,
                          const VectorType &loaded,
                          double           &force2,
                          double           &moment2) const;

    /// Adds to @p applied_moment2 the squared spatial moment that the
    /// @p applied generalized force puts on every junction with rotation
    /// DoFs, and to @p reaction_moment2 that of the residual @p loaded at
    /// the clamped ones (their reactions).
    void
    add_junction_moments(const VectorType &u,
                         const VectorType &applied,
                         const VectorType &loaded,
                         double           &applied_moment2,
                         double           &reaction_moment2) const;

    /// The scales of @p loads: the larger applied or reaction part, each
    /// combined().
    ResidualParts
    scale_of(const LoadParts &loads) const;

    /// The force scale of @p force and @p moment, the larger of the force
    /// and the moment over L, and the moment scale that times L.
    ResidualParts
    combined(double force, double moment) const;

    /// The moment (N m) that rows @p g (w, x, y, z) of junction
    /// @p junction's quaternion stand for at @p u; the w row is completed
    /// from the gauge invariance g . q = 0.
    Vector3
    junction_moment(const VectorType      &u,
                    unsigned int           junction,
                    const Eigen::Vector4d &g) const;

    Eigen::Vector4d
    junction_quaternion(const VectorType &u, unsigned int junction) const;

    const SolvableModel &model;
    DofRoles             dof_roles;
    /// Fixed twist DoFs that a hinge or junction element sees.
    std::vector<global_dof_index> fixed_twists;
  };
} // namespace rodnet

#endif
