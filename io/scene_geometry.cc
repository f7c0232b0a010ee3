#include <deal.II/base/patterns.h>

#include <elements/hinge_kernel.h>
#include <io/generator_registry.h>
#include <io/scene.h>
#include <io/scene_entries.h>

#include <algorithm>
#include <numeric>

namespace rodnet
{
  namespace
  {
    using dealii::Patterns::Bool;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    using scene_entries::join;
    using scene_entries::vector_pattern;

    /// The junctions of @p graph that build_rod_network() gives a
    /// rotation (four DoFs): the nodes of two or more beam ends or of a
    /// kind, but pinned.
    double
    rotating_junctions(const RodGraph &graph)
    {
      std::vector<unsigned int> ends(graph.nodes.size(), 0);
      for (const RodGraph::Beam &beam : graph.beams)
        {
          ++ends[beam.from];
          ++ends[beam.to];
        }
      double junctions = 0;
      for (std::size_t i = 0; i < graph.nodes.size(); ++i)
        {
          const auto &kind = graph.nodes[i].kind;
          junctions += (ends[i] > 1 || kind) && kind != JunctionKind::pinned;
        }
      return junctions;
    }

    /// Declares the entries of subsection Geometry that every generator
    /// shares: how the rods are discretized, oriented and made stress free.
    void
    declare_rod_entries(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Segments",
                        "100",
                        Integer(1),
                        "Number of segments of the rod (per piece for a "
                        "polyline, per beam for a generated network or "
                        "network file). [-]");
      prm.declare_entry(
        "Clamp at first segment midpoint",
        "false",
        Bool(),
        "Open rods (not networks, nor dynamic relaxation): centre the first "
        "segment on the rod's start along its tangent, so that the clamp of "
        "the start (Supports/Clamped ends, required) acts exactly there and "
        "the free length is the rod's length. [-]");
      prm.declare_entry(
        "Natural shape",
        to_string(NaturalShape::initial_geometry),
        Selection(to_string(NaturalShape::initial_geometry) + "|" +
                  to_string(NaturalShape::straight)),
        "Stress-free shape of every rod: \"initial geometry\" (the rods "
        "are stress free as built: a helix stays a helix at zero load) or "
        "\"straight\" (a curved rod starts prestressed, bent from a "
        "straight one). The material's Natural curvature and twist act on "
        "top of either. Junctions always keep their initial angles. [-]");
      prm.declare_entry("Director d1",
                        "0, 1, 0",
                        vector_pattern(),
                        "Orientation of the first material director: d1 of "
                        "each segment is this vector made orthogonal to the "
                        "segment. Bending stiffness EI1 acts about d1. Not "
                        "for networks, which orient their beams (see "
                        "doc/networks.md). [-]");
      prm.declare_entry("Frame half turns",
                        "0",
                        dealii::Patterns::Integer(0),
                        "Of closed rods (rings): half turns of the material "
                        "frame about the tangent once around, spread evenly; "
                        "odd numbers close a Moebius band. [-]");
      prm.declare_entry("Hinge kernel",
                        "simple",
                        Selection(join(hinge_kernel_names(), "|")),
                        "Bending and twisting measures: \"simple\" (Korner, "
                        "Audoly, Bhattacharya 2021) or \"classic\" "
                        "(Lestringant & Kochmann 2020, eqs. 10-12). [-]");
      prm.declare_entry(
        "Ghost spin",
        "exact",
        Selection("exact|small rotation"),
        "Junctions: spin angle of the ghost segments, exact for finite "
        "rotations (L&K appendix B) or its small-rotation form (eq. 8). [-]");
    }
  } // namespace

  void
  Scene::declare_geometry(dealii::ParameterHandler &prm)
  {
    const GeneratorRegistry &generators = GeneratorRegistry::instance();
    prm.enter_subsection("Geometry");
    prm.declare_entry(
      "Generator",
      generators.names().front(),
      Selection(join(generators.names(), "|")),
      "How the rods are made: a straight rod, a circular arc, a closed "
      "ring, a helix, a polyline through given points, the rods of a Gmsh "
      "line mesh (one rod per physical tag); or a network of beams tied at "
      "junctions: the right-angle frame and the windmill of Lestringant & "
      "Kochmann (Fig. 3), a square or hexagonal lattice, a node/beam list "
      "file, a branched Gmsh line mesh, or blocks of a block map (Fig. 6; "
      "see doc/networks.md).");
    declare_rod_entries(prm);
    // An entry that several generators read is declared by each alike;
    // deal.II keeps the first declaration's place.
    for (const std::string &name : generators.names())
      generators.create(name)->declare_parameters(prm);
    prm.leave_subsection();
  }

  void
  Scene::parse_geometry(dealii::ParameterHandler &prm,
                        const std::string        &scene_directory,
                        const SizeCheck          &check_size)
  {
    prm.enter_subsection("Geometry");
    const std::string name      = prm.get("Generator");
    const auto        generator = GeneratorRegistry::instance().create(name);
    GeneratorInput    input;
    input.segments        = prm.get_integer("Segments");
    input.midpoint_clamp  = prm.get_bool("Clamp at first segment midpoint");
    input.scene_directory = scene_directory;
    director_hint         = scene_entries::get_direction(prm, "Director d1");
    hinge_kernel          = prm.get("Hinge kernel");
    frame_half_turns      = prm.get_integer("Frame half turns");
    natural_shape         = natural_shape_from_string(prm.get("Natural shape"));
    midpoint_clamp        = input.midpoint_clamp;
    if (midpoint_clamp && !generator->open_rods())
      throw std::invalid_argument(
        "entry \"Geometry/Clamp at first segment midpoint\": the " + name +
        " generator has no open rod start for it (rings are closed; a "
        "network clamps exactly at a clamped node); set it to false");
    // What cannot fit in memory is refused before it is generated.
    const std::string size_entry = generator->size_entry();
    if (const auto planned = generator->planned_size(prm, input))
      check_size(*planned, size_entry);
    GeneratedGeometry geometry = generator->generate(prm, input);
    rod_points                 = std::move(geometry.rod_points);
    rod_closed                 = std::move(geometry.rod_closed);
    if (frame_half_turns > 0 &&
        std::find(rod_closed.begin(), rod_closed.end(), true) ==
          rod_closed.end())
      throw std::invalid_argument(
        "entry \"Geometry/Frame half turns\": the " + name +
        " generator makes no closed rod to turn the frame around; use the "
        "ring generator or set it to 0");
    graph             = std::move(geometry.graph);
    segments_per_beam = graph ? input.segments : 1;
    ghost_spin        = prm.get("Ghost spin") == "exact" ? GhostSpin::exact :
                                                           GhostSpin::small_rotation;

    geometry_notes   = std::move(geometry.notes);
    model_size_entry = size_entry;
    model_size       = check_size(geometry_size(), size_entry);
    prm.leave_subsection();
  }

  std::vector<double>
  Scene::rod_segments() const
  {
    // A mesh's chain (a beam with interior vertices) keeps its segments;
    // build_rod_network() splits a straight beam into segments_per_beam.
    std::vector<double> segments;
    if (graph)
      for (const RodGraph::Beam &beam : graph->beams)
        segments.push_back(!beam.interior.empty() ? beam.interior.size() + 1.0 :
                           beam.segments > 0      ? beam.segments :
                                                    segments_per_beam);
    else
      for (std::size_t r = 0; r < rod_points.size(); ++r)
        segments.push_back(rod_closed[r] ? rod_points[r].size() :
                                           rod_points[r].size() - 1.0);
    return segments;
  }

  ProblemSize
  Scene::geometry_size() const
  {
    const std::vector<double> segments = rod_segments();
    ProblemSize               size =
      rods_size(segments.size(),
                std::accumulate(segments.begin(), segments.end(), 0.0),
                std::count(rod_closed.begin(), rod_closed.end(), true));
    if (graph)
      size.junctions = rotating_junctions(*graph);
    return size;
  }

  double
  Scene::constraint_dofs() const
  {
    // As DofLayout numbers them: a multiplier per segment of an
    // inextensible rod (a developable ribbon is one), and three DoFs per
    // hinge of a ribbon (every vertex of a closed rod, the inner ones of an
    // open one).
    const std::vector<double>        segments = rod_segments();
    const std::vector<unsigned int> &groups   = rod_material;
    double                           dofs     = 0;
    for (std::size_t r = 0; r < segments.size(); ++r)
      {
        const SceneMaterial &group = scene_materials[groups[r]];
        const bool ribbon = group.material->developable_ribbon() != nullptr;
        const bool closed = !graph && rod_closed[r];
        if (ribbon || group.inextensible)
          dofs += segments[r];
        if (ribbon)
          dofs += 3 * (closed ? segments[r] : segments[r] - 1);
      }
    return dofs;
  }
} // namespace rodnet
