#ifndef RODNET_CORE_SUPPORTS_AND_LOADS_H
#define RODNET_CORE_SUPPORTS_AND_LOADS_H

#include <core/rod_network.h>
#include <core/time_function.h>

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rodnet
{
  /// How a load follows the load factor lambda.
  enum class LoadRamp
  {
    /// lambda times its value at load factor 1 (unless the model holds
    /// all its loads, RodModel::fix_loads()).
    ramped,
    /// Its full value at every load factor, whatever else lambda ramps:
    /// an imperfection present from the first step on.
    held
  };

  /**
   * The supports and dead loads of a structure, in terms of its network
   * alone (rods, rod ends, vertices, junctions), at load factor 1: what a
   * scene or a user's program states once and every model (Model::apply())
   * lowers to its own DoFs. A model refuses, with one message, what it
   * cannot represent (DrModel: prescribed rotations and moments).
   */
  struct SupportsAndLoads
  {
    /// Holds the position and rotation of a rod end or of a junction; a
    /// support called @p name.
    struct Clamp
    {
      std::string                        name;
      std::variant<RodEnd, unsigned int> target; ///< rod end or junction
    };

    /// Holds the masked position components of a vertex at a displacement
    /// (zero: a fixed vertex), scaled by the load factor or by its own
    /// function of time; a support called @p name.
    struct FixedComponents
    {
      std::string         name;
      unsigned int        vertex;
      std::array<bool, 3> mask;
      Vector3             displacement = Vector3::Zero();
      TimeFunction        in_time = {};
    };

    /**
     * A rotation (rad, about the unit @p axis) prescribed at @p vertex, or
     * a moment (N m) about it: a clamp's end vertex or a junction's (a
     * rotation handle where the vertex has no junction of its own).
     * @p where names the origin in messages ("entry \"Loads/Moments\":
     * \"tip\"").
     */
    struct AxisLoad
    {
      std::string                 where;
      unsigned int                vertex;
      std::optional<unsigned int> junction;
      Vector3                     axis;
      double                      value;
      /// Moments only: how the moment follows the load factor.
      LoadRamp ramp = LoadRamp::ramped;
      /// Rotations only: the load factor scales the angle, or a function
      /// of time.
      TimeFunction in_time = {};
    };

    struct PointForce
    {
      unsigned int vertex;
      Vector3      force;
      LoadRamp     ramp = LoadRamp::ramped;
    };

    /// A force per undeformed length on a whole rod (a weight: mass per
    /// length times the acceleration of gravity).
    struct DistributedForce
    {
      unsigned int rod;
      Vector3      force_per_length;
    };

    /// Applied first: the rotations and moments look the clamps up.
    std::vector<Clamp>            clamps;
    std::vector<AxisLoad>         rotations; ///< value: the angle (rad)
    std::vector<AxisLoad>         moments;   ///< value: the moment (N m)
    std::vector<FixedComponents>  fixed_components;
    std::vector<PointForce>       point_forces;
    std::vector<DistributedForce> distributed_forces;
  };
} // namespace rodnet

#endif
