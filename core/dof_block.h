#ifndef RODNET_CORE_DOF_BLOCK_H
#define RODNET_CORE_DOF_BLOCK_H

#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace rodnet
{
  using dealii::types::global_dof_index;

  /// What a DoF of a family's own block is, for the solvers' checks.
  enum class DofRole : unsigned char
  {
    /// A shape DoF (a force-like row; weighted like a position).
    shape,
    /// A Lagrange multiplier: its row is a constraint scaled to a force, it
    /// is a row of the KKT tangent (RodModel::multiplier_dofs()).
    multiplier,
    /**
     * A component of the unit quaternion of the junction at the DoF's
     * vertex (Lestringant & Kochmann section 2.2). A block declares the four
     * components (w, x, y, z) of a junction as consecutive DoFs, stored as
     * q - (1, 0, 0, 0) so that zero is the reference; their rows are
     * moments. DofLayout::rotation_dof() finds them by junction.
     */
    rotation
  };

  /// How a declared DoF shows in the output: its value times @p factor is
  /// added to component @p component of the vertex field @p field.
  struct DeclaredDofOutput
  {
    /// Name of the vertex field; empty: not written.
    std::string field;
    /// Components of the field: 1 (scalar) or 3 (vector).
    unsigned int components = 1;
    unsigned int component  = 0;
    double       factor     = 1;
    /// Unit of the field, as a picture's colour bar states it ("N").
    std::string unit;
  };

  /**
   * One DoF of a block that an element family declares for itself
   * (ElementFamily::own_dofs()): its role, the vertex it belongs to, how
   * messages name it, how it is written to output.
   */
  struct DeclaredDof
  {
    DofRole role = DofRole::multiplier;
    /// The triangulation vertex the DoF is attached to.
    unsigned int vertex = 0;
    /// How messages name it: "bond 0 (0:end = 1:start), its x force".
    std::string       label;
    DeclaredDofOutput output;
    /**
     * What finalize() does with a multiplier whose stencils see held DoFs
     * only (a row of zeros in the tangent): hold it at zero (true: the
     * supports keep its constraint already, as they keep the length of a
     * segment between two clamped vertices) or refuse the model, naming
     * the label (false: the user asked for a constraint that cannot act).
     */
    bool held_where_supports_hold = false;
  };

  /// The DoFs a family declared, numbered from @p first on.
  struct DofBlock
  {
    /// The family's name (ElementFamily::name()).
    std::string              owner;
    global_dof_index         first = 0;
    std::vector<DeclaredDof> dofs;
  };
} // namespace rodnet

#endif
