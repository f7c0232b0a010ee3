#ifndef RODNET_IO_RIGID_BODY_ENTRIES_H
#define RODNET_IO_RIGID_BODY_ENTRIES_H

#include <core/rigid_body.h>

#include <optional>
#include <string>

namespace rodnet
{
  /**
   * One item of the scene entry "Loads/Rigid bodies" as written,
   * "<place>: mass <m> [inertia <j> | <J_t>,<J_p> |
   * <J_xx>,<J_yy>,<J_zz>[,<J_yz>,<J_zx>,<J_xy>]] [offset <c> |
   * centre <dx>,<dy>,<dz>]" (doc/dynamics.md, "Rigid bodies"), before it is
   * placed on a network.
   */
  struct RigidBodyItem
  {
    /// The vertex as the supports take it: [rod:]start|end|mid|<index>,
    /// @<name>.
    std::string place;
    /// The scene entry, "Loads/Rigid bodies".
    std::string entry;
    /// "entry \"<entry>\": \"<place>\"", what messages call it.
    std::string where;
    double      mass = 0;
    /// J_t and J_p (kg m^2); both j for "inertia <j>", 0 without.
    double axial_inertia = 0, transverse_inertia = 0;
    /// Whether two inertias were given (an axisymmetric body).
    bool axisymmetric = false;
    /// The tensor of three or six inertias, in global axes at the
    /// undeformed configuration; zero otherwise.
    Matrix3 inertia_tensor = Matrix3::Zero();
    /// c (m), 0 without.
    double offset = 0;
    /// r_0 (m), the centre's offset from the vertex in global axes; zero
    /// without.
    Vector3 centre_offset = Vector3::Zero();
  };

  /**
   * Reads the item @p place: @p text of entry @p entry. Throws
   * std::invalid_argument naming the entry and the item for a word that is
   * not mass, inertia, offset or centre, one given twice, a missing mass,
   * a value that is not a positive finite number (an off-diagonal
   * component of an inertia tensor: not a finite number), and a centre
   * that is not three finite numbers, not all zero.
   */
  RigidBodyItem
  parse_rigid_body_item(const std::string &place,
                        const std::string &text,
                        const std::string &entry);

  /**
   * The vertex of @p item in @p network where the body's rotary inertia
   * or centre off the vertex needs a rotation handle: a vertex in no
   * junction, inside a rod, or a free rod end where the inertia is
   * isotropic or a tensor and there is no offset;
   * none for a body without either or at a junction. Throws as
   * select_vertex().
   */
  std::optional<unsigned int>
  rigid_body_handle_vertex(const RodNetwork    &network,
                           const RigidBodyItem &item);

  /**
   * The body of @p item on @p network: at a junction (a network junction or
   * a rotation handle, rigid_body_handle_vertex()), on its vertex and
   * rotation; at a free rod end without one, welded to the end segment;
   * elsewhere at the vertex. Throws
   * std::invalid_argument naming the item for an offset or two inertias
   * where there is no free rod end (no tangent to align them with), and
   * as select_vertex().
   */
  RigidBody
  place_rigid_body(const RodNetwork &network, const RigidBodyItem &item);
} // namespace rodnet

#endif
