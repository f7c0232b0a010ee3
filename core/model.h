#ifndef RODNET_CORE_MODEL_H
#define RODNET_CORE_MODEL_H

#include <core/output_fields.h>
#include <core/rod_network.h>
#include <core/supports_and_loads.h>
#include <elements/quaternion.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace rodnet
{
  /// A named set of fixed DoFs whose reaction force can be probed.
  struct Support
  {
    std::string               name;
    std::vector<unsigned int> vertices;
    /// Fixed position components per vertex (same order as vertices).
    std::vector<std::array<bool, 3>> fixed;
    /// Whether the support holds the rotation at its vertex too (a clamp
    /// of a rod end or of a junction).
    bool clamped = false;
    /// A clamp of a rod end (Model::clamp_end()): the cell of the end
    /// segment; its end vertex is vertices[0].
    std::optional<unsigned int> clamped_segment;
  };

  /// Diagonal of the bounding box of the vertices of @p network (m): the
  /// length scale of every model of it.
  double
  length_scale(const RodNetwork &network);

  /**
   * What every model of a rod network offers before and apart from a state:
   * the specification of supports and loads (lowered to the model's DoFs),
   * the network, the named supports, the length scale and what the model
   * can be asked. Probes are parsed against it (io/probe.h); Model<State>
   * adds the evaluation at a state.
   *
   * Supports and loads are added before finalize(); one added after it
   * would never be applied and is refused with std::logic_error.
   */
  class ModelBase
  {
  public:
    virtual ~ModelBase() = default;

    /// @name Supports and dead loads at load factor 1 (before finalize())
    /// @{
    /// Holds the first (or last) end of rod @p rod; a support @p name.
    virtual void
    clamp_end(const std::string &name, unsigned int rod, bool at_start) = 0;

    /// Holds junction @p junction's position and rotation.
    virtual void
    clamp_junction(const std::string &name, unsigned int junction) = 0;

    /// Fixes the masked position components of @p vertex; their value
    /// moves with the load factor to @p displacement (at load factor 1).
    virtual void
    fix_components(const std::string         &name,
                   unsigned int               vertex,
                   const std::array<bool, 3> &mask,
                   const Vector3             &displacement) = 0;

    /// As fix_components(), the displacement scaled by the function of time
    /// @p in_time instead of the load factor (time stepping). Refused with
    /// std::invalid_argument naming the support by a model without time.
    virtual void
    move_components(const std::string         &name,
                    unsigned int               vertex,
                    const std::array<bool, 3> &mask,
                    const Vector3             &displacement,
                    const TimeFunction        &in_time)
    {
      (void)vertex;
      (void)mask;
      (void)displacement;
      throw std::invalid_argument(
        "support \"" + name + "\" moves in time (" + in_time.expression +
        "), which only time stepping of a rod model can follow");
    }

    /// Prescribed rotations and moments (after the clamps, which they may
    /// turn or refuse).
    virtual void
    add_rotational_loads(
      const std::vector<SupportsAndLoads::AxisLoad> &rotations,
      const std::vector<SupportsAndLoads::AxisLoad> &moments) = 0;

    virtual void
    add_point_force(unsigned int vertex, const Vector3 &force) = 0;

    /// A dead force at its full value at every load factor
    /// (LoadRamp::held).
    virtual void
    add_held_point_force(unsigned int vertex, const Vector3 &force) = 0;

    /// Force per unit undeformed length on rod @p rod (lumped_forces()).
    virtual void
    add_distributed_force(unsigned int   rod,
                          const Vector3 &force_per_length) = 0;

    /// Lowers @p spec: clamps, rotational loads, fixed components, forces,
    /// in this order.
    void
    apply(const SupportsAndLoads &spec)
    {
      for (const auto &clamp : spec.clamps)
        if (const auto *end = std::get_if<RodEnd>(&clamp.target))
          clamp_end(clamp.name, end->rod, end->at_start);
        else
          clamp_junction(clamp.name, std::get<unsigned int>(clamp.target));
      add_rotational_loads(spec.rotations, spec.moments);
      for (const auto &f : spec.fixed_components)
        if (f.in_time.given())
          move_components(f.name, f.vertex, f.mask, f.displacement, f.in_time);
        else
          fix_components(f.name, f.vertex, f.mask, f.displacement);
      for (const auto &f : spec.point_forces)
        if (f.ramp == LoadRamp::held)
          add_held_point_force(f.vertex, f.force);
        else
          add_point_force(f.vertex, f.force);
      for (const auto &f : spec.distributed_forces)
        add_distributed_force(f.rod, f.force_per_length);
    }

    /// Builds the DoFs' constraints and the load vector. Call once.
    virtual void
    finalize() = 0;
    /// @}

    virtual const RodNetwork &
    network() const = 0;

    virtual const std::vector<Support> &
    supports() const = 0;

    /// The support called @p name; throws std::invalid_argument if none is.
    const Support &
    support(const std::string &name) const
    {
      for (const Support &s : supports())
        if (s.name == name)
          return s;
      throw std::invalid_argument("no support named \"" + name + "\"");
    }

    /// The clamp of a rod end (clamp_end()) whose end vertex is
    /// @p vertex, or null.
    const Support *
    clamp_at(const unsigned int vertex) const
    {
      for (const Support &s : supports())
        if (s.clamped_segment && s.vertices[0] == vertex)
          return &s;
      return nullptr;
    }

    /// Diagonal of the bounding box of the undeformed network (m), once
    /// finalized.
    double
    length_scale() const
    {
      return length;
    }

    /// @name Capabilities (what probes may ask of the model)
    /// @{
    /// Whether the model has junction rotations at all (quaternions).
    virtual bool
    has_junction_rotations() const = 0;

    /// Whether junction @p junction has a rotation of its own, which
    /// junction_rotation() and reaction_moment() report.
    virtual bool
    has_rotation(unsigned int junction) const = 0;

    /// Whether the model has a tangent whose eigenvalues a solver tracks.
    virtual bool
    has_tangent() const = 0;
    /// @}

  protected:
    /// The support called @p name of the masked components of @p vertex;
    /// throws std::invalid_argument naming both if the network has no such
    /// vertex.
    Support
    vertex_support(const std::string         &name,
                   const unsigned int         vertex,
                   const std::array<bool, 3> &mask) const
    {
      if (vertex >= network().n_vertices())
        throw std::invalid_argument("support \"" + name + "\": vertex " +
                                    std::to_string(vertex) + " does not exist");
      Support s;
      s.name     = name;
      s.vertices = {vertex};
      s.fixed    = {mask};
      return s;
    }

    /// Throws std::logic_error if finalize() has run: @p what (the call,
    /// naming the support or load) would never be applied.
    void
    require_not_finalized(const std::string &what) const
    {
      if (finalized)
        throw std::logic_error(what +
                               " after finalize(), where it would never be "
                               "applied; add every support and load before "
                               "finalize()");
    }

    /// Throws std::logic_error unless finalize() has run: @p what (the
    /// call) needs the DoF numbering and pattern that finalize() makes.
    void
    require_finalized(const std::string &what) const
    {
      if (!finalized)
        throw std::logic_error(what +
                               " before finalize(), where the model has no "
                               "DoF numbering or sparsity pattern yet; call "
                               "finalize() first");
    }

    double length    = 0;
    bool   finalized = false;
  };


  /**
   * A model at a state of type @p StateVector: the positions, the
   * reactions of named supports, the energy and the fields for output. The
   * probes, the VTU writer, the scene runner and a user's program work
   * against this interface; RodModel (discrete rods, Newton) and DrModel
   * (bending-active beams, dynamic relaxation) implement it.
   */
  template <class StateVector>
  class Model : public ModelBase
  {
  public:
    using State = StateVector;

    /// @name Evaluation at a state
    /// @{
    /// A zero state.
    virtual State
    create_vector() const = 0;

    /// Sets the fixed DoFs of @p u to their values at @p load_factor.
    virtual void
    apply_boundary_values(State &u, double load_factor) const = 0;

    /// Current position of vertex @p vertex.
    virtual Vector3
    position(const State &u, unsigned int vertex) const = 0;

    /// Elastic energy (no load potential) at @p u, with the natural shape
    /// a ramped one has at @p load_factor (Loads/Ramped natural shape).
    virtual double
    elastic_energy(const State &u, double load_factor) const = 0;

    /// Reaction force of support @p s at the converged @p u.
    virtual Vector3
    reaction(const Support &s, const State &u, double load_factor) const = 0;

    /// Reaction moment of the clamp @p s about its end vertex.
    virtual Vector3
    reaction_moment(const Support &s,
                    const State   &u,
                    double         load_factor) const = 0;

    /// Moment that the rotation of junction @p junction transmits.
    virtual Vector3
    reaction_moment(unsigned int junction,
                    const State &u,
                    double       load_factor) const = 0;

    /// Rotation of junction @p junction from the undeformed state.
    virtual Quaternion
    junction_rotation(const State &u, unsigned int junction) const = 0;

    /// The displacement and fields of @p u for output.
    virtual OutputFields
    output_fields(const State &u) const = 0;
    /// @}
  };
} // namespace rodnet

#endif
