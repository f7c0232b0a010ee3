#include <deal.II/base/patterns.h>

#include <io/entry_tree.h>
#include <io/scene.h>
#include <io/scene_entries.h>
#include <materials/rod_material.h>

namespace rodnet
{
  namespace
  {
    /// Material subsections: "Material" for every rod, and optional ones
    /// for the material groups of a network.
    constexpr unsigned int n_material_groups = 4;

    std::string
    material_section(const unsigned int group)
    {
      return group == 0 ? "Material" :
                          "Material of group " + std::to_string(group);
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

    /// Declares "Density", "Model" and a subsection per registered
    /// material in the current (material) subsection.
    void
    declare_material(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Density",
        "0",
        dealii::Patterns::Double(0),
        "Mass density rho, with the cross-section of \"Stiffness input = "
        "section\": the weight rho A g per length under Loads/Gravity, and "
        "for time stepping rho A per length and rho (I1 + I2) of twist "
        "inertia; 0: not given. [kg/m^3]");
      prm.declare_entry(
        "Inextensible",
        "false",
        dealii::Patterns::Bool(),
        "Keep every segment's length exactly, by a Lagrange multiplier per "
        "segment (Korner et al. eq. 4.4), instead of the stretching energy. "
        "For Newton steps (full step or backtracking) and continuation; the "
        "multipliers are written as axial_force. [-]");
      const MaterialRegistry        &registry = MaterialRegistry::instance();
      const std::vector<std::string> names    = registry.names();
      std::string                    help     = "Constitutive law of the rods:";
      for (const std::string &n : names)
        help += " \"" + n + "\": " + registry.description(n);
      prm.declare_entry("Model",
                        names.front(),
                        dealii::Patterns::Selection(
                          scene_entries::join(names, "|")),
                        help);
      for (const std::string &n : names)
        {
          prm.enter_subsection(n);
          registry.create(n)->declare_parameters(prm);
          prm.leave_subsection();
        }
    }
  } // namespace

  void
  Scene::declare_materials(dealii::ParameterHandler &prm)
  {
    for (unsigned int group = 0; group < n_material_groups; ++group)
      {
        prm.enter_subsection(material_section(group));
        if (group > 0)
          prm.declare_entry("Use",
                            "false",
                            dealii::Patterns::Bool(),
                            "Give the beams of material group " +
                              std::to_string(group) +
                              " of a network this material instead of "
                              "that of subsection Material. [-]");
        declare_material(prm);
        prm.leave_subsection();
      }
  }

  Scene::MaterialGroup
  Scene::parse_material(dealii::ParameterHandler &prm,
                        const EntryNode          &entries,
                        const unsigned int        group)
  {
    MaterialGroup g;
    g.subsection   = material_section(group);
    g.model        = prm.get("Model");
    g.density      = prm.get_double("Density");
    g.inextensible = prm.get_bool("Inextensible");
    if (!sets_an_entry(*entries.find(g.subsection)->find(g.model)))
      throw std::invalid_argument(
        "subsection \"" + g.subsection + "/" + g.model +
        "\" sets no entry, so the rods have no stiffness: give a "
        "Young's modulus and a cross section, or the rigidities "
        "(rodnet-run --help lists the entries; scenes/elastica.prm "
        "is an example)");
    auto material = MaterialRegistry::instance().create(g.model);
    prm.enter_subsection(g.model);
    // The material's message names its entry; this adds which material
    // subsection.
    try
      {
        material->parse_parameters(prm);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw std::invalid_argument("subsection \"" + g.subsection +
                                    "\": " + error_message(e));
      }
    prm.leave_subsection();
    g.section  = material->cross_section();
    g.material = std::move(material);
    return g;
  }

  void
  Scene::parse_materials(dealii::ParameterHandler &prm,
                         const EntryNode          &entries)
  {
    for (unsigned int group = 0; group < n_material_groups; ++group)
      {
        prm.enter_subsection(material_section(group));
        if (group == 0 || prm.get_bool("Use"))
          material_groups.push_back(parse_material(prm, entries, group));
        else
          material_groups.push_back(material_groups.front());
        prm.leave_subsection();
      }
  }
} // namespace rodnet
