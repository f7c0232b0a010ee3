// Rigid bodies attached to a rod network: their checks against the network
// and their weight (doc/dynamics.md, "Rigid bodies").
#include <core/rigid_body.h>

#include <cmath>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    void
    require_not_negative(const RigidBody &body,
                         const double     value,
                         const char      *what)
    {
      if (!(value >= 0) || !std::isfinite(value))
        throw std::invalid_argument(body.where + ": the " + what + " is " +
                                    std::to_string(value) +
                                    "; it must be finite and not negative");
    }

    /// A body at vertex @p v: a point mass, and an isotropic inertia on the
    /// rotation of the junction there.
    void
    check_vertex_body(const RodNetwork  &network,
                      const RigidBody   &body,
                      const unsigned int v)
    {
      const std::string where = body.where + ": ";
      if (v >= network.n_vertices())
        throw std::invalid_argument(where + "vertex " + std::to_string(v) +
                                    " does not exist");
      if (body.offset != 0)
        throw std::invalid_argument(
          where +
          "an offset needs a rod end, whose tangent carries the "
          "centre; " +
          network.describe_vertex(v) + " is not a free rod end");
      if (body.axial_inertia != body.transverse_inertia)
        throw std::invalid_argument(
          where + "at " + network.describe_vertex(v) +
          " only an isotropic rotary inertia is represented (no axis to "
          "align J_t, J_p with); give one value");
      if (body.axial_inertia == 0)
        return;
      const auto junction = network.junction_at(v);
      if (!junction || !network.junctions()[*junction].has_rotation())
        throw std::invalid_argument(
          where + "a rotary inertia turns with a junction's rotation, and " +
          network.describe_vertex(v) +
          (junction ? " is in the pinned junction \"" +
                        network.junctions()[*junction].name +
                        "\", where each rod end turns on its own" :
                      " has none (a scene adds a rotation handle there)"));
    }
  } // namespace

  std::pair<unsigned int, double>
  end_segment(const RodNetwork &network, const RodEnd &end)
  {
    const Rod         &rod = network.rods().at(end.rod);
    const unsigned int e   = network.end_vertex(end);
    const unsigned int p =
      end.at_start ? rod.vertices[1] : rod.vertices[rod.vertices.size() - 2];
    return {p, (network.vertex(e) - network.vertex(p)).norm()};
  }

  void
  check_rigid_body(const RodNetwork &network, const RigidBody &body)
  {
    require_not_negative(body, body.mass, "mass (kg)");
    require_not_negative(body, body.axial_inertia, "rotary inertia (kg m^2)");
    require_not_negative(body,
                         body.transverse_inertia,
                         "rotary inertia (kg m^2)");
    require_not_negative(body, body.offset, "offset (m)");
    if (body.mass == 0 && body.axial_inertia == 0 &&
        body.transverse_inertia == 0)
      throw std::invalid_argument(body.where +
                                  ": it has neither mass nor rotary inertia");
    if (const auto *v = std::get_if<unsigned int>(&body.attachment))
      return check_vertex_body(network, body, *v);
    const RodEnd &end = std::get<RodEnd>(body.attachment);
    if (end.rod >= network.rods().size())
      throw std::invalid_argument(body.where + ": rod " +
                                  std::to_string(end.rod) + " does not exist");
    if (network.rods()[end.rod].closed)
      throw std::invalid_argument(body.where + ": rod " +
                                  std::to_string(end.rod) +
                                  " is closed and has no end");
  }

  std::vector<std::pair<unsigned int, Vector3>>
  rigid_body_weight(const RodNetwork &network,
                    const RigidBody  &body,
                    const Vector3    &gravity)
  {
    const Vector3 weight = body.mass * gravity;
    if (const auto *v = std::get_if<unsigned int>(&body.attachment))
      return {{*v, weight}};
    // The centre x_c = (1 + c/l) x_e - (c/l) x_p: the potential -m g.x_c
    // is that of these two forces.
    const RodEnd &end      = std::get<RodEnd>(body.attachment);
    const auto [before, l] = end_segment(network, end);
    const double ratio     = body.offset / l;
    if (ratio == 0)
      return {{network.end_vertex(end), weight}};
    return {{network.end_vertex(end), (1 + ratio) * weight},
            {before, -ratio * weight}};
  }
} // namespace rodnet
