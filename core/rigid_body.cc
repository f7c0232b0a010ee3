// Rigid bodies attached to a rod network: their checks against the network
// and their weight (doc/dynamics.md, "Rigid bodies").
#include <core/rigid_body.h>

#include <Eigen/Eigenvalues>
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

    /// A general inertia tensor: finite, symmetric, positive definite (a
    /// body's kinetic energy is positive for every omega), and the body's
    /// only rotary inertia.
    void
    check_inertia_tensor(const RigidBody &body)
    {
      const Matrix3 &J     = body.inertia_tensor;
      const auto     where = body.where + ": the inertia tensor ";
      if (!J.allFinite() || (J - J.transpose()).norm() > 1e-12 * J.norm())
        throw std::invalid_argument(where + "must be finite and symmetric");
      if (body.axial_inertia != 0 || body.transverse_inertia != 0 ||
          body.offset != 0)
        throw std::invalid_argument(
          where + "comes with another inertia or a rod end's offset; give "
                  "the tensor alone (a centre off a junction: centre "
                  "<dx>,<dy>,<dz>)");
      const double smallest =
        Eigen::SelfAdjointEigenSolver<Matrix3>(J).eigenvalues().minCoeff();
      if (!(smallest > 0))
        throw std::invalid_argument(where + "has the principal moment " +
                                    std::to_string(smallest) +
                                    " kg m^2; it must be positive definite");
    }

    /// A body at vertex @p v: a point mass, and an isotropic inertia or an
    /// inertia tensor on the rotation of the junction there.
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
      if (body.axial_inertia == 0 && !body.turns_with_junction())
        return;
      const auto junction = network.junction_at(v);
      if (!junction || !network.junctions()[*junction].has_rotation())
        throw std::invalid_argument(
          where +
          (body.has_centre_offset() ? "a centre off the vertex" :
                                      "a rotary inertia") +
          " turns with a junction's rotation, and " +
          network.describe_vertex(v) +
          (junction ? " is in the pinned junction \"" +
                        network.junctions()[*junction].name +
                        "\", where each rod end turns on its own" :
                      " has none (a scene adds a rotation handle there)"));
    }
  } // namespace

  EndKinematics
  end_kinematics(const RodNetwork &network,
                 const RodEnd     &end,
                 const double      offset)
  {
    const Rod         &rod = network.rods().at(end.rod);
    const unsigned int n   = rod.segments.size();
    EndKinematics      e;
    e.vertices = {end.at_start ? rod.vertices[0] : rod.vertices[n],
                  end.at_start ? rod.vertices[1] : rod.vertices[n - 1]};
    e.segments = {end.at_start ? rod.segments.front() : rod.segments.back()};
    // t = (x_e - x_p) / l, x_c = x_e + c t, the spin the end segment's.
    const double l =
      (network.vertex(e.vertices[0]) - network.vertex(e.vertices[1])).norm();
    e.tangent = {1 / l, -1 / l};
    e.centre  = {1 + offset / l, -offset / l};
    e.spin    = {1};
    return e;
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
    if (!body.centre_offset.allFinite())
      throw std::invalid_argument(body.where +
                                  ": the centre offset is not finite");
    if (body.has_inertia_tensor())
      check_inertia_tensor(body);
    if (body.mass == 0 && body.axial_inertia == 0 &&
        body.transverse_inertia == 0 && !body.has_inertia_tensor())
      throw std::invalid_argument(body.where +
                                  ": it has neither mass nor rotary inertia");
    if (const auto *v = std::get_if<unsigned int>(&body.attachment))
      return check_vertex_body(network, body, *v);
    if (body.turns_with_junction())
      throw std::invalid_argument(
        body.where + ": " +
        (body.has_inertia_tensor() ? "an inertia tensor" :
                                     "a centre off the vertex") +
        " turns with a junction's rotation, and a rod end welded to a body "
        "has none");
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
    // -m g . x_c with x_c = sum_i centre_i x_i: a force per vertex.
    const EndKinematics e =
      end_kinematics(network, std::get<RodEnd>(body.attachment), body.offset);
    std::vector<std::pair<unsigned int, Vector3>> forces;
    for (unsigned int i = 0; i < e.vertices.size(); ++i)
      if (e.centre[i] != 0)
        forces.emplace_back(e.vertices[i], e.centre[i] * weight);
    return forces;
  }
} // namespace rodnet
