#ifndef RODNET_SOLVERS_CHECKS_DOF_ROLES_H
#define RODNET_SOLVERS_CHECKS_DOF_ROLES_H

#include <core/solvable_model.h>

#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * What every DoF of a RodModel is, for the solvers' checks: a position
   * component of a vertex (a force row), the twist of a segment or a
   * component of a junction's quaternion (moment rows), or inert: a DoF the
   * model fixes because it carries nothing (the copies of shared junction
   * positions, a twist that no hinge sees, the real part of a quaternion,
   * which is its gauge), or the Lagrange multiplier of an inextensible
   * segment (a constraint row, scaled to a force), or what a family
   * declared of a DoF of its own (DeclaredDof). Also names DoFs, vertices
   * and segments the way messages and scenes do.
   */
  class DofRoles
  {
  public:
    enum class Kind : unsigned char
    {
      position,
      twist,
      quaternion,
      multiplier,
      shape,
      inert
    };

    /// @p model must be finalized and outlive this object.
    explicit DofRoles(const SolvableModel &model);

    Kind
    kind(const global_dof_index dof) const
    {
      return kinds[dof];
    }

    /// The vertex (position DoFs, the DoFs that families declare), cell
    /// (twists) or junction (quaternion components) DoF @p dof belongs to.
    unsigned int
    owner(const global_dof_index dof) const
    {
      return owners[dof];
    }

    /// The component (0, 1, 2) of a position DoF or (1, 2, 3) of a
    /// quaternion DoF.
    unsigned int
    component(const global_dof_index dof) const
    {
      return components[dof];
    }

    global_dof_index
    n_dofs() const
    {
      return kinds.size();
    }

    /// Rod and index along it of triangulation vertex @p v.
    std::pair<unsigned int, unsigned int>
    vertex_place(const unsigned int v) const
    {
      return vertex_places[v];
    }

    /// Rod and segment index along it of cell @p cell.
    std::pair<unsigned int, unsigned int>
    cell_place(const unsigned int cell) const
    {
      return cell_places[cell];
    }

    /// Vertex @p v as scenes name it: "1:start", "0:end", "0:12".
    std::string
    vertex_name(unsigned int v) const;

    /// "rod 1 segment 3 (vertex 4)", "rod 0 segment 2 (its twist)",
    /// "rod 0 segment 2 (its length)", "junction \"tip\"": where DoF @p dof
    /// sits. A vertex is named by the shorter (stiffer) of its segments.
    std::string
    describe(global_dof_index dof) const;

  private:
    /// Kind, owner and label of the DoFs that families declared
    /// (DofLayout::declared_blocks()).
    void
    mark_declared_dofs(const DofLayout &layout);

    const SolvableModel                               &model;
    std::vector<Kind>                                  kinds;
    std::vector<unsigned int>                          owners;
    std::vector<unsigned char>                         components;
    std::vector<std::pair<unsigned int, unsigned int>> vertex_places;
    std::vector<std::pair<unsigned int, unsigned int>> cell_places;
    /// Per DoF, its declaration if a family declared it (its label), else
    /// null.
    std::vector<const DeclaredDof *> declared;
  };
} // namespace rodnet

#endif
