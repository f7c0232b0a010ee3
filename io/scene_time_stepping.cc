#include <deal.II/base/function_parser.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <io/parsed_function.h>
#include <io/scene.h>
#include <io/scene_entries.h>
#include <solvers/time/integration_scheme_registry.h>

#include <cmath>

namespace rodnet
{
  namespace
  {
    using scene_entries::number;
    using scene_entries::time_stepping_section;

    /// The load factor of the expression of entry "Load factor" of
    /// @p prm: throws naming the entry where it is not finite.
    std::function<double(double)>
    parse_load_factor(const dealii::ParameterHandler &prm)
    {
      const std::string load_entry = time_stepping_section + "/Load factor";
      return
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
    }
  } // namespace

  void
  Scene::declare_initial_state(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry(
      "Initial displacement",
      "0; 0; 0",
      dealii::Patterns::Anything(),
      "Displacement of every vertex at the start, three ';'-separated "
      "muparser expressions of its undeformed position x, y, z, e.g. \"0; "
      "0; 0.01*x^2\"; supported components take their prescribed values. "
      "With a preload, the state the preload starts from. [m]");
    prm.declare_entry("Initial velocity",
                      "0; 0; 0",
                      dealii::Patterns::Anything(),
                      "Velocity of every vertex at the start, as \"Initial "
                      "displacement\"; zero on supported components, and "
                      "ignored after a preload, which ends at rest. [m/s]");
    prm.leave_subsection();
  }

  void
  Scene::parse_time_stepping(dealii::ParameterHandler &prm)
  {
    TimeIntegrator::Parameters &p = time_stepping;
    p.newton                      = solver.newton;
    p.relative_tolerance          = solver.relative_tolerance;
    p.min_step_fraction           = solver.min_step_fraction;
    prm.enter_subsection("Time stepping");
    p.parse_parameters(prm);
    p.load_factor = parse_load_factor(prm);
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
    const double rho = p.spectral_radius_at_infinity;
    if (!(rho >= 0 && rho <= 1))
      throw std::invalid_argument(
        entry + "Spectral radius at infinity\": " + number(rho) +
        " lies outside [0, 1]; 1 damps no frequency (as newmark), 0 removes "
        "the highest in one step");
    check_damping();
    if (!p.dynamic())
      return;
    // Throws for a material group in use without its inertia.
    inertia();
    if (integration_scheme_registry().traits(p.integrator).needs_stored_energy)
      for (const unsigned int g : rod_material)
        {
          const RodMaterial &m = *scene_materials[g].material;
          if (m.n_hinge_internal_variables() +
                m.n_segment_internal_variables() >
              0)
            throw std::invalid_argument(
              entry +
              "Integrator\": the midpoint rule conserves a stored "
              "energy, which the \"" +
              scene_materials[g].model + "\" of subsection \"" +
              scene_materials[g].subsection +
              "\" does not have (it has internal variables); use newmark or "
              "backward euler");
        }
  }

  void
  Scene::check_damping() const
  {
    const TimeIntegrator::Parameters &p = time_stepping;
    const std::string entry = "entry \"" + time_stepping_section + "/";
    if (p.rayleigh_mass < 0 || p.rayleigh_stiffness < 0)
      throw std::invalid_argument(
        entry + "Rayleigh damping\": alpha = " + number(p.rayleigh_mass) +
        " and beta = " + number(p.rayleigh_stiffness) +
        " must not be negative (a negative damping feeds energy in)");
    if (p.viscous_drag < 0)
      throw std::invalid_argument(
        entry + "Viscous drag per length\": " + number(p.viscous_drag) +
        " N s/m^2 must not be negative");
    if (p.damped() && !p.dynamic())
      throw std::invalid_argument(
        entry +
        "Integrator\": damping acts on velocities, which a quasi-static "
        "run does not have; set backward euler, newmark or midpoint, or "
        "the damping to 0");
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
} // namespace rodnet
