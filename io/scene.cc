#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <core/vertex_selector.h>
#include <io/entry_numbers.h>
#include <io/entry_tree.h>
#include <io/run_limits.h>
#include <io/scene.h>
#include <io/scene_entries.h>
#include <io/scene_families.h>
#include <io/solution_methods.h>
#include <io/substrate.h>
#include <io/time_drive.h>
#include <io/unread_geometry_entries.h>
#include <materials/rod_material.h>
#include <solvers/time/integration_scheme_registry.h>

#include <cmath>
#include <families/body_weight_family.h>
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
    using scene_entries::get_vector;
    using scene_entries::number;
    using scene_entries::time_stepping_section;
    using scene_entries::vector_pattern;

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

    /// The components of a prescribed displacement that an item gives and
    /// their values.
    struct DisplacementComponents
    {
      std::array<bool, 3> mask{{false, false, false}};
      Vector3             value = Vector3::Zero();
    };

    /// Parses "x=<dx> y=<dy> ..." of @p entry.
    DisplacementComponents
    parse_displacement(const std::string &text, const std::string &entry)
    {
      DisplacementComponents d;
      std::istringstream     words(text);
      std::string            w;
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
              d.mask[w[0] - 'x']  = true;
              d.value[w[0] - 'x'] = value;
            }
          catch (const std::exception &)
            {
              throw std::invalid_argument("entry \"" + entry + "\": \"" + w +
                                          "\" should read x=<value>, "
                                          "y=<value> or z=<value>");
            }
        }
      return d;
    }

    /// Parses "fx, fy, fz".
    Vector3
    parse_force(const std::string &text, const std::string &entry)
    {
      const auto xyz = dealii::Utilities::split_string_list(text, ',');
      try
        {
          if (xyz.size() != 3)
            throw std::invalid_argument("");
          const std::vector<double> f =
            dealii::Utilities::string_to_double(xyz);
          return Vector3(f[0], f[1], f[2]);
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                      "\" is not a force fx, fy, fz");
        }
    }

    /// Splits "vertex: rest" items of a ';'-separated list.
    std::vector<std::pair<std::string, std::string>>
    split_items(const std::string &text, const std::string &entry)
    {
      std::vector<std::pair<std::string, std::string>> items;
      for (const std::string &item :
           dealii::Utilities::split_string_list(text, ';'))
        {
          // The vertex may itself contain "rod:", so split at the last ':'
          // before a function of time, whose conditionals (c ? a : b) have
          // their own.
          const auto colon = item.rfind(':', in_time_offset(item));
          if (colon == std::string::npos)
            throw std::invalid_argument("entry \"" + entry + "\": \"" + item +
                                        "\" should read \"<vertex>: ...\"");
          items.emplace_back(dealii::Utilities::trim(item.substr(0, colon)),
                             dealii::Utilities::trim(item.substr(colon + 1)));
        }
      return items;
    }

    /// The entries "Point forces", "Moments" and "Distributed force" of
    /// the subsection Loads.
    void
    declare_forces_and_moments(dealii::ParameterHandler &prm)
    {
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
                        vector_pattern(),
                        "Dead force per unit undeformed length on every rod at "
                        "load factor 1. [N/m]");
    }

    /// The entries of the subsection Loads that give the weight: "Gravity",
    /// "Mass per length" and "Rigid bodies".
    void
    declare_weight(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Gravity",
                        "0, 0, 0",
                        vector_pattern(),
                        "Gravitational acceleration; the weight per length of "
                        "a rod is its material's \"Mass per length\" (or "
                        "rho A) times this. [m/s^2]");
      prm.declare_entry("Mass per length",
                        "0",
                        Double(0),
                        "The \"Mass per length\" of materials giving none "
                        "(one given must agree); 0: not given. [kg/m]");
      prm.declare_entry("Rigid bodies",
                        "",
                        Anything(),
                        "\"<vertex>: mass <m> [inertia <j>|<J_t>,<J_p>|"
                        "<J_xx>,<J_yy>,<J_zz>[,<J_yz>,<J_zx>,<J_xy>]] "
                        "[offset <c>|centre <dx>,<dy>,<dz>]; ...\" "
                        "(doc/dynamics.md). [kg, kg m^2, m]");
    }

    /// The subsection Imperfections of Loads.
    void
    declare_imperfections(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Imperfections");
      prm.declare_entry("Point forces",
                        "",
                        Anything(),
                        "Small forces, as Loads/Point forces. [N]");
      prm.declare_entry("Moments",
                        "",
                        Anything(),
                        "Small moments, as Loads/Moments. [N m]");
      prm.declare_entry("Magnitude",
                        "held",
                        dealii::Patterns::Selection("held|ramped"),
                        "held: full from the first step on; ramped: scaled by "
                        "the load factor. [-]");
      prm.leave_subsection();
    }

    /// The junctions of @p network that tie rod ends (not the rotation
    /// handles), for "Pinned vertices = junctions"; throws naming the
    /// entry where there are none.
    std::vector<unsigned int>
    rod_end_junctions(const RodNetwork &network)
    {
      std::vector<unsigned int> junctions;
      for (unsigned int j = 0; j < network.junctions().size(); ++j)
        if (!network.junctions()[j].ends.empty())
          junctions.push_back(j);
      if (junctions.empty())
        throw std::invalid_argument(
          "entry \"Supports/Pinned vertices\": \"junctions\" pins every "
          "junction, but the scene has none (" +
          std::to_string(network.rods().size()) +
          (network.rods().size() == 1 ? " rod" : " rods") +
          " and no junction); name the vertices to pin, e.g. \"start, end\"");
      return junctions;
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
    declare_geometry(prm);
    declare_materials(prm);
    declare_supports(prm);
    Substrate::declare_parameters(prm);
    declare_loads(prm);
    declare_solver(prm);
    declare_output(prm);
    declare_element_family_parameters(prm);
  }

  void
  Scene::declare_supports(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Supports");
    prm.declare_entry("Clamped ends",
                      "",
                      Anything(),
                      "Rod ends clamped by holding their end segment (two "
                      "vertices and the twist; Korner et al. 5a), e.g. "
                      "\"start\" or \"0:start, 1:end\", or \"@name\" of a "
                      "free network end or of a junction (held whole). A "
                      "clamp moves rigidly with the prescribed "
                      "displacement and rotation of its end vertex. [-]");
    prm.declare_entry("Pinned vertices",
                      "",
                      Anything(),
                      "Vertices whose position is fixed, e.g. \"end, 0:mid\". "
                      "Vertices are [rod:]start|end|mid|<index>; "
                      "\"junctions\": every junction, its rotation free. [-]");
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
      "<ax>,<ay>,<az> <angle> [in time <f(t)>]; ...\" (degrees; in time "
      "stepping angle x f(t)), where is a clamped end (turned about its end "
      "vertex), a junction or any vertex (a rotation handle there). [deg]");
    prm.declare_entry("Prescribed displacements",
                      "",
                      Anything(),
                      "Displacements at load factor 1, ramped with it (or "
                      "x f(t)): \"<vertex>: x=<dx> y=<dy> [in time <f(t)>]; "
                      "...\". [m]");
    prm.leave_subsection();
  }

  void
  Scene::declare_loads(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Steps",
      "10",
      Integer(1),
      "Number of equal load steps from load factor 0 to 1, at most "
      "100000; every load and prescribed displacement is ramped. [-]");
    declare_forces_and_moments(prm);
    declare_weight(prm);
    prm.declare_entry("Ramped natural shape",
                      "",
                      Anything(),
                      "Parts of the natural shape that the load factor "
                      "scales as it scales the loads: \"curvature, twist, "
                      "eigenstrain\" or some, then \": <rod>, ...\" or all "
                      "rods. [-]");
    prm.declare_entry("Fixed loads",
                      "false",
                      dealii::Patterns::Bool(),
                      "Forces and moments at full value at every load "
                      "factor, which ramps only the rest. [-]");
    declare_imperfections(prm);
    prm.leave_subsection();
  }

  void
  Scene::declare_solver(dealii::ParameterHandler &prm)
  {
    std::vector<std::string> names;
    std::string              help;
    for (const SolutionMethodEntry &m : solution_methods())
      {
        names.push_back(m.name);
        help += m.name + ": " + m.description + " ";
      }
    prm.enter_subsection("Solver");
    prm.declare_entry("Method",
                      names.front(),
                      dealii::Patterns::Selection(
                        scene_entries::join(names, "|")),
                      help + "[-]");
    for (const SolutionMethodEntry &m : solution_methods())
      m.declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Solver");
    declare_initial_state(prm);
    prm.leave_subsection();
  }

  void
  Scene::declare_output(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
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
                        probe_kinds_description() + ". [-]");
    prm.declare_entry("Plot",
                      "true",
                      Bool(),
                      "Plot the probes against the load factor (the time "
                      "for time stepping) into probes.png, and draw "
                      "picture.png (both need gnuplot). [-]");
    prm.declare_entry("Mode shapes",
                      "0",
                      Integer(0, 100),
                      "Newton and continuation: the n lowest eigenvalues "
                      "of the tangent at the last equilibrium into "
                      "modes.csv, the modes into modes-NNNNN.vtu. [-]");
    PictureOptions::declare_entries(prm);
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
    const bool        static_checks =
      solution_method == "newton" || solution_method == "continuation" ||
      (solution_method == "time stepping" &&
       !integration_scheme_registry()
          .traits(prm.get({"Solver", "Time stepping"}, "Integrator"))
          .dynamic);
    const bool   time_stepping = solution_method == "time stepping";
    const double bytes_per_dof =
      memory_per_dof(static_checks,
                     time_stepping,
                     prm.get_bool({"Output"}, "Write VTU"));
    const double bytes_per_factor_entry =
      memory_per_factor_entry(static_checks, time_stepping);
    // What cannot fit in memory is refused before it is generated.
    const SizeCheck check_size =
      [bytes_per_dof, bytes_per_factor_entry](ProblemSize        size,
                                              const std::string &entry) {
        size.bytes_per_dof          = bytes_per_dof;
        size.bytes_per_factor_entry = bytes_per_factor_entry;
        check_memory(size, available_memory(), entry);
        return size;
      };

    refuse_unread_geometry_entries(*entries.find("Geometry"),
                                   prm.get({"Geometry"}, "Generator"));
    parse_geometry(prm, scene_directory, check_size);
    parse_materials(prm, entries);
    parse_rod_groups(prm, entries);
    // The groups give segments; the materials say which rods carry
    // constraints with DoFs of their own.
    model_size                 = geometry_size();
    model_size.constraint_dofs = constraint_dofs();
    model_size                 = check_size(model_size, model_size_entry);
    parse_supports(prm);
    substrate = Substrate::parse(prm);
    parse_loads(prm);
    if (gravity.norm() > 0)
      rod_masses = masses_per_length();
    parse_solver(prm);
    parse_output(prm);
    family_requests = parse_element_family_requests(prm);
    check_run_length();
  }

  void
  Scene::parse_supports(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Supports");
    clamped_ends             = prm.get("Clamped ends");
    pinned_vertices          = prm.get("Pinned vertices");
    fixed_components         = prm.get("Fixed components");
    prescribed_displacements = prm.get("Prescribed displacements");
    prescribed_rotations     = prm.get("Prescribed rotations");
    prm.leave_subsection();
  }

  void
  Scene::parse_loads(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    solver.n_steps    = prm.get_integer("Steps");
    point_forces      = prm.get("Point forces");
    moments           = prm.get("Moments");
    distributed_force = get_vector(prm, "Distributed force");
    gravity           = get_vector(prm, "Gravity");
    mass_per_length   = prm.get_double("Mass per length");
    for (const auto &[place, text] :
         split_items(prm.get("Rigid bodies"), "Loads/Rigid bodies"))
      rigid_body_items.push_back(
        parse_rigid_body_item(place, text, "Loads/Rigid bodies"));
    natural_shape_ramp =
      parse_natural_shape_ramp(prm.get("Ramped natural shape"));
    fixed_loads = prm.get_bool("Fixed loads");
    if (fixed_loads && !moves_shape_or_support(false))
      throw std::invalid_argument(
        "entry \"Loads/Fixed loads\": with the loads fixed the load factor "
        "has nothing to ramp; give Loads/Ramped natural shape, a ramped "
        "activation field (Group <name>/Natural curvature, ...), "
        "Supports/Prescribed displacements or rotations without \"in "
        "time\" (an item \"in time\" follows its own function of time) or "
        "a strain of the Substrate");
    prm.enter_subsection("Imperfections");
    imperfection_forces  = prm.get("Point forces");
    imperfection_moments = prm.get("Moments");
    imperfection_ramp =
      prm.get("Magnitude") == "held" ? LoadRamp::held : LoadRamp::ramped;
    prm.leave_subsection();
    prm.leave_subsection();
    check_imperfection_ramp();
  }

  bool
  Scene::moves_shape_or_support(const bool in_time_too) const
  {
    const auto moves = [in_time_too](const std::string &items) {
      for (const std::string &item :
           dealii::Utilities::split_string_list(items, ';'))
        if (in_time_too || !follows_time_function(item))
          return true;
      return false;
    };
    return natural_shape_ramp || ramps_activation(in_time_too) || substrate.moves() ||
           moves(prescribed_displacements) || moves(prescribed_rotations);
  }

  void
  Scene::check_imperfection_ramp() const
  {
    const std::string entry = "entry \"Loads/Imperfections/Magnitude\": ";
    if (imperfection_forces.empty() && imperfection_moments.empty())
      return;
    if (imperfection_ramp == LoadRamp::ramped && fixed_loads)
      throw std::invalid_argument(
        entry + "\"ramped\" contradicts Loads/Fixed loads = true, which "
                "holds every load at its full value; set Magnitude = held");
    const bool ramped_loads =
      !fixed_loads && (!point_forces.empty() || !moments.empty() ||
                       distributed_force.norm() > 0 || gravity.norm() > 0);
    // A support moving in time moves something the imperfections perturb.
    if (imperfection_ramp == LoadRamp::held && !ramped_loads &&
        !moves_shape_or_support(true))
      throw std::invalid_argument(
        entry + "the imperfections are held at their full value and the "
                "load factor has nothing else to ramp; give the loads, "
                "Loads/Ramped natural shape or a prescribed displacement or "
                "rotation that they perturb, or set Magnitude = ramped");
  }

  void
  Scene::parse_solver(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    solver.parse_parameters(prm);
    method = solution_method(prm.get("Method")).method;
    parse_time_stepping(prm);
    check_activation_drives();
    prm.enter_subsection("Dynamic relaxation");
    relaxation.parse_parameters(prm);
    relaxation.n_steps = solver.n_steps;
    prm.leave_subsection();
    prm.enter_subsection("Continuation");
    continuation.parse_parameters(prm);
    continuation.relative_tolerance = solver.relative_tolerance;
    continuation.linear_solver      = solver.newton.linear_solver;
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void
  Scene::parse_output(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    write_vtu        = prm.get_bool("Write VTU");
    vtu_interval     = prm.get_integer("VTU interval");
    probe_text       = prm.get("Probes");
    plot             = prm.get_bool("Plot");
    mode_shapes      = prm.get_integer("Mode shapes");
    picture.parse_entries(prm);
    prm.leave_subsection();
    picture.resolve_groups(groups_of_rods());
    if (mode_shapes > 0 && method != SolutionMethod::newton &&
        method != SolutionMethod::continuation)
      throw std::invalid_argument(
        "entry \"Output/Mode shapes\": the modes are those of the static "
        "tangent at an equilibrium, which only \"Solver/Method = newton\" "
        "and \"continuation\" find; set it to 0 for this method");
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
    if (method == SolutionMethod::continuation)
      return continuation.max_steps;
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

  std::vector<std::array<double, 2>>
  Scene::fiber_distances() const
  {
    // Twice the radius of gyration about each axis: the radius of a
    // circle, 1.15 times the half depth of a rectangle (on the safe side).
    std::vector<std::array<double, 2>> result;
    for (const unsigned int g : rod_material)
      {
        const std::optional<CrossSection> &section = scene_materials[g].section;
        if (section)
          result.push_back({{2 * std::sqrt(section->I1 / section->area),
                             2 * std::sqrt(section->I2 / section->area)}});
        else
          result.push_back({{std::nan(""), std::nan("")}});
      }
    return result;
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
          {
            network->add_rod(rod_points[r],
                             rod_closed[r],
                             director_hint,
                             hinge_kernel,
                             natural_shape);
            if (rod_closed[r])
              network->set_frame_half_turns(r, frame_half_turns);
          }
        network->create_triangulation();
      }
    std::vector<std::shared_ptr<const RodMaterial>> materials;
    const std::vector<unsigned int>                &groups = rod_material;
    for (unsigned int r = 0; r < groups.size(); ++r)
      {
        materials.push_back(scene_materials[groups[r]].material);
        network->set_inextensible(r, scene_materials[groups[r]].inextensible);
      }
    return {std::move(network), materials};
  }

  std::unique_ptr<RodModel>
  Scene::build_model() const
  {
    auto [network, materials] = build_network();
    add_rotation_handles(*network);
    auto model =
      std::make_unique<RodModel>(std::move(network), materials, ghost_spin);
    for (const RequestedFamily &family : family_requests)
      model->add_element_family(family.request->create(*model));
    model->apply(supports_and_loads(model->network()));
    for (const RigidBodyItem &item : rigid_body_items)
      model->add_rigid_body(place_rigid_body(model->network(), item));
    if (auto weight = body_weight_family(*model, gravity))
      model->add_element_family(std::move(weight));
    if (natural_shape_ramp)
      ramp_natural_shape(*model);
    add_activation_fields(*model);
    if (fixed_loads)
      model->fix_loads();
    model->finalize();
    if (midpoint_clamp)
      check_midpoint_clamps(*model);
    return model;
  }

  void
  Scene::ramp_natural_shape(RodModel &model) const
  {
    std::vector<unsigned int> rods = natural_shape_ramp->rods;
    if (rods.empty())
      for (unsigned int r = 0; r < model.network().rods().size(); ++r)
        rods.push_back(r);
    try
      {
        model.ramp_natural_shape(natural_shape_ramp->parts, rods);
      }
    catch (const std::invalid_argument &e)
      {
        throw std::invalid_argument("entry \"" + natural_shape_ramp_entry +
                                    "\": " + e.what());
      }
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
          std::make_pair("Loads/Moments", moments),
          std::make_pair("Loads/Imperfections/Moments", imperfection_moments)})
      for (const auto &[name, value] : split_items(text, entry))
        {
          const RotationTarget target =
            select_rotation_target(network, name, entry);
          if (!target.junction && clamped.count(target.vertex) == 0)
            network.add_rotation_handle(name[0] == '@' ? name.substr(1) : name,
                                        target.vertex);
        }
    // A rotary inertia turns with a junction's rotation.
    for (const RigidBodyItem &item : rigid_body_items)
      if (const auto v = rigid_body_handle_vertex(network, item);
          v && clamped.count(*v) == 0)
        network.add_rotation_handle(item.place[0] == '@' ?
                                      item.place.substr(1) :
                                      item.place,
                                    *v);
  }

  void
  Scene::refuse_for_dr_element() const
  {
    if (midpoint_clamp)
      throw std::invalid_argument(
        "entry \"Geometry/Clamp at first segment midpoint\": the "
        "bending-active element of dynamic relaxation clamps at a node, "
        "which is the rod's start without the option; set it to false");
    if (!family_requests.empty())
      throw std::invalid_argument(
        "section \"" + family_requests.front().name +
        "\": the bending-active element of dynamic relaxation has no "
        "element families; use Solver/Method = newton");
    if (natural_shape_ramp)
      throw std::invalid_argument(
        "entry \"" + natural_shape_ramp_entry +
        "\": the bending-active element of dynamic relaxation has no "
        "natural shape; use Solver/Method = newton or continuation");
    for (const RigidBodyItem &item : rigid_body_items)
      if (item.centre_offset != Vector3::Zero())
        throw std::invalid_argument(
          item.where + ": the bending-active element of dynamic relaxation "
                       "has no junction rotation to carry a centre off the "
                       "vertex; use Solver/Method = newton or continuation");
    for (const std::vector<ActivationItem> &items : rod_activation)
      if (!items.empty())
        throw std::invalid_argument(
          "entry \"" + items.front().entry +
          "\": the bending-active element of dynamic relaxation has no "
          "natural shape; use Solver/Method = newton or continuation");
    for (const SceneMaterial &group : scene_materials)
      if (group.inextensible)
        throw std::invalid_argument(
          "entry \"" + group.subsection +
          "/Inextensible\": the "
          "bending-active element of dynamic relaxation has no constraints; "
          "use Solver/Method = newton or continuation");
  }

  void
  Scene::refuse_for_dr_loading() const
  {
    if (fixed_loads)
      throw std::invalid_argument(
        "entry \"Loads/Fixed loads\": dynamic relaxation ramps its loads "
        "only; use Solver/Method = newton or continuation");
    if (imperfection_ramp == LoadRamp::held &&
        !(imperfection_forces.empty() && imperfection_moments.empty()))
      throw std::invalid_argument(
        "entry \"Loads/Imperfections/Magnitude\": dynamic relaxation ramps "
        "its loads only, and cannot hold the imperfections; set Magnitude = "
        "ramped or use Solver/Method = newton or continuation");
  }

  std::unique_ptr<DrModel>
  Scene::build_dr_model() const
  {
    refuse_for_dr_element();
    refuse_for_dr_loading();
    auto [network, materials] = build_network();
    std::vector<RodStiffness> stiffness;
    for (unsigned int r = 0; r < materials.size(); ++r)
      {
        const std::optional<RodStiffness> rigidities =
          materials[r]->straight_linear_elastic_stiffness();
        if (!rigidities)
          throw std::invalid_argument(
            "Solver/Method = dynamic relaxation: rod " + std::to_string(r) +
            " is not a linear elastic rod without natural shape, the only "
            "material the bending-active element has");
        stiffness.push_back(*rigidities);
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
    substrate.add_sites(network, spec);
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
    for (const auto &[entry, text, list, ramp] :
         {std::make_tuple("Supports/Prescribed rotations",
                          &prescribed_rotations,
                          &spec.rotations,
                          LoadRamp::ramped),
          std::make_tuple("Loads/Moments",
                          &moments,
                          &spec.moments,
                          LoadRamp::ramped),
          std::make_tuple("Loads/Imperfections/Moments",
                          &imperfection_moments,
                          &spec.moments,
                          imperfection_ramp)})
      for (const auto &[name, value] : split_items(*text, entry))
        {
          // Rotations are given in degrees, moments in N m; rotations may
          // follow a function of time.
          const bool         rotation = list == &spec.rotations;
          std::string        rest     = value;
          const TimeFunction in_time =
            rotation ? support_in_time(entry, name, value, rest) :
                       TimeFunction();
          const auto [axis, amount] = parse_axis_value(rest, entry);
          const RotationTarget target =
            select_rotation_target(net, name, entry);
          list->push_back(
            {"entry \"" + std::string(entry) + "\": \"" + name + "\"",
             target.vertex,
             target.junction,
             axis,
             rotation ? amount * M_PI / 180 : amount,
             ramp,
             in_time});
        }
  }

  TimeFunction
  Scene::support_in_time(const std::string &entry,
                         const std::string &name,
                         const std::string &value,
                         std::string       &rest) const
  {
    const std::string context =
      "entry \"" + entry + "\", item \"" + name + ": " + value + "\": ";
    std::vector<std::string> words =
      dealii::Utilities::split_string_list(value, ' ');
    const TimeFunction in_time = read_in_time(words, entry, context);
    rest.clear();
    for (const std::string &w : words)
      rest += (rest.empty() ? "" : " ") + w;
    if (in_time.given())
      check_time_function(*in_time.of_time,
                          context + "a function of time moves a support",
                          "let the load factor move it (without \"in time\")");
    return in_time;
  }

  void
  Scene::add_position_supports(const RodNetwork &net,
                               SupportsAndLoads &spec) const
  {
    for (const std::string &v :
         dealii::Utilities::split_string_list(pinned_vertices, ','))
      if (v == "junctions")
        for (const unsigned int j : rod_end_junctions(net))
          spec.fixed_components.push_back(
            {"Pinned vertices: @" + net.junctions()[j].name,
             net.junctions()[j].vertex,
             {{true, true, true}}});
      else
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
        const std::string  entry = "Supports/Prescribed displacements";
        std::string        rest;
        const TimeFunction in_time = support_in_time(entry, v, values, rest);
        const DisplacementComponents d = parse_displacement(rest, entry);
        spec.fixed_components.push_back(
          {"Prescribed displacements: " + v + ": " + values,
           select_vertex(net, v, entry),
           d.mask,
           d.value,
           in_time});
      }
  }

  void
  Scene::add_forces(const RodNetwork &net, SupportsAndLoads &spec) const
  {
    for (const auto &[entry, text, ramp] :
         {std::make_tuple("Loads/Point forces",
                          &point_forces,
                          LoadRamp::ramped),
          std::make_tuple("Loads/Imperfections/Point forces",
                          &imperfection_forces,
                          imperfection_ramp)})
      for (const auto &[v, value] : split_items(*text, entry))
        spec.point_forces.push_back(
          {select_vertex(net, v, entry), parse_force(value, entry), ramp});
    // The weight is a distributed force, added with it.
    for (unsigned int r = 0; r < net.rods().size(); ++r)
      {
        const Vector3 q = distributed_force +
                          (rod_masses.empty() ? 0. : rod_masses[r]) * gravity;
        if (q.norm() > 0)
          spec.distributed_forces.push_back({r, q});
      }
    // The bodies' weight acts at their centres (rigid_body_weight()).
    if (gravity.norm() > 0)
      for (const RigidBodyItem &item : rigid_body_items)
        for (const auto &[vertex, force] :
             rigid_body_weight(net, place_rigid_body(net, item), gravity))
          spec.point_forces.push_back({vertex, force, LoadRamp::ramped});
  }

  double
  Scene::mass_per_length_of(const SceneMaterial &group) const
  {
    if (const std::optional<double> rho_A = rod_mass_per_length(group))
      return *rho_A;
    const std::string density_entry = "\"" + group.subsection + "/Density\"";
    if (group.density > 0)
      throw std::invalid_argument(
        "entry \"Loads/Gravity\": the weight of the rods of \"" +
        group.subsection + "\" is " + density_entry +
        " times the section's area, but \"" + group.subsection + "/" +
        group.model +
        "\" gives its rigidities directly, without a section; give "
        "\"Loads/Mass per length\" or \"Stiffness input = section\"");
    throw std::invalid_argument(
      "entry \"Loads/Gravity\": the rods of \"" + group.subsection +
      "\" have no mass to weigh; give " + density_entry +
      " (with a cross-section) or \"Loads/Mass per length\"");
  }

  std::vector<double>
  Scene::masses_per_length() const
  {
    std::vector<double> masses;
    for (const unsigned int g : rod_material)
      masses.push_back(mass_per_length_of(scene_materials[g]));
    return masses;
  }

  ProbeList
  Scene::probes(const ModelBase &model) const
  {
    ProbeList probes = parse_probes(probe_text, model, "Output/Probes");
    // Only a dynamic integrator has velocities and a mass matrix.
    const Probe *motion = first_motion_probe(probes);
    if (motion != nullptr &&
        !(method == SolutionMethod::time_stepping && time_stepping.dynamic()))
      throw std::invalid_argument(
        "entry \"Output/Probes\", probe \"" + motion->name() +
        "\": energies and momenta of the motion need dynamic time stepping "
        "(Solver/Method = time stepping with an Integrator other than "
        "quasi-static)");
    return probes;
  }
} // namespace rodnet
