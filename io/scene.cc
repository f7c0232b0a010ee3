#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <core/network_generators.h>
#include <core/rod_generators.h>
#include <core/rod_graph.h>
#include <elements/hinge_kernel.h>
#include <io/entry_numbers.h>
#include <io/entry_tree.h>
#include <io/gmsh_network.h>
#include <io/gmsh_rods.h>
#include <io/network_file.h>
#include <io/run_limits.h>
#include <io/scene.h>
#include <io/vertex_selector.h>
#include <materials/rod_material.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace rodnet
{
  namespace
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;

    /// Material subsections: "Material" for every rod, and optional ones
    /// for the material groups of a network.
    constexpr unsigned int n_material_groups = 4;

    std::string
    material_section(const unsigned int group)
    {
      return group == 0 ? "Material" :
                          "Material of group " + std::to_string(group);
    }

    /// Parses "ax,ay,az <value>" into a unit axis and a number.
    std::pair<Vector3, double>
    parse_axis_value(const std::string &text, const std::string &entry)
    {
      std::istringstream words(text);
      std::string        axis_text, value_text, extra;
      words >> axis_text >> value_text >> extra;
      try
        {
          const auto xyz = dealii::Utilities::split_string_list(axis_text, ',');
          if (xyz.size() != 3 || value_text.empty() || !extra.empty())
            throw std::invalid_argument("");
          const auto    v = dealii::Utilities::string_to_double(xyz);
          const Vector3 axis(v[0], v[1], v[2]);
          std::size_t   used  = 0;
          const double  value = std::stod(value_text, &used);
          if (used != value_text.size() || !std::isfinite(value) ||
              !(axis.norm() > 0))
            throw std::invalid_argument("");
          return {axis.normalized(), value};
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(
            "entry \"" + entry + "\": \"" + text +
            "\" should read \"<ax>,<ay>,<az> <value>\" (no spaces inside the "
            "axis, non-zero axis)");
        }
    }

    /// A pattern for "x, y, z".
    const dealii::Patterns::List vector_pattern(Double(), 3, 3, ",");

    Vector3
    get_vector(const dealii::ParameterHandler &prm, const std::string &entry)
    {
      const std::vector<double> v = dealii::Utilities::string_to_double(
        dealii::Utilities::split_string_list(prm.get(entry), ','));
      return Vector3(v[0], v[1], v[2]);
    }

    /// "<value>" of a double for messages.
    std::string
    number(const double value)
    {
      std::ostringstream s;
      s << value;
      return s.str();
    }

    /// The vector entry @p name of subsection Geometry, which gives a
    /// direction: refused if zero.
    Vector3
    get_direction(const dealii::ParameterHandler &prm, const std::string &name)
    {
      const Vector3 v = get_vector(prm, name);
      if (!(v.norm() > 0))
        throw std::invalid_argument(
          "entry \"Geometry/" + name + "\": \"" + prm.get(name) +
          "\" has no direction; give a non-zero vector, e.g. 0, 0, 1");
      return v;
    }

    /// "Plane axis 1" and "Plane axis 2" as unit vectors; refused unless
    /// they are orthogonal (to 1e-6 in the cosine of their angle).
    std::pair<Vector3, Vector3>
    get_plane_axes(const dealii::ParameterHandler &prm)
    {
      const Vector3 e1     = get_direction(prm, "Plane axis 1").normalized();
      const Vector3 e2     = get_direction(prm, "Plane axis 2").normalized();
      const double  cosine = e1.dot(e2);
      if (std::abs(cosine) > 1e-6)
        throw std::invalid_argument(
          "entry \"Geometry/Plane axis 2\": \"" + prm.get("Plane axis 2") +
          "\" makes " +
          number(std::acos(std::clamp(cosine, -1., 1.)) * 180 / M_PI) +
          " deg with \"Plane axis 1\" = \"" + prm.get("Plane axis 1") +
          "\"; the axes of the circle's plane must be orthogonal, e.g. 1, 0, "
          "0 and 0, 1, 0");
      return {e1, e2};
    }

    /// True if an entry below @p section holds other than its default.
    bool
    sets_an_entry(const EntryNode &section)
    {
      bool set = false;
      for_each_entry(section, [&set](const std::string &, const EntryNode &e) {
        set = set || e.value != e.default_value;
      });
      return set;
    }

    /**
     * The size of what @p generator makes from @p n segments (per rod,
     * piece or beam), from the entries alone, for the generators that make
     * many points or beams from a few numbers: their size is checked
     * before a point is generated. Empty for the others (the file readers,
     * the frame and the windmill), checked once they are read.
     */
    std::optional<ProblemSize>
    planned_size(const dealii::ParameterHandler &prm,
                 const std::string              &generator,
                 const double                    n)
    {
      if (generator == "straight" || generator == "arc" || generator == "helix")
        return rods_size(1, n);
      if (generator == "ring")
        return rods_size(1, n, 1);
      if (generator == "polyline")
        return rods_size(
          1,
          n * (dealii::Utilities::split_string_list(prm.get("Points"), ';')
                 .size() -
               1));
      if (generator != "square lattice" && generator != "hexagonal lattice")
        return std::nullopt;
      const auto cells = dealii::Utilities::string_to_int(
        dealii::Utilities::split_string_list(prm.get("Cells"), ','));
      const double nx = cells[0], ny = cells[1];
      // Square: the sides of (nx + 1)(ny + 1) nodes; hexagonal: 3 new
      // sides per cell and 2 more at the rim, 2 corners per cell and 2 more.
      return generator == "square lattice" ?
               network_size(nx * (ny + 1) + ny * (nx + 1),
                            (nx + 1) * (ny + 1),
                            n) :
               network_size(3 * nx * ny + 2 * (nx + ny),
                            2 * nx * ny + 2 * (nx + ny),
                            n);
    }

    /// The size of the rods that build_rod_network() makes of @p graph,
    /// @p n segments per beam: its junctions with a rotation (four DoFs)
    /// are the nodes of two or more beam ends or of a kind, but pinned.
    ProblemSize
    graph_size(const RodGraph &graph, const double n)
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
      return network_size(graph.beams.size(), junctions, n);
    }

    /// The size of the rods @p rods, closed where @p closed says.
    ProblemSize
    generated_size(const std::vector<std::vector<Vector3>> &rods,
                   const std::vector<bool>                 &closed)
    {
      double segments = 0, n_closed = 0;
      for (std::size_t r = 0; r < rods.size(); ++r)
        {
          segments += closed[r] ? rods[r].size() : rods[r].size() - 1.0;
          n_closed += closed[r];
        }
      return rods_size(rods.size(), segments, n_closed);
    }

    std::string
    join(const std::vector<std::string> &names, const std::string &separator)
    {
      std::string out;
      for (const std::string &n : names)
        out += (out.empty() ? "" : separator) + n;
      return out;
    }

    /// "x y" or "x=0.1, z=-2" style component lists.
    std::array<bool, 3>
    parse_mask(const std::string &text, const std::string &entry)
    {
      std::array<bool, 3> mask{{false, false, false}};
      std::istringstream  words(text);
      std::string         w;
      while (words >> w)
        {
          if (w != "x" && w != "y" && w != "z")
            throw std::invalid_argument("entry \"" + entry + "\": \"" + w +
                                        "\" is not a component (x, y or z)");
          mask[w[0] - 'x'] = true;
        }
      if (!mask[0] && !mask[1] && !mask[2])
        throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                    "\" names no component");
      return mask;
    }

    /// Splits "vertex: rest" items of a ';'-separated list.
    std::vector<std::pair<std::string, std::string>>
    split_items(const std::string &text, const std::string &entry)
    {
      std::vector<std::pair<std::string, std::string>> items;
      for (const std::string &item :
           dealii::Utilities::split_string_list(text, ';'))
        {
          // The vertex may itself contain "rod:", so split at the last ':'.
          const auto colon = item.rfind(':');
          if (colon == std::string::npos)
            throw std::invalid_argument("entry \"" + entry + "\": \"" + item +
                                        "\" should read \"<vertex>: ...\"");
          items.emplace_back(dealii::Utilities::trim(item.substr(0, colon)),
                             dealii::Utilities::trim(item.substr(colon + 1)));
        }
      return items;
    }

    /// Where the time-stepping entries live, for messages.
    const std::string time_stepping_section = "Solver/Time stepping";

    /// The integrators in the order of the "Integrator" selection.
    const std::vector<Integrator> integrators = {Integrator::quasi_static,
                                                 Integrator::backward_euler,
                                                 Integrator::newmark,
                                                 Integrator::midpoint};

    /// Declares the subsection "Time stepping" in the current subsection.
    void
    declare_time_stepping(dealii::ParameterHandler &prm)
    {
      std::vector<std::string> names;
      for (const Integrator i : integrators)
        names.push_back(to_string(i));
      prm.enter_subsection("Time stepping");
      prm.declare_entry(
        "Integrator",
        to_string(Integrator::newmark),
        Selection(join(names, "|")),
        "quasi-static: equilibrium at every time, no inertia (creep, "
        "relaxation). backward euler: first order, numerically damped. "
        "newmark: average acceleration, second order, undamped. midpoint: "
        "implicit midpoint rule with a discrete gradient, conserves the "
        "energy of elastic rods (not for viscoelastic materials). All but "
        "quasi-static need a Density in every material subsection in "
        "use. [-]");
      // No lower bound in the pattern: a bad step is reported by the
      // scene with what is wrong, rather than as a pattern mismatch.
      prm.declare_entry("Time step",
                        "0",
                        Double(),
                        "Nominal time step h, required (positive), at most "
                        "1e6 steps from the start to the end time; a step "
                        "whose Newton solve fails is halved down to "
                        "\"Minimum step fraction\" of it. [s]");
      prm.declare_entry("Start time", "0", Double(), "Time of the start. [s]");
      prm.declare_entry("End time",
                        "1",
                        Double(),
                        "Time of the end, not before the start. [s]");
      prm.declare_entry(
        "Load factor",
        "1",
        Anything(),
        "Factor on every load and prescribed displacement as a function of "
        "the time t, a muparser expression (pi is defined), e.g. \"if(t < "
        "0, 1, 0)\" (held during a preload, released at t = 0) or "
        "\"sin(2*pi*5*t)\". [-]");
      prm.declare_entry(
        "Preload time",
        "0",
        Double(0),
        "Quasi-static hold before the start: the structure is loaded by the "
        "load factor over this time before \"Start time\" and starts from "
        "rest; viscoelastic rods creep meanwhile. 0: no preload. [s]");
      prm.declare_entry("Preload steps",
                        "1",
                        Integer(1),
                        "Equal quasi-static steps of the preload. [-]");
      prm.declare_entry("Mass",
                        "consistent",
                        Selection("consistent|lumped"),
                        "Distribution of each segment's mass onto its "
                        "vertices: linear shape functions (consistent) or "
                        "half at each end (lumped). [-]");
      prm.declare_entry("Progress interval",
                        "100",
                        Integer(0),
                        "Print time, Newton iterations and energy every this "
                        "many steps (0: never). [-]");
      prm.declare_entry(
        "Energy growth limit",
        "0.01",
        Double(0),
        "A dynamic run stops as unstable where, under an unchanged load "
        "factor, the total energy grows by more than this fraction of its "
        "value (or of the largest kinetic energy since the load last "
        "changed); 0 switches the check off. [-]");
      prm.declare_entry(
        "Initial displacement",
        "0; 0; 0",
        Anything(),
        "Displacement of every vertex at the start, three ';'-separated "
        "muparser expressions of its undeformed position x, y, z, e.g. \"0; "
        "0; 0.01*x^2\"; supported components take their prescribed values. "
        "With a preload, the state the preload starts from. [m]");
      prm.declare_entry("Initial velocity",
                        "0; 0; 0",
                        Anything(),
                        "Velocity of every vertex at the start, as \"Initial "
                        "displacement\"; zero on supported components, and "
                        "ignored after a preload, which ends at rest. [m/s]");
      prm.leave_subsection();
    }

    /**
     * The function of the ';'-separated muparser expressions @p text
     * (one per component) in the variables @p variables, with the constant
     * pi. Muparser reads
     * an expression when it is first evaluated, so every component is
     * evaluated once at the origin here, which makes a syntax error or an
     * unknown name an error of the entry @p entry rather than of the run.
     */
    template <int dim>
    std::shared_ptr<const dealii::FunctionParser<dim>>
    parse_function(const std::string &text,
                   const std::string &variables,
                   const unsigned int n_components,
                   const std::string &entry)
    {
      const std::vector<std::string> expressions =
        dealii::Utilities::split_string_list(text, ';');
      if (expressions.size() != n_components)
        throw std::invalid_argument(
          "entry \"" + entry + "\": \"" + text + "\" should be " +
          std::to_string(n_components) + " expression(s) of " + variables +
          " separated by ';'");
      auto function =
        std::make_shared<dealii::FunctionParser<dim>>(n_components);
      try
        {
          function->initialize(variables, expressions, {{"pi", M_PI}});
          for (unsigned int c = 0; c < n_components; ++c)
            function->value(dealii::Point<dim>(), c);
        }
      catch (const std::exception &e)
        {
          throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                      "\" is not an expression of " +
                                      variables + ": " + error_message(e));
        }
      return function;
    }

  } // namespace

  std::string
  error_message(const std::exception &e)
  {
    std::ostringstream text;
    if (const auto *info = dynamic_cast<const dealii::ExceptionBase *>(&e))
      info->print_info(text);
    else
      text << e.what();
    std::istringstream words(text.str());
    std::string        word, line;
    while (words >> word)
      line += (line.empty() ? "" : " ") + word;
    return line;
  }

  void
  Scene::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry(
        "Generator",
        "straight",
        Selection("straight|arc|ring|helix|polyline|gmsh|frame|windmill|"
                  "square lattice|hexagonal lattice|network file|"
                  "gmsh network"),
        "How the rods are made: a straight rod, a circular arc, a closed "
        "ring, a helix, a polyline through given points, the rods of a Gmsh "
        "line mesh (one rod per physical tag); or a network of beams tied at "
        "junctions: the right-angle frame and the windmill of Lestringant & "
        "Kochmann (Fig. 3), a square or hexagonal lattice, a node/beam list "
        "file, or a branched Gmsh line mesh (see doc/networks.md).");
      prm.declare_entry("Beam length",
                        "1",
                        Double(0),
                        "Networks: leg length of the frame, shaft length of "
                        "the windmill, cell side of the lattices. [m]");
      prm.declare_entry("Cells",
                        "2, 2",
                        dealii::Patterns::List(Integer(1), 2, 2, ","),
                        "Lattices: number of cells along x and y. [-]");
      prm.declare_entry("Network file",
                        "",
                        Anything(),
                        "Network file: path of the node/beam list, relative "
                        "to the scene file. [-]");
      prm.declare_entry(
        "Ghost spin",
        "exact",
        Selection("exact|small rotation"),
        "Junctions: spin angle of the ghost segments, exact for finite "
        "rotations (L&K appendix B) or its small-rotation form (eq. 8). [-]");
      prm.declare_entry("Segments",
                        "100",
                        Integer(1),
                        "Number of segments of the rod (per piece for a "
                        "polyline, per beam for a generated network or "
                        "network file). [-]");
      prm.declare_entry("Start",
                        "0, 0, 0",
                        vector_pattern,
                        "Straight rod: first end. [m]");
      prm.declare_entry("End",
                        "1, 0, 0",
                        vector_pattern,
                        "Straight rod: second end. [m]");
      prm.declare_entry(
        "Clamp at first segment midpoint",
        "false",
        Bool(),
        "Open rods (straight, arc, helix, polyline, gmsh): centre the first "
        "segment on the rod's start, along the rod's tangent there (the "
        "chain begins half a segment behind the start), so that the clamp "
        "of the start, which Supports/Clamped ends must then hold, acts "
        "exactly at the start with the rod's tangent, and the free length "
        "is the rod's length. Not for rings, networks (clamp a node "
        "instead) or dynamic relaxation. [-]");
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
      prm.declare_entry("Center",
                        "0, 0, 0",
                        vector_pattern,
                        "Arc and ring: center of the circle. [m]");
      prm.declare_entry("Radius",
                        "1",
                        Double(0),
                        "Arc, ring and helix: radius. [m]");
      prm.declare_entry("Plane axis 1",
                        "1, 0, 0",
                        vector_pattern,
                        "Arc and ring: direction of the first in-plane "
                        "axis (normalized; angle 0). [-]");
      prm.declare_entry("Plane axis 2",
                        "0, 1, 0",
                        vector_pattern,
                        "Arc and ring: direction of the second in-plane "
                        "axis (normalized; angle 90 deg), orthogonal to the "
                        "first. [-]");
      prm.declare_entry("Start angle",
                        "0",
                        Double(),
                        "Arc: angle of the first vertex. [deg]");
      prm.declare_entry("End angle",
                        "90",
                        Double(),
                        "Arc: angle of the last vertex. [deg]");
      prm.declare_entry("Rise per radian",
                        "0.1",
                        Double(),
                        "Helix: axial rise per radian of turn (the pitch "
                        "divided by 2 pi). [m]");
      prm.declare_entry("Turns", "1", Double(0), "Helix: number of turns. [-]");
      prm.declare_entry("Points",
                        "0,0,0; 1,0,0",
                        Anything(),
                        "Polyline: corner points \"x,y,z; x,y,z; ...\". [m]");
      prm.declare_entry("Mesh file",
                        "",
                        Anything(),
                        "Gmsh: path of the .msh line mesh, relative to the "
                        "scene file. [-]");
      prm.declare_entry("Director d1",
                        "0, 1, 0",
                        vector_pattern,
                        "Orientation of the first material director: d1 of "
                        "each segment is this vector made orthogonal to the "
                        "segment. Bending stiffness EI1 acts about d1. [-]");
      prm.declare_entry("Hinge kernel",
                        "simple",
                        Selection(join(hinge_kernel_names(), "|")),
                        "Bending and twisting measures: \"simple\" (Korner, "
                        "Audoly, Bhattacharya 2021) or \"classic\" "
                        "(Lestringant & Kochmann 2020, eqs. 10-12). [-]");
    }
    prm.leave_subsection();

    for (unsigned int group = 0; group < n_material_groups; ++group)
      {
        prm.enter_subsection(material_section(group));
        if (group > 0)
          prm.declare_entry("Use",
                            "false",
                            Bool(),
                            "Give the beams of material group " +
                              std::to_string(group) +
                              " of a network this material instead of "
                              "that of subsection Material. [-]");
        prm.declare_entry(
          "Density",
          "0",
          Double(0),
          "Mass density rho of the rods, for time stepping: a rod carries rho "
          "A per length and rho (I1 + I2) of twist inertia, with A, I1, I2 "
          "from the cross-section of the model's \"Stiffness input = "
          "section\". 0 means not given, which static solves and "
          "quasi-static time stepping accept. [kg/m^3]");
        const std::vector<std::string> names =
          MaterialRegistry::instance().names();
        std::string help = "Constitutive law of the rods:";
        for (const std::string &n : names)
          help +=
            " \"" + n + "\": " + MaterialRegistry::instance().description(n);
        prm.declare_entry("Model",
                          names.front(),
                          Selection(join(names, "|")),
                          help);
        for (const std::string &n : names)
          {
            prm.enter_subsection(n);
            MaterialRegistry::instance().create(n)->declare_parameters(prm);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }

    prm.enter_subsection("Supports");
    {
      prm.declare_entry("Clamped ends",
                        "",
                        Anything(),
                        "Rod ends clamped by holding their end segment (two "
                        "vertices and the twist; Korner et al. 5a), e.g. "
                        "\"start\" or \"0:start, 1:end\", or \"@name\" of a "
                        "free network end or of a junction (held whole). A "
                        "clamp moves rigidly with the prescribed "
                        "displacement and rotation of its end vertex. [-]");
      prm.declare_entry(
        "Pinned vertices",
        "",
        Anything(),
        "Vertices whose position is fixed, e.g. \"end, 0:mid\". "
        "Vertices are [rod:]start|end|mid|<index>. [-]");
      prm.declare_entry("Fixed components",
                        "",
                        Anything(),
                        "Position components held at zero displacement: "
                        "\"<vertex>: <components>; ...\", e.g. \"mid: z; "
                        "end: y z\". [-]");
      prm.declare_entry(
        "Prescribed rotations",
        "",
        Anything(),
        "Rotations reached at load factor 1 and ramped with it: \"<where>: "
        "<ax>,<ay>,<az> <angle>; ...\" (angle in degrees about the axis), "
        "where is a clamped end (turned about its end vertex), a junction "
        "or any vertex (a rotation handle there, its position free). [deg]");
      prm.declare_entry("Prescribed displacements",
                        "",
                        Anything(),
                        "Displacements reached at load factor 1 and ramped "
                        "with it: \"<vertex>: x=<dx> y=<dy>; ...\". [m]");
    }
    prm.leave_subsection();

    prm.enter_subsection("Loads");
    {
      prm.declare_entry(
        "Steps",
        "10",
        Integer(1),
        "Number of equal load steps from load factor 0 to 1, at most "
        "100000; every load and prescribed displacement is ramped. [-]");
      prm.declare_entry("Point forces",
                        "",
                        Anything(),
                        "Dead forces at load factor 1: \"<vertex>: fx, fy, fz; "
                        "...\". [N]");
      prm.declare_entry("Moments",
                        "",
                        Anything(),
                        "Moments about fixed axes at load factor 1: "
                        "\"<where>: <ax>,<ay>,<az> <M>; ...\", where is a "
                        "junction with a free rotation or any vertex that no "
                        "clamp holds (a rotation handle there). [N m]");
      prm.declare_entry("Distributed force",
                        "0, 0, 0",
                        vector_pattern,
                        "Dead force per unit undeformed length on every rod at "
                        "load factor 1. [N/m]");
      prm.declare_entry("Gravity",
                        "0, 0, 0",
                        vector_pattern,
                        "Gravitational acceleration; the weight per length is "
                        "\"Mass per length\" times this. [m/s^2]");
      prm.declare_entry("Mass per length",
                        "0",
                        Double(0),
                        "Mass of the rod per unit undeformed length, for "
                        "gravity. [kg/m]");
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    {
      prm.declare_entry(
        "Method",
        "newton",
        Selection("newton|dynamic relaxation|time stepping"),
        "newton: discrete elastic rods and junction elements, Newton per "
        "load step (Trilinos NOX). dynamic relaxation: the bending-active "
        "beam element (position, normal and rotation per node) relaxed by "
        "explicit pseudo-dynamics with kinetic damping; see "
        "doc/dynamic_relaxation.md for which to pick. time stepping: the "
        "discrete rods in time, with inertia or quasi-statically, for "
        "vibrations and viscoelastic materials (subsection Time stepping; "
        "the Newton entries of Solver apply to every time step). [-]");
      declare_time_stepping(prm);
      prm.enter_subsection("Dynamic relaxation");
      {
        prm.declare_entry("Time step",
                          "1",
                          Double(0),
                          "Pseudo-time step; the fictitious masses are "
                          "scaled for it (stable up to sqrt(2 Mass "
                          "scaling)), and an unstable run halves it. [-]");
        prm.declare_entry("Mass scaling",
                          "1",
                          Double(1),
                          "Factor on the fictitious masses of the stability "
                          "bound (>= 1). [-]");
        prm.declare_entry("Residual tolerance",
                          "1e-6",
                          Double(0, 1),
                          "Converged when the out-of-balance force norm is "
                          "below this times the applied load norm (or the "
                          "step's initial residual). [-]");
        prm.declare_entry("Max iterations",
                          "1000000",
                          Integer(1),
                          "Pseudo-time iterations per load step. [-]");
        prm.declare_entry("Progress interval",
                          "0",
                          Integer(0),
                          "Print iteration, kinetic energy and residual every "
                          "this many iterations (0: once per load step). [-]");
      }
      prm.leave_subsection();
      prm.declare_entry("Line search",
                        "full step",
                        Selection("backtrack|polynomial|full step"),
                        "Globalization of Newton's method (Trilinos NOX). The "
                        "line searches reduce the residual norm, which for "
                        "nearly inextensible rods (large EA) rejects good "
                        "Newton steps; the default takes full steps and "
                        "relies on load-step cutting instead. [-]");
      prm.declare_entry(
        "Max iterations",
        "25",
        Integer(1),
        "Newton iterations per load or time step before it is cut. [-]");
      prm.declare_entry("Relative tolerance",
                        "1e-9",
                        Double(0, 1),
                        "Converged when the residual force norm is below this "
                        "times the applied load norm (or the step's initial "
                        "residual). [-]");
      prm.declare_entry("Predictor",
                        "true",
                        Bool(),
                        "Start each load step from a prediction: the last "
                        "converged increment scaled to the step, or on the "
                        "first step the linear response to the prescribed "
                        "displacements. Keeps displacement-driven steps "
                        "converging on fine meshes. [-]");
      prm.declare_entry("Minimum step fraction",
                        "0.0009765625",
                        Double(0, 1),
                        "Failed load and time steps are halved; the run stops "
                        "with an error below this fraction of the nominal "
                        "step. [-]");
      prm.declare_entry("Critical load search",
                        "false",
                        Bool(),
                        "Track the lowest eigenvalue of the tangent and locate "
                        "by bisection the load factor where it crosses "
                        "zero. [-]");
      prm.declare_entry("Critical load tolerance",
                        "1e-6",
                        Double(0, 1),
                        "Bracket width of the bisection, in load factor. [-]");
      prm.declare_entry(
        "Branch switching amplitude",
        "0",
        Double(0, 1),
        "Where a converged equilibrium is unstable (negative lowest "
        "eigenvalue), push it along the buckling mode, both ways, by a dead "
        "force of this fraction of the applied load, remove that force in "
        "four steps, and continue on the stable equilibrium of lower energy "
        "found; 0 switches this off. Costs a dense eigenvalue analysis per "
        "step. [-]");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "output",
                        Anything(),
                        "Where outputs go (overridden by --output). [-]");
      prm.declare_entry("Write VTU",
                        "true",
                        Bool(),
                        "Write solution-NNNNN.vtu and solution.pvd. [-]");
      prm.declare_entry("VTU interval",
                        "1",
                        Integer(1),
                        "Write the VTU of every n-th step (step 0 is the "
                        "unloaded or initial state); a run writes at most "
                        "10000 VTU files, and no more than fit on the "
                        "disk. [-]");
      prm.declare_entry("Probes",
                        "",
                        Anything(),
                        "Columns of probes.csv: \"name: kind args; ...\" with "
                        "the kinds " +
                          probe_kinds_description() +
                          ". energy: the elastic energy; eigenvalue: the "
                          "lowest of the constrained tangent (Newton only); "
                          "rotation: the angle of a junction's rotation "
                          "about the axis, continuous over the steps; "
                          "moment: the reaction moment at a junction. [-]");
      prm.declare_entry("Plot",
                        "true",
                        Bool(),
                        "Plot the probes against the load factor (the time "
                        "for time stepping) into probes.png (needs "
                        "gnuplot). [-]");
    }
    prm.leave_subsection();
  }

  Scene::Scene(dealii::ParameterHandler &prm,
               const std::string        &scene_directory)
  {
    // Before anything is read or generated: every number of every entry.
    const EntryNode entries = entry_tree(prm);
    check_entry_numbers(entries,
                        {"Geometry/Mesh file",
                         "Geometry/Network file",
                         "Output/Directory"});
    const std::string solution_method = prm.get({"Solver"}, "Method");
    const double      bytes_per_dof =
      memory_per_dof(solution_method == "newton" ||
                       (solution_method == "time stepping" &&
                        prm.get({"Solver", "Time stepping"}, "Integrator") ==
                          "quasi-static"),
                     solution_method == "time stepping",
                     prm.get_bool({"Output"}, "Write VTU"));
    // What cannot fit in memory is refused before it is generated.
    const auto check_size = [&](ProblemSize size, const std::string &entry) {
      size.bytes_per_dof = bytes_per_dof;
      check_memory(size, available_memory(), entry);
      return size;
    };

    prm.enter_subsection("Geometry");
    {
      // File names are relative to the scene file.
      const auto resolve = [&](std::string file, const std::string &entry) {
        if (file.empty())
          throw std::invalid_argument("entry \"Geometry/" + entry +
                                      "\" is empty but the generator needs it");
        const std::string path =
          file[0] == '/' ? file : scene_directory + "/" + file;
        if (std::filesystem::is_directory(path))
          throw std::invalid_argument("entry \"Geometry/" + entry + "\": \"" +
                                      path + "\" is a directory, not a file");
        return path;
      };
      const std::string  generator = prm.get("Generator");
      const unsigned int n         = prm.get_integer("Segments");
      const double       degree    = M_PI / 180;
      director_hint                = get_direction(prm, "Director d1");
      hinge_kernel                 = prm.get("Hinge kernel");
      natural_shape  = natural_shape_from_string(prm.get("Natural shape"));
      midpoint_clamp = prm.get_bool("Clamp at first segment midpoint");
      if (midpoint_clamp && generator != "straight" && generator != "arc" &&
          generator != "helix" && generator != "polyline" &&
          generator != "gmsh")
        throw std::invalid_argument(
          "entry \"Geometry/Clamp at first segment midpoint\": the " +
          generator +
          " generator has no open rod start for it (rings are closed; a "
          "network clamps exactly at a clamped node); set it to false");
      const bool lattice = generator.find("lattice") != std::string::npos;
      const std::string size_entry =
        lattice ? "Geometry/Cells" : "Geometry/Segments";
      if (const auto planned = planned_size(prm, generator, n))
        check_size(*planned, size_entry);
      if (generator == "straight")
        rod_points.push_back(generators::straight(get_vector(prm, "Start"),
                                                  get_vector(prm, "End"),
                                                  n,
                                                  midpoint_clamp));
      else if (generator == "arc")
        rod_points.push_back(
          generators::arc(get_vector(prm, "Center"),
                          prm.get_double("Radius"),
                          get_plane_axes(prm).first,
                          get_plane_axes(prm).second,
                          prm.get_double("Start angle") * degree,
                          prm.get_double("End angle") * degree,
                          n,
                          midpoint_clamp));
      else if (generator == "ring")
        rod_points.push_back(generators::ring(get_vector(prm, "Center"),
                                              prm.get_double("Radius"),
                                              get_plane_axes(prm).first,
                                              get_plane_axes(prm).second,
                                              n));
      else if (generator == "helix")
        rod_points.push_back(
          generators::helix(prm.get_double("Radius"),
                            prm.get_double("Rise per radian"),
                            prm.get_double("Turns"),
                            n,
                            midpoint_clamp));
      else if (generator == "polyline")
        {
          std::vector<Vector3> corners;
          for (const std::string &p :
               dealii::Utilities::split_string_list(prm.get("Points"), ';'))
            {
              const auto xyz = dealii::Utilities::split_string_list(p, ',');
              try
                {
                  if (xyz.size() != 3)
                    throw std::invalid_argument("");
                  const auto v = dealii::Utilities::string_to_double(xyz);
                  corners.emplace_back(v[0], v[1], v[2]);
                }
              catch (const std::exception &)
                {
                  throw std::invalid_argument("entry \"Geometry/Points\": \"" +
                                              p + "\" is not a point x,y,z");
                }
            }
          rod_points.push_back(
            generators::polyline(corners, n, midpoint_clamp));
        }
      else if (generator == "gmsh")
        {
          for (const RodChain &chain :
               read_gmsh_rods(resolve(prm.get("Mesh file"), "Mesh file")))
            {
              if (midpoint_clamp && chain.closed)
                throw std::invalid_argument(
                  "entry \"Geometry/Clamp at first segment midpoint\": "
                  "physical tag " +
                  std::to_string(chain.tag) +
                  " of the mesh is a closed chain with no start to clamp; "
                  "set it to false");
              rod_points.push_back(
                midpoint_clamp ?
                  generators::center_first_segment_on_start(chain.points) :
                  chain.points);
              rod_closed.push_back(chain.closed);
            }
        }
      else
        {
          const double a     = prm.get_double("Beam length");
          const auto   cells = dealii::Utilities::string_to_int(
            dealii::Utilities::split_string_list(prm.get("Cells"), ','));
          if (generator == "frame")
            graph = network_generators::right_angle_frame(a);
          else if (generator == "windmill")
            graph = network_generators::windmill(a);
          else if (generator == "square lattice")
            graph = network_generators::square_lattice(cells[0], cells[1], a);
          else if (generator == "hexagonal lattice")
            graph =
              network_generators::hexagonal_lattice(cells[0], cells[1], a);
          else if (generator == "network file")
            graph = read_network_file(
              resolve(prm.get("Network file"), "Network file"));
          else
            graph =
              read_gmsh_network(resolve(prm.get("Mesh file"), "Mesh file"));
          segments_per_beam = n;
        }
      rod_closed.resize(rod_points.size(), generator == "ring");
      ghost_spin = prm.get("Ghost spin") == "exact" ? GhostSpin::exact :
                                                      GhostSpin::small_rotation;
      model_size = check_size(graph ? graph_size(*graph, n) :
                                      generated_size(rod_points, rod_closed),
                              size_entry);
    }
    prm.leave_subsection();

    for (unsigned int group = 0; group < n_material_groups; ++group)
      {
        prm.enter_subsection(material_section(group));
        if (group == 0 || prm.get_bool("Use"))
          {
            MaterialGroup g;
            g.subsection = material_section(group);
            g.model      = prm.get("Model");
            g.density    = prm.get_double("Density");
            if (!sets_an_entry(*entries.find(g.subsection)->find(g.model)))
              throw std::invalid_argument(
                "subsection \"" + g.subsection + "/" + g.model +
                "\" sets no entry, so the rods have no stiffness: give a "
                "Young's modulus and a cross section, or the rigidities "
                "(rodnet-run --help lists the entries; scenes/elastica.prm "
                "is an example)");
            auto m = MaterialRegistry::instance().create(g.model);
            prm.enter_subsection(g.model);
            // The material's message names its entry; this adds which
            // material subsection.
            try
              {
                m->parse_parameters(prm);
              }
            catch (const dealii::ExceptionBase &e)
              {
                throw std::invalid_argument("subsection \"" + g.subsection +
                                            "\": " + error_message(e));
              }
            // Both registered materials read "section" the same way; the
            // material has checked the section's entries already.
            if (prm.get("Stiffness input") == "section")
              g.section = CrossSectionParameters::parse_parameters(prm);
            prm.leave_subsection();
            g.material = std::move(m);
            material_groups.push_back(std::move(g));
          }
        else
          material_groups.push_back(material_groups.front());
        prm.leave_subsection();
      }

    prm.enter_subsection("Supports");
    clamped_ends             = prm.get("Clamped ends");
    pinned_vertices          = prm.get("Pinned vertices");
    fixed_components         = prm.get("Fixed components");
    prescribed_displacements = prm.get("Prescribed displacements");
    prescribed_rotations     = prm.get("Prescribed rotations");
    prm.leave_subsection();

    prm.enter_subsection("Loads");
    solver.n_steps    = prm.get_integer("Steps");
    point_forces      = prm.get("Point forces");
    moments           = prm.get("Moments");
    distributed_force = get_vector(prm, "Distributed force");
    gravity           = get_vector(prm, "Gravity");
    mass_per_length   = prm.get_double("Mass per length");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    solver.newton.line_search      = prm.get("Line search");
    solver.newton.max_iterations   = prm.get_integer("Max iterations");
    solver.relative_tolerance      = prm.get_double("Relative tolerance");
    solver.min_step_fraction       = prm.get_double("Minimum step fraction");
    solver.predict                 = prm.get_bool("Predictor");
    solver.find_critical_load      = prm.get_bool("Critical load search");
    solver.critical_load_tolerance = prm.get_double("Critical load tolerance");
    solver.branch_switch_amplitude =
      prm.get_double("Branch switching amplitude");
    const std::string method_name = prm.get("Method");
    method = method_name == "newton" ? SolutionMethod::newton :
             method_name == "dynamic relaxation" ?
                                       SolutionMethod::dynamic_relaxation :
                                       SolutionMethod::time_stepping;
    parse_time_stepping(prm);
    prm.enter_subsection("Dynamic relaxation");
    relaxation.n_steps            = solver.n_steps;
    relaxation.time_step          = prm.get_double("Time step");
    relaxation.mass_scaling       = prm.get_double("Mass scaling");
    relaxation.residual_tolerance = prm.get_double("Residual tolerance");
    relaxation.max_iterations     = prm.get_integer("Max iterations");
    relaxation.progress_interval  = prm.get_integer("Progress interval");
    prm.leave_subsection();
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    write_vtu        = prm.get_bool("Write VTU");
    vtu_interval     = prm.get_integer("VTU interval");
    probe_text       = prm.get("Probes");
    plot             = prm.get_bool("Plot");
    prm.leave_subsection();
    check_run_length();
  }

  const ProblemSize &
  Scene::size() const
  {
    return model_size;
  }

  double
  Scene::planned_steps() const
  {
    const TimeIntegrator::Parameters &t = time_stepping;
    return method == SolutionMethod::time_stepping ?
             std::ceil((t.end_time - t.start_time) / t.time_step) +
               (t.preload_time > 0 ? t.preload_steps : 0) :
             solver.n_steps;
  }

  double
  Scene::planned_vtu_files() const
  {
    // Step 0 (the unloaded or initial state), then every interval-th step.
    return write_vtu ? std::floor(planned_steps() / vtu_interval) + 1 : 0;
  }

  void
  Scene::check_run_length() const
  {
    using namespace run_limits;
    if (method != SolutionMethod::time_stepping &&
        solver.n_steps > max_load_steps)
      throw std::invalid_argument(
        "entry \"Loads/Steps\": " + std::to_string(solver.n_steps) +
        " load steps are more than the " + std::to_string(max_load_steps) +
        " a run may take; fewer do as well (a step that fails is cut "
        "where needed)");
    const TimeIntegrator::Parameters &t = time_stepping;
    const double n_time_steps = (t.end_time - t.start_time) / t.time_step;
    if (method == SolutionMethod::time_stepping &&
        n_time_steps > max_time_steps)
      throw std::invalid_argument(
        "entry \"" + time_stepping_section + "/Time step\": " +
        number(t.time_step) + " s from " + number(t.start_time) + " to " +
        number(t.end_time) + " s are " + number(std::ceil(n_time_steps)) +
        " time steps, more than the " + number(max_time_steps) +
        " a run may take; take a larger step or a shorter time");
    const double files = planned_vtu_files();
    if (files > max_vtu_files)
      throw std::invalid_argument(
        "entry \"Output/VTU interval\": the run would write " + number(files) +
        " VTU files, more than the " + std::to_string(max_vtu_files) +
        " a run may write; set the interval to " +
        number(std::ceil(planned_steps() / (max_vtu_files - 1))) +
        " or more, or \"Write VTU = false\"");
  }

  void
  Scene::parse_time_stepping(dealii::ParameterHandler &prm)
  {
    TimeIntegrator::Parameters &p = time_stepping;
    p.newton                      = solver.newton;
    p.relative_tolerance          = solver.relative_tolerance;
    p.min_step_fraction           = solver.min_step_fraction;
    prm.enter_subsection("Time stepping");
    p.integrator    = parse_integrator(prm.get("Integrator"));
    p.time_step     = prm.get_double("Time step");
    p.start_time    = prm.get_double("Start time");
    p.end_time      = prm.get_double("End time");
    p.preload_time  = prm.get_double("Preload time");
    p.preload_steps = prm.get_integer("Preload steps");
    p.mass =
      prm.get("Mass") == "lumped" ? MassKind::lumped : MassKind::consistent;
    p.progress_interval          = prm.get_integer("Progress interval");
    p.energy_growth_limit        = prm.get_double("Energy growth limit");
    const std::string load_entry = time_stepping_section + "/Load factor";
    p.load_factor =
      [load_entry,
       f = parse_function<1>(prm.get("Load factor"), "t", 1, load_entry)](
        const double t) {
        const double value = f->value(dealii::Point<1>(t));
        if (!std::isfinite(value))
          throw std::invalid_argument(
            "entry \"" + load_entry + "\": the load factor is " +
            number(value) + " at t = " + number(t) + " s");
        return value;
      };
    initial_displacement =
      parse_function<3>(prm.get("Initial displacement"),
                        "x,y,z",
                        3,
                        time_stepping_section + "/Initial displacement");
    initial_velocity =
      parse_function<3>(prm.get("Initial velocity"),
                        "x,y,z",
                        3,
                        time_stepping_section + "/Initial velocity");
    prm.leave_subsection();
    if (method == SolutionMethod::time_stepping)
      check_time_stepping();
  }

  void
  Scene::check_time_stepping() const
  {
    const TimeIntegrator::Parameters &p = time_stepping;
    const std::string entry = "entry \"" + time_stepping_section + "/";
    if (!(p.time_step > 0) || !std::isfinite(p.time_step))
      throw std::invalid_argument(entry +
                                  "Time step\": must be positive, got " +
                                  number(p.time_step) + " s");
    if (!(p.end_time >= p.start_time))
      throw std::invalid_argument(entry + "End time\": " + number(p.end_time) +
                                  " s lies before the start time " +
                                  number(p.start_time) + " s");
    if (p.integrator == Integrator::quasi_static)
      return;
    // Throws for a material group without density or section.
    inertia();
    if (p.integrator == Integrator::midpoint)
      for (const unsigned int g : rod_groups())
        {
          const RodMaterial &m = *material_groups[g].material;
          if (m.n_hinge_internal_variables() +
                m.n_segment_internal_variables() >
              0)
            throw std::invalid_argument(
              entry +
              "Integrator\": the midpoint rule conserves a stored "
              "energy, which the \"" +
              material_groups[g].model + "\" of subsection \"" +
              material_groups[g].subsection +
              "\" does not have (it has internal variables); use newmark or "
              "backward euler");
        }
  }

  std::vector<unsigned int>
  Scene::rod_groups() const
  {
    if (!graph)
      return std::vector<unsigned int>(rod_points.size(), 0);
    // build_rod_network() makes beam b rod b.
    std::vector<unsigned int> groups;
    for (const RodGraph::Beam &beam : graph->beams)
      {
        if (beam.group >= material_groups.size())
          throw std::invalid_argument(
            "the network has material group " + std::to_string(beam.group) +
            "; scenes define groups 0 to " +
            std::to_string(material_groups.size() - 1));
        groups.push_back(beam.group);
      }
    return groups;
  }

  std::vector<RodInertia>
  Scene::inertia() const
  {
    const std::string       integrator = to_string(time_stepping.integrator);
    std::vector<RodInertia> result;
    for (const unsigned int g : rod_groups())
      {
        const MaterialGroup &group = material_groups[g];
        if (!(group.density > 0))
          throw std::invalid_argument(
            "entry \"" + group.subsection +
            "/Density\": time stepping with the " + integrator +
            " integrator needs the density of every material in use (0 means "
            "not given)");
        if (!group.section)
          throw std::invalid_argument(
            "entry \"" + group.subsection + "/" + group.model +
            "/Stiffness input\": time stepping with the " + integrator +
            " integrator takes the inertia rho A and rho (I1 + I2) from the "
            "cross-section, which \"direct\" rigidities do not give; use "
            "\"section\"");
        result.push_back(rod_inertia(*group.section, group.density));
      }
    return result;
  }

  std::vector<double>
  Scene::fiber_distances() const
  {
    std::vector<double> result;
    for (const unsigned int g : rod_groups())
      {
        const std::optional<CrossSection> &section =
          material_groups[g].section;
        result.push_back(
          section ?
            2 * std::sqrt(std::max(section->I1, section->I2) / section->area) :
            std::nan(""));
      }
    return result;
  }

  void
  Scene::initial_state(const RodModel &model,
                       VectorType     &u,
                       VectorType     &v) const
  {
    const RodNetwork &net = model.network();
    // Vertices of rod ends at a junction share its position DoFs (and
    // position), so writing every vertex is consistent.
    const auto fill = [&](const dealii::Function<3> &function,
                          const std::string         &name,
                          VectorType                &field) {
      field = model.create_vector();
      for (unsigned int vertex = 0; vertex < net.n_vertices(); ++vertex)
        {
          const Vector3          x = net.vertex(vertex);
          const dealii::Point<3> p(x[0], x[1], x[2]);
          for (unsigned int c = 0; c < 3; ++c)
            {
              const double value = function.value(p, c);
              if (!std::isfinite(value))
                throw std::invalid_argument(
                  "entry \"" + time_stepping_section + "/" + name +
                  "\": component " + std::to_string(c + 1) + " is " +
                  number(value) + " at (" + number(x[0]) + ", " + number(x[1]) +
                  ", " + number(x[2]) + ")");
              field[model.layout().vertex_dof(vertex, c)] = value;
            }
        }
      field.compress(dealii::VectorOperation::insert);
    };
    fill(*initial_displacement, "Initial displacement", u);
    fill(*initial_velocity, "Initial velocity", v);
    // Supports hold still; the integrator sets their displacements.
    model.constraints().set_zero(v);
  }

  std::pair<std::unique_ptr<RodNetwork>,
            std::vector<std::shared_ptr<const RodMaterial>>>
  Scene::build_network() const
  {
    std::unique_ptr<RodNetwork> network;
    if (graph)
      network = build_rod_network(*graph,
                                  segments_per_beam,
                                  hinge_kernel,
                                  natural_shape)
                  .network;
    else
      {
        network = std::make_unique<RodNetwork>();
        for (unsigned int r = 0; r < rod_points.size(); ++r)
          network->add_rod(rod_points[r],
                           rod_closed[r],
                           director_hint,
                           hinge_kernel,
                           natural_shape);
        network->create_triangulation();
      }
    std::vector<std::shared_ptr<const RodMaterial>> materials;
    for (const unsigned int g : rod_groups())
      materials.push_back(material_groups[g].material);
    return {std::move(network), materials};
  }

  std::unique_ptr<RodModel>
  Scene::build_model() const
  {
    auto [network, materials] = build_network();
    add_rotation_handles(*network);
    auto model =
      std::make_unique<RodModel>(std::move(network), materials, ghost_spin);
    model->apply(supports_and_loads(model->network()));
    model->finalize();
    if (midpoint_clamp)
      check_midpoint_clamps(*model);
    return model;
  }

  void
  Scene::check_midpoint_clamps(const RodModel &model) const
  {
    // The chain begins half a segment behind the start: without a clamp
    // there the rod would be half a segment too long.
    const auto &constraints = model.constraints();
    for (unsigned int r = 0; r < model.network().rods().size(); ++r)
      {
        const Rod &rod     = model.network().rods()[r];
        bool       clamped = constraints.is_constrained(
          model.layout().twist_dof(rod.segments.front()));
        for (unsigned int v = 0; v < 2; ++v)
          for (unsigned int c = 0; c < 3; ++c)
            clamped =
              clamped && constraints.is_constrained(
                           model.layout().vertex_dof(rod.vertices[v], c));
        if (!clamped)
          throw std::invalid_argument(
            "entry \"Geometry/Clamp at first segment midpoint\": the start "
            "of rod " +
            std::to_string(r) +
            " is not clamped, but the option begins the rod half a segment "
            "behind its start for a clamp there; clamp it (Supports/Clamped "
            "ends = " +
            (model.network().rods().size() > 1 ? std::to_string(r) + ":" :
                                                 std::string()) +
            "start) or set the option to false");
      }
  }

  void
  Scene::add_rotation_handles(RodNetwork &network) const
  {
    // Clamped rod ends turn with their clamp and take no moment.
    std::set<unsigned int> clamped;
    for (const std::string &end :
         dealii::Utilities::split_string_list(clamped_ends, ','))
      {
        const auto target =
          select_rod_end(network, end, "Supports/Clamped ends");
        if (const auto *rod_end = std::get_if<RodEnd>(&target))
          clamped.insert(network.end_vertex(*rod_end));
      }
    for (const auto &[entry, text] :
         {std::make_pair("Supports/Prescribed rotations", prescribed_rotations),
          std::make_pair("Loads/Moments", moments)})
      for (const auto &[name, value] : split_items(text, entry))
        {
          const RotationTarget target =
            select_rotation_target(network, name, entry);
          if (!target.junction && clamped.count(target.vertex) == 0)
            network.add_rotation_handle(name[0] == '@' ? name.substr(1) : name,
                                        target.vertex);
        }
  }

  std::unique_ptr<DrModel>
  Scene::build_dr_model() const
  {
    if (midpoint_clamp)
      throw std::invalid_argument(
        "entry \"Geometry/Clamp at first segment midpoint\": the "
        "bending-active element of dynamic relaxation clamps at a node, "
        "which is the rod's start without the option; set it to false");
    auto [network, materials] = build_network();
    std::vector<RodStiffness> stiffness;
    for (unsigned int r = 0; r < materials.size(); ++r)
      {
        const auto *elastic =
          dynamic_cast<const LinearElasticRod *>(materials[r].get());
        const RodNaturalShape shape =
          elastic != nullptr ? elastic->natural_shape() : RodNaturalShape{};
        if (elastic == nullptr || shape.curvature1 != 0 ||
            shape.curvature2 != 0 || shape.twist != 0 ||
            shape.axial_eigenstrain != 0)
          throw std::invalid_argument(
            "Solver/Method = dynamic relaxation: rod " + std::to_string(r) +
            " is not a linear elastic rod without natural shape, the only "
            "material the bending-active element has");
        stiffness.push_back(elastic->stiffness());
      }
    auto model = std::make_unique<DrModel>(std::move(network), stiffness);
    model->apply(supports_and_loads(model->network()));
    model->finalize();
    return model;
  }

  SupportsAndLoads
  Scene::supports_and_loads(const RodNetwork &network) const
  {
    SupportsAndLoads spec;
    add_clamps(network, spec);
    add_rotational_loads(network, spec);
    add_position_supports(network, spec);
    add_forces(network, spec);
    return spec;
  }

  void
  Scene::add_clamps(const RodNetwork &net, SupportsAndLoads &spec) const
  {
    for (const std::string &end :
         dealii::Utilities::split_string_list(clamped_ends, ','))
      {
        const std::string entry  = "Supports/Clamped ends";
        const std::string name   = "Clamped ends: " + end;
        const auto        target = select_rod_end(net, end, entry);
        if (const auto *rod_end = std::get_if<RodEnd>(&target))
          spec.clamps.push_back({name, *rod_end});
        else
          {
            const Junction &j = net.junctions()[std::get<unsigned int>(target)];
            if (!j.has_rotation())
              throw std::invalid_argument(
                "entry \"" + entry + "\": \"" + end +
                "\" is the pinned junction \"" + j.name +
                "\", where each rod end turns on its own; clamp the ends "
                "one by one (<rod>:start or <rod>:end)");
            spec.clamps.push_back({name, std::get<unsigned int>(target)});
          }
      }
  }

  void
  Scene::add_rotational_loads(const RodNetwork &net,
                              SupportsAndLoads &spec) const
  {
    for (const auto &[entry, text, list] :
         {std::make_tuple("Supports/Prescribed rotations",
                          &prescribed_rotations,
                          &spec.rotations),
          std::make_tuple("Loads/Moments", &moments, &spec.moments)})
      for (const auto &[name, value] : split_items(*text, entry))
        {
          const auto [axis, amount] = parse_axis_value(value, entry);
          const RotationTarget target =
            select_rotation_target(net, name, entry);
          // Rotations are given in degrees, moments in N m.
          const bool rotation = list == &spec.rotations;
          list->push_back({"entry \"" + std::string(entry) + "\": \"" + name +
                             "\"",
                           target.vertex,
                           target.junction,
                           axis,
                           rotation ? amount * M_PI / 180 : amount});
        }
  }

  void
  Scene::add_position_supports(const RodNetwork &net,
                               SupportsAndLoads &spec) const
  {
    for (const std::string &v :
         dealii::Utilities::split_string_list(pinned_vertices, ','))
      spec.fixed_components.push_back(
        {"Pinned vertices: " + v,
         select_vertex(net, v, "Supports/Pinned vertices"),
         {{true, true, true}}});
    for (const auto &[v, components] :
         split_items(fixed_components, "Supports/Fixed components"))
      spec.fixed_components.push_back(
        {"Fixed components: " + v + ": " + components,
         select_vertex(net, v, "Supports/Fixed components"),
         parse_mask(components, "Supports/Fixed components")});
    for (const auto &[v, values] :
         split_items(prescribed_displacements,
                     "Supports/Prescribed displacements"))
      {
        const std::string   entry = "Supports/Prescribed displacements";
        std::array<bool, 3> mask{{false, false, false}};
        Vector3             d = Vector3::Zero();
        std::istringstream  words(values);
        std::string         w;
        while (words >> w)
          {
            const auto eq = w.find('=');
            try
              {
                if (eq != 1 || (w[0] != 'x' && w[0] != 'y' && w[0] != 'z'))
                  throw std::invalid_argument("");
                std::size_t  used  = 0;
                const double value = std::stod(w.substr(2), &used);
                if (used != w.size() - 2 || !std::isfinite(value))
                  throw std::invalid_argument("");
                mask[w[0] - 'x'] = true;
                d[w[0] - 'x']    = value;
              }
            catch (const std::exception &)
              {
                throw std::invalid_argument("entry \"" + entry + "\": \"" + w +
                                            "\" should read x=<value>, "
                                            "y=<value> or z=<value>");
              }
          }
        spec.fixed_components.push_back(
          {"Prescribed displacements: " + v + ": " + values,
           select_vertex(net, v, entry),
           mask,
           d});
      }
  }

  void
  Scene::add_forces(const RodNetwork &net, SupportsAndLoads &spec) const
  {
    for (const auto &[v, value] :
         split_items(point_forces, "Loads/Point forces"))
      {
        const auto xyz = dealii::Utilities::split_string_list(value, ',');
        std::vector<double> f;
        try
          {
            if (xyz.size() != 3)
              throw std::invalid_argument("");
            f = dealii::Utilities::string_to_double(xyz);
          }
        catch (const std::exception &)
          {
            throw std::invalid_argument("entry \"Loads/Point forces\": \"" +
                                        value + "\" is not a force fx, fy, fz");
          }
        spec.point_forces.push_back(
          {select_vertex(net, v, "Loads/Point forces"),
           Vector3(f[0], f[1], f[2])});
      }
    // The weight is a distributed force, added with it.
    const Vector3 q = distributed_force + mass_per_length * gravity;
    if (q.norm() > 0)
      for (unsigned int r = 0; r < net.rods().size(); ++r)
        spec.distributed_forces.push_back({r, q});
  }

  std::vector<Probe>
  Scene::probes(const RodModel &model) const
  {
    return parse_probes(probe_text, model, "Output/Probes");
  }

  std::vector<Probe>
  Scene::probes(const DrModel &model) const
  {
    return parse_probes(probe_text, model, "Output/Probes");
  }
} // namespace rodnet
