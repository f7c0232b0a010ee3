#ifndef RODNET_SOLVERS_TIME_GYROSCOPIC_COUPLING_H
#define RODNET_SOLVERS_TIME_GYROSCOPIC_COUPLING_H

#include <core/solvable_model.h>

#include <array>
#include <vector>

namespace rodnet
{
  /**
   * The gyroscopic force of the sections' spin on the centreline, for the
   * midpoint rule (doc/theory.md, "Twist"; doc/dynamics.md, "Momenta under
   * the midpoint rule").
   *
   * The twist inertia rho (I1 + I2) l0 (plus a welded body's J_t), the
   * twist row J_k of the mass matrix, weighs the twist rate phidot in the
   * chart of the step's reference frames, whose tangent spin vanishes at the
   * reference but whose curl does not: the kinetic energy
   * J/2 (phidot - A(t).tdot)^2, A = (T x t) / (1 + T.t), has the
   * Euler-Lagrange force -p t x tdot / |e| on the chord e of a segment
   * (p = J omega.t its spin), which turns the spin p t with the tangent.
   * Without it the spin vector turns with no torque to balance it and the
   * angular momentum changes by sum_k p_k tdot_k.
   *
   * Over a step from u_n to y, with e_m = (e_n + e) / 2, dt = t - t_n and
   * pbar = J (phi - phi_n) / h, the force on the segment's end vertex is
   *   g = -pbar (e_m x dt) / (h |e_m|^2),
   * and -g on its start vertex: no resultant, no work (e_m x dt is normal
   * to t_n and t, hence to e - e_n), and the moment e_m x g = pbar dt / h
   * (exactly for a segment whose length does not change), which cancels the
   * turn of the spin in the balance of angular momentum.
   *
   * Serial, as the model is (it refuses more than one process; issue 37):
   * it reads the mass matrix and the vectors by global index.
   */
  class GyroscopicCoupling
  {
  public:
    /// @p model must be finalized and outlive this object, as must @p
    /// mass, its unconstrained mass matrix, whose twist diagonal is read at
    /// the first call.
    GyroscopicCoupling(const SolvableModel &model, const MatrixType &mass);

    /// Adds the force of the step from @p u_n to @p y of length @p h to
    /// @p r (fixed rows too: the caller zeroes them).
    void
    add_force(const VectorType &u_n,
              const VectorType &y,
              double            h,
              VectorType       &r);

    /// Adds its Jacobian with respect to @p y to @p k, leaving the rows and
    /// columns of fixed DoFs alone.
    void
    add_jacobian(const VectorType &u_n,
                 const VectorType &y,
                 double            h,
                 MatrixType       &k);

    /// The step of one segment: its chords at u_n and y, its twist step.
    struct SegmentStep
    {
      Vector3 e0, e1;
      double  twist;
    };

  private:
    /// A segment with twist inertia.
    struct Segment
    {
      /// Position DoFs of its start and end vertex, then its twist.
      std::array<global_dof_index, 7> dofs;
      std::array<unsigned int, 2>     vertices;
      double                          inertia;
    };

    /// The segments with twist inertia, once.
    void
    collect_segments();

    /// The compressed rows of a tangent that places refers to.
    struct CompressedRows
    {
      const Epetra_CrsMatrix *matrix    = nullptr;
      int                    *offsets   = nullptr;
      int                    *columns   = nullptr;
      int                     n_entries = 0;

      bool
      operator==(const CompressedRows &other) const
      {
        return matrix == other.matrix && offsets == other.offsets &&
               columns == other.columns && n_entries == other.n_entries;
      }
    };

    /// places for the rows of @p m, found again when they are not those of
    /// the last call (another matrix, or its pattern was built anew).
    void
    place_entries(const Epetra_CrsMatrix &m);

    /// The step of @p s from @p u_n to @p y.
    SegmentStep
    step_of(const Segment &s, const DofValues &u_n, const DofValues &y) const;

    const SolvableModel &model;
    const MatrixType    &mass;
    std::vector<Segment> segments;
    bool                 collected = false;
    /// Per segment, the place of each entry (row-major: 6 position rows,
    /// the 6 positions and the twist as columns) of its Jacobian block in
    /// the values of the tangent's compressed rows, or -1 where the row or
    /// the column is fixed: adding there costs no search of the row
    /// (Trilinos' add() took 0.015 s a tangent at 1.1e5 DoFs, this 0.005 s
    /// with the derivatives; doc/performance.md).
    std::vector<std::array<int, 42>> places;
    CompressedRows                   placed_rows;
  };
} // namespace rodnet

#endif
