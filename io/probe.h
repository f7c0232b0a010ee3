#ifndef RODNET_IO_PROBE_H
#define RODNET_IO_PROBE_H

#include <base/registry.h>
#include <core/model.h>
#include <core/motion.h>

#include <memory>
#include <string>

namespace rodnet
{
  /**
   * A model at a converged state as a probe reads it, whatever the model's
   * state vector: the model (its network, supports and capabilities), the
   * load factor, the lowest eigenvalue of the tangent where the solver
   * computed it, and the state's positions, energy, reactions and junction
   * rotations; in dynamic time stepping also its Motion (energies and
   * momenta). ProbedStateOf<State> is the one implementation.
   */
  class ProbedState
  {
  public:
    ProbedState(const ModelBase &model,
                const double     load_factor,
                const double     lowest_eigenvalue,
                const Motion    *motion = nullptr)
        : model(model)
        , load_factor(load_factor)
        , lowest_eigenvalue(lowest_eigenvalue)
        , motion(motion)
    {
    }

    virtual ~ProbedState() = default;

    virtual Vector3
    position(unsigned int vertex) const = 0;

    virtual double
    elastic_energy() const = 0;

    virtual Vector3
    reaction(const Support &support) const = 0;

    /// Reaction moment of the clamp @p support about its end vertex.
    virtual Vector3
    reaction_moment(const Support &support) const = 0;

    /// Moment that the rotation of junction @p junction transmits.
    virtual Vector3
    reaction_moment(unsigned int junction) const = 0;

    virtual Quaternion
    junction_rotation(unsigned int junction) const = 0;

    const ModelBase &model;
    const double     load_factor;
    /// NaN where the solver did not compute it.
    const double lowest_eigenvalue;
    /// Energies and momenta with the velocities of dynamic time stepping;
    /// null elsewhere (Scene::probes() refuses the probes that read it).
    const Motion *const motion;
  };

  /// ProbedState of a Model<State> at the state @p u.
  template <class State>
  class ProbedStateOf final : public ProbedState
  {
  public:
    ProbedStateOf(const Model<State> &model,
                  const State        &u,
                  const double        load_factor,
                  const double        lowest_eigenvalue,
                  const Motion       *motion = nullptr)
        : ProbedState(model, load_factor, lowest_eigenvalue, motion)
        , state_model(model)
        , u(u)
    {
    }

    Vector3
    position(const unsigned int vertex) const override
    {
      return state_model.position(u, vertex);
    }

    double
    elastic_energy() const override
    {
      return state_model.elastic_energy(u, load_factor);
    }

    Vector3
    reaction(const Support &support) const override
    {
      return state_model.reaction(support, u, load_factor);
    }

    Vector3
    reaction_moment(const Support &support) const override
    {
      return state_model.reaction_moment(support, u, load_factor);
    }

    Vector3
    reaction_moment(const unsigned int junction) const override
    {
      return state_model.reaction_moment(junction, u, load_factor);
    }

    Quaternion
    junction_rotation(const unsigned int junction) const override
    {
      return state_model.junction_rotation(u, junction);
    }

  private:
    const Model<State> &state_model;
    const State        &u;
  };

  /// The words of one probe "name: kind first second [extra]" of a scene
  /// entry, with where it stands for messages.
  struct ProbeWords
  {
    std::string name;
    std::string entry;   ///< the scene entry, for vertex selection
    std::string context; ///< 'entry "...", probe "..."' for messages
    std::string kind;
    std::string first;  ///< a vertex or junction
    std::string second; ///< a component or an axis
    std::string extra;  ///< must be empty
  };

  /**
   * One scalar recorded at every converged step (a column of probes.csv).
   * A probe kind is one class, made from its words by the factory it
   * registers with RODNET_REGISTER_PROBE_KIND in its own .cc file
   * (doc/architecture.md); the scene's "Output/Probes" accepts it at once.
   */
  class Probe
  {
  public:
    explicit Probe(std::string name)
        : probe_name(std::move(name))
    {
    }

    virtual ~Probe() = default;

    /// The column name.
    const std::string &
    name() const
    {
      return probe_name;
    }

    /// Unit of the values ("m", "N", ...), for plots.
    virtual std::string
    unit() const = 0;

    /// The value at @p state.
    virtual double
    value(const ProbedState &state) const = 0;

    /// @p value made continuous from @p previous, the value of the step
    /// before (0 before the first step); as it is by default (rotations are
    /// known modulo a turn and take the nearest value).
    virtual double
    continued(const double value, const double /*previous*/) const
    {
      return value;
    }

    /// Whether value() reads ProbedState::lowest_eigenvalue, which the
    /// solver then computes at every recorded state.
    virtual bool
    needs_lowest_eigenvalue() const
    {
      return false;
    }

    /// Whether value() reads ProbedState::motion, which only dynamic time
    /// stepping provides.
    virtual bool
    needs_motion() const
    {
      return false;
    }

  private:
    std::string probe_name;
  };

  /// The probe kinds, by the keyword a scene writes ("position", ...); the
  /// description is "<syntax> [<unit>]: <what it records>".
  Registry<Probe, const ProbeWords &, const ModelBase &> &
  probe_kind_registry();

  /// The component x, y or z of @p words.second as 0, 1, 2; throws
  /// std::invalid_argument naming the probe otherwise.
  unsigned int
  probe_component(const ProbeWords &words);

  /// Throws std::invalid_argument naming the probe unless @p words has
  /// exactly the arguments of @p syntax ("position <vertex> <x|y|z>"):
  /// @p n_arguments of them.
  void
  require_probe_arguments(const ProbeWords &words,
                          unsigned int      n_arguments,
                          const std::string &syntax);
} // namespace rodnet

/// Registers Probe class @p classname (unqualified, inside namespace
/// rodnet, constructible from (const ProbeWords &, const ModelBase &))
/// under the keyword @p keyword.
#define RODNET_REGISTER_PROBE_KIND(classname, keyword, description)       \
  namespace                                                               \
  {                                                                       \
    const bool rodnet_registered_##classname = [] {                       \
      rodnet::probe_kind_registry().add(                                  \
        keyword,                                                          \
        description,                                                      \
        [](const rodnet::ProbeWords &words,                               \
           const rodnet::ModelBase  &model) {                             \
          return std::unique_ptr<rodnet::Probe>(new classname(words, model)); \
        });                                                               \
      return true;                                                        \
    }();                                                                  \
  }

#endif
