#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <solvers/time/integration_scheme_registry.h>
#include <solvers/time/time_integrator.h>

namespace rodnet
{
  namespace
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;

    /// The integrator, the times and the load factor, the preload.
    void
    declare_steps(dealii::ParameterHandler &prm)
    {
      const IntegrationSchemeRegistry &schemes = integration_scheme_registry();
      prm.declare_entry("Integrator",
                        "newmark",
                        Selection(schemes.selection()),
                        schemes.listing() +
                          "All but quasi-static need the inertia of every "
                          "material in use. [-]");
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
    }

    /// The mass, the progress and energy checks, the damping.
    void
    declare_dynamics(dealii::ParameterHandler &prm)
    {
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
        "A dynamic run stops as unstable where the total energy grows beyond "
        "the work of the loads and moving supports by more than this fraction "
        "of its scale (the largest energy or work); 0: no check. [-]");
      prm.declare_entry("Rayleigh damping",
                        "0, 0",
                        dealii::Patterns::List(Double(), 2, 2, ","),
                        "alpha, beta of C = alpha M + beta K (K at the start): "
                        "damping ratio alpha/(2 omega) + beta omega/2. [1/s, "
                        "s]");
      prm.declare_entry("Spectral radius at infinity",
                        "0.8",
                        Double(),
                        "generalized alpha: amplitude a stiff mode keeps per "
                        "step. [-]");
      prm.declare_entry("Viscous drag per length",
                        "0",
                        Double(),
                        "Force -c v per length on the positions (as alpha = "
                        "c/(rho A)). [N s/m^2]");
    }
  } // namespace

  void
  TimeIntegrator::Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    declare_steps(prm);
    declare_dynamics(prm);
  }

  bool
  TimeIntegrator::Parameters::dynamic() const
  {
    return integration_scheme_registry().traits(integrator).dynamic;
  }

  void
  TimeIntegrator::Parameters::parse_parameters(
    const dealii::ParameterHandler &prm)
  {
    integrator    = prm.get("Integrator");
    time_step     = prm.get_double("Time step");
    start_time    = prm.get_double("Start time");
    end_time      = prm.get_double("End time");
    preload_time  = prm.get_double("Preload time");
    preload_steps = prm.get_integer("Preload steps");
    mass =
      prm.get("Mass") == "lumped" ? MassKind::lumped : MassKind::consistent;
    progress_interval   = prm.get_integer("Progress interval");
    energy_growth_limit = prm.get_double("Energy growth limit");
    const std::vector<std::string> rayleigh =
      dealii::Utilities::split_string_list(prm.get("Rayleigh damping"), ',');
    rayleigh_mass      = dealii::Utilities::string_to_double(rayleigh[0]);
    rayleigh_stiffness = dealii::Utilities::string_to_double(rayleigh[1]);
    viscous_drag       = prm.get_double("Viscous drag per length");
    spectral_radius_at_infinity = prm.get_double("Spectral radius at infinity");
  }
} // namespace rodnet
