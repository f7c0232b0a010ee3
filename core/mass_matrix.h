#ifndef RODNET_CORE_MASS_MATRIX_H
#define RODNET_CORE_MASS_MATRIX_H

#include <core/solvable_model.h>
#include <materials/cross_section.h>

#include <vector>

namespace rodnet
{
  /// Inertia of one rod per unit undeformed length.
  struct RodInertia
  {
    /// rho A (kg/m): translational inertia of the centreline.
    double mass_per_length;
    /// rho (I1 + I2) (kg m): polar moment of inertia of the cross-section
    /// about the centreline, the inertia of the twist.
    double rotational_inertia_per_length;
    /// rho I_b (kg m), I_b = (I1 + I2) / 2: rotary inertia of the
    /// cross-section about its bending axes (Rayleigh beam); 0 leaves it out
    /// (Euler-Bernoulli rod).
    double rotary_inertia_per_length = 0;
  };

  /**
   * The inertia of a rod of density @p density (kg/m^3) and cross-section
   * @p section: rho A, rho (I1 + I2) and the rotary rho (I1 + I2) / 2.
   * Note that I1 + I2 is the polar second moment, not the torsion constant
   * J of the section (they agree for a circle only). Throws
   * std::invalid_argument for a density that is not positive and finite.
   */
  RodInertia
  rod_inertia(const CrossSection &section, double density);

  /// How the translational inertia of a segment is distributed.
  enum class MassKind
  {
    /// Linear shape functions along the segment:
    /// rho A l0 / 6 [[2, 1], [1, 2]] per position component.
    consistent,
    /// Half the segment's mass at each end vertex: rho A l0 / 2 each (the
    /// row sums of the consistent matrix).
    lumped
  };

  /**
   * Assembles the mass matrix M of @p model, so that the kinetic energy
   * is 1/2 v^T M v for the DoF velocity v (doc/theory.md, "Mass and
   * rotational inertia"); @p inertia holds one RodInertia per rod. The
   * model must be finalized; @p mass is (re)initialized with the model's
   * sparsity pattern, so that it can be added to a tangent of the model.
   *
   * Per segment of undeformed length l0, the positions of its two vertices
   * carry rho A l0 as chosen by @p kind plus the rotary inertia of its
   * sections, rho I_b / l0 [[1, -1], [-1, 1]] per position component for
   * either kind (so a lumped M is diagonal only where rho I_b = 0), and its
   * twist DoF carries rho (I1 + I2) l0: deal.II's FEValues integrate it cell by
   * cell on the model's DoFHandler (each cell's material_id names its rod), and
   * the junction constraints condense the rod ends at a junction onto its
   * vertex, which collects the mass of every adjacent segment once. The
   * constrained position DoFs of those ends and the quaternion DoFs of
   * junctions carry no inertia (Lestringant & Kochmann section 2.5: none on
   * the ghost segments), so their rows are zero, but for the model's rigid
   * bodies (SolvableModel::rigid_bodies(), add_rigid_body_mass()): point
   * masses, a junction's isotropic rotary inertia, bodies welded to rod ends.
   *
   * With @p apply_constraints, the rows and columns of the DoFs that the
   * model's constraints() fix are zero as well, their diagonal included:
   * K + c M with the tangent K of SolvableModel::assemble (constrained) then
   * keeps K's diagonal on fixed rows and a zero Newton increment there.
   * Without, M is the mass of the free structure.
   *
   * Throws std::invalid_argument naming the rod for a mass, rotational or
   * rotary inertia per length that is negative or not finite, and where the
   * number of inertias is not the number of rods; std::logic_error before
   * SolvableModel::finalize().
   */
  void
  assemble_mass_matrix(const SolvableModel           &model,
                       const std::vector<RodInertia> &inertia,
                       MassKind                       kind,
                       MatrixType                    &mass,
                       bool apply_constraints = false);

  /**
   * Whether this process adds the block whose first DoF is @p anchor into
   * @p matrix: where it owns that DoF's row. On several processes each
   * segment's or body's block is added by one process, and the matrix sends
   * the rows of other processes' DoFs to their owners when compressed.
   */
  bool
  adds_here(const MatrixType &matrix, global_dof_index anchor);

  /**
   * Kinetic energy 1/2 v^T M v of the DoF velocity @p velocity for the
   * mass matrix @p mass. Throws std::invalid_argument if their sizes
   * differ.
   */
  double
  kinetic_energy(const MatrixType &mass, const VectorType &velocity);

  /**
   * The entries of @p from that are not zero, and its diagonal, into @p to
   * in a sparsity pattern of their own. A mass matrix on the model's
   * pattern is mostly zeros (a consistent M couples the same component of
   * neighbouring vertices only): a product with @p to costs what its
   * entries do. Each row keeps its order and loses only zero terms, so a
   * product with a finite vector is that of @p from to the bit (but the
   * sign of a zero). @p to cannot be added to a tangent of the model.
   */
  void
  copy_nonzeros(const MatrixType &from, MatrixType &to);
} // namespace rodnet

#endif
