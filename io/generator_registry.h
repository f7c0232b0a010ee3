#ifndef RODNET_IO_GENERATOR_REGISTRY_H
#define RODNET_IO_GENERATOR_REGISTRY_H

#include <deal.II/base/parameter_handler.h>

#include <base/registry.h>
#include <elements/quaternion.h>
#include <geometry/rod_graph.h>
#include <io/problem_size.h>
#include <io/read_notes.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /// What a generator makes: plain rods (their points, closed or open) or
  /// a network of beams and junctions.
  struct GeneratedGeometry
  {
    std::vector<std::vector<Vector3>> rod_points;
    /// One flag per rod of rod_points.
    std::vector<bool> rod_closed;
    /// Networks: the beams and junctions.
    std::optional<RodGraph> graph;
    /// What a reader of an input file said of it.
    ReadNotes notes;
  };

  /// The entries of subsection Geometry that every generator may use
  /// besides its own.
  struct GeneratorInput
  {
    /// "Segments": per rod, per polyline piece or per beam.
    unsigned int segments = 1;
    /// "Clamp at first segment midpoint" (only for open_rods() generators).
    bool midpoint_clamp = false;
    /// Relative file names are relative to it.
    std::string scene_directory = ".";
  };

  /// An entry of subsection Geometry that a generator does not read, and
  /// why (for the message that refuses a scene setting it).
  struct UnreadEntry
  {
    std::string entry;
    std::string reason;
  };

  /**
   * A way to make the rods of a scene ("Geometry/Generator = <name>"): it
   * declares the entries of subsection Geometry it reads (an entry that
   * several generators read, as "Radius", is declared by each alike) and
   * makes the geometry from them. Registered by name in GeneratorRegistry.
   */
  class GeometryGenerator
  {
  public:
    virtual ~GeometryGenerator() = default;

    /// Declares the generator's entries in subsection Geometry (current).
    virtual void
    declare_parameters(dealii::ParameterHandler &prm) const = 0;

    /**
     * The size of what the generator makes, from its entries alone, for
     * the generators that make many points or beams from a few numbers:
     * their size is checked before a point is generated. Empty (the
     * default) for the others, checked once they are read.
     */
    virtual std::optional<ProblemSize>
    planned_size(const dealii::ParameterHandler &prm,
                 const GeneratorInput           &input) const;

    /// The entry a message about the size of the model names.
    virtual std::string
    size_entry() const;

    /// True if the generator makes open rods that "Clamp at first segment
    /// midpoint" can begin half a segment behind their start.
    virtual bool
    open_rods() const;

    /**
     * The entries of subsection Geometry that every generator shares (as
     * "Director d1") but this one does not read; a scene that sets one is
     * refused (refuse_unread_geometry_entries()). None by default.
     */
    virtual std::vector<UnreadEntry>
    unread_shared_entries() const;

    /// Makes the geometry; throws std::invalid_argument naming the entry
    /// where one is inadmissible.
    virtual GeneratedGeometry
    generate(const dealii::ParameterHandler &prm,
             const GeneratorInput           &input) const = 0;
  };

  /**
   * The geometry generators by name (base/registry.h), in the order of
   * registration, which is the order of the "Generator" selection (the
   * first is its default). The registrations are one line each in
   * register_rod_generators() and register_network_generators().
   */
  class GeneratorRegistry : public Registry<GeometryGenerator>
  {
  public:
    /// An empty registry (instance() has every generator of rodnet).
    GeneratorRegistry()
        : Registry<GeometryGenerator>("generator",
                                      "generators",
                                      RegistryOrder::registration)
    {
    }

    /// The process-wide registry with every generator of rodnet.
    static const GeneratorRegistry &
    instance();
  };
} // namespace rodnet

#endif
