#include <deal.II/base/patterns.h>

#include <base/nearest_names.h>
#include <io/entry_tree.h>
#include <io/rod_groups.h>
#include <io/scene.h>
#include <io/scene_entries.h>
#include <materials/rod_material.h>

#include <cmath>
#include <regex>
#include <set>

namespace rodnet
{
  namespace
  {
    /// Material subsections: "Material" for every rod, and "Material
    /// <name>" for the rods whose group names it.
    const std::string &material_prefix = material_subsection_prefix;

    /// Refuses the numbered material groups of earlier scenes ("Material of
    /// group 1" with "Use = true").
    void
    refuse_numbered_group(const std::string &title)
    {
      static const std::regex numbered("Material of group ([0-9]+)");
      std::smatch             match;
      if (std::regex_match(title, match, numbered))
        throw std::invalid_argument(
          "subsection \"" + title +
          "\": material groups are named now: write the material as "
          "\"subsection Material <name>\" (without \"Use\") and give it to "
          "the rods of group " +
          match[1].str() + " with \"subsection Group " + match[1].str() +
          "\", \"set Material = <name>\" (doc/networks.md)");
    }

    /// "Rotary inertia per length" of the material subsection @p title:
    /// empty for "auto", else a number that must be finite and not negative
    /// (refused naming the entry).
    std::optional<double>
    rotary_inertia_entry(const dealii::ParameterHandler &prm,
                         const std::string              &title)
    {
      const std::string text = prm.get("Rotary inertia per length");
      if (text == "auto")
        return std::nullopt;
      double      value = -1;
      std::size_t used  = 0;
      try
        {
          value = std::stod(text, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      const bool whole =
        used > 0 && text.find_first_not_of(" \t", used) == std::string::npos;
      if (!whole || !std::isfinite(value) || value < 0)
        throw std::invalid_argument(
          "entry \"" + title + "/Rotary inertia per length\": \"" + text +
          "\" is not a rotary inertia: give a finite number >= 0 (kg m; 0 "
          "for none) or auto (half the twist inertia per length)");
      return value;
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
        "Mass density rho: with a section, the default of the two entries "
        "below; 0: not given. [kg/m^3]");
      prm.declare_entry("Mass per length",
                        "0",
                        dealii::Patterns::Double(0),
                        "rho A, weighed by Loads/Gravity and accelerated in "
                        "time stepping; 0: Density times the section's "
                        "area. [kg/m]");
      prm.declare_entry("Twist inertia per length",
                        "0",
                        dealii::Patterns::Double(0),
                        "Mass moment of the section about the centreline, "
                        "for time stepping (rho J for a circle); 0: Density "
                        "times I1 + I2. [kg m]");
      prm.declare_entry("Rotary inertia per length",
                        "auto",
                        dealii::Patterns::Anything(),
                        "rho (I1 + I2) / 2 of the sections about their bending "
                        "axes; auto: half the twist inertia; 0: none. [kg m]");
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
    prm.enter_subsection("Material");
    declare_material(prm);
    prm.leave_subsection();
  }

  void
  Scene::declare_named_subsections(dealii::ParameterHandler       &prm,
                                   const std::vector<std::string> &titles)
  {
    for (const std::string &title :
         std::set<std::string>(titles.begin(), titles.end()))
      {
        refuse_numbered_group(title);
        const bool material = name_in_title(title, material_prefix).has_value();
        if (!material && !name_in_title(title, group_subsection_prefix))
          continue;
        prm.enter_subsection(title);
        if (material)
          declare_material(prm);
        else
          declare_rod_group(prm);
        prm.leave_subsection();
      }
  }

  Scene::SceneMaterial
  Scene::parse_material(dealii::ParameterHandler &prm,
                        const EntryNode          &entries,
                        const std::string        &title)
  {
    SceneMaterial g;
    g.subsection                = title;
    g.model                     = prm.get("Model");
    g.density                   = prm.get_double("Density");
    g.mass_per_length           = prm.get_double("Mass per length");
    g.twist_inertia_per_length  = prm.get_double("Twist inertia per length");
    g.rotary_inertia_per_length = rotary_inertia_entry(prm, title);
    g.inextensible              = prm.get_bool("Inextensible");
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
    for (const EntryNode &section : entries.children)
      if (section.name == "Material" ||
          name_in_title(section.name, material_prefix))
        {
          prm.enter_subsection(section.name);
          scene_materials.push_back(parse_material(prm, entries, section.name));
          prm.leave_subsection();
        }
  }

  unsigned int
  Scene::material_index(const RodSettings &rod) const
  {
    if (rod.material.empty())
      return 0;
    for (unsigned int m = 0; m < scene_materials.size(); ++m)
      if (scene_materials[m].subsection == material_prefix + rod.material)
        return m;
    std::vector<std::string> names;
    for (const SceneMaterial &material : scene_materials)
      if (const auto name = name_in_title(material.subsection, material_prefix))
        names.push_back(*name);
    throw std::invalid_argument(
      "entry \"" + group_subsection_prefix + rod.material_group +
      "/Material\": the scene has no subsection \"Material " + rod.material +
      "\"" +
      (names.empty() ?
         std::string("; it names none") :
         "; it names " + quoted_list(nearest_names(names, rod.material, 8))));
  }

  // The inertia of the material groups: stated per group ("Mass per
  // length", "Twist inertia per length"), independently of the stiffness,
  // or derived from the group's Density and cross-section (doc/dynamics.md,
  // "Stating the inertia").
  namespace
  {
    using scene_entries::number;

    /// Whether @p a and @p b differ by more than 1e-6 relative to @p b.
    bool
    differ_relatively(const double a, const double b)
    {
      return std::abs(a - b) > 1e-6 * b;
    }

    /**
     * The value @p stated in the entry @p entry of the material subsection
     * @p subsection (0: not given), else @p density times the property
     * @p of_section of the section (empty without a density or a section).
     * Throws naming the entry where both are given and differ: one of them
     * would be silently ignored.
     */
    std::optional<double>
    stated_or_derived(const double                stated,
                      const double                density,
                      const std::optional<double> of_section,
                      const std::string          &subsection,
                      const std::string          &entry,
                      const std::string          &unit,
                      const std::string          &property)
    {
      std::optional<double> derived;
      if (density > 0 && of_section)
        derived = density * *of_section;
      if (stated > 0 && derived && differ_relatively(stated, *derived))
        throw std::invalid_argument(
          "entry \"" + subsection + "/" + entry + "\": " + number(stated) +
          " " + unit + " differs from the " + number(*derived) + " " + unit +
          " of \"" + subsection + "/Density\" times the section's " + property +
          "; give one of them");
      if (stated > 0)
        return stated;
      return derived;
    }
  } // namespace

  std::optional<double>
  Scene::rod_mass_per_length(const SceneMaterial &group) const
  {
    const std::optional<double> own =
      stated_or_derived(group.mass_per_length,
                        group.density,
                        group.section ?
                          std::optional<double>(group.section->area) :
                          std::nullopt,
                        group.subsection,
                        "Mass per length",
                        "kg/m",
                        "area");
    if (!own)
      return mass_per_length > 0 ? std::optional<double>(mass_per_length) :
                                   std::nullopt;
    if (mass_per_length > 0 && differ_relatively(mass_per_length, *own))
      throw std::invalid_argument(
        "entry \"Loads/Mass per length\": " + number(mass_per_length) +
        " kg/m differs from the " + number(*own) + " kg/m of \"" +
        group.subsection +
        (group.mass_per_length > 0 ? "/Mass per length\"" :
                                     "/Density\" times the section's area") +
        ", which gravity would weigh as well; give one of them (Mass per "
        "length = 0 takes rho A)");
    return own;
  }

  RodInertia
  Scene::inertia_of(const SceneMaterial &group) const
  {
    const std::string needs = "\": time stepping with the " +
                              time_stepping.integrator + " integrator needs ";
    const std::string or_density =
      " of the rods of \"" + group.subsection + "\": give it, or \"" +
      group.subsection +
      "/Density\" with a cross-section (\"Stiffness input = section\")";
    const std::optional<double> rho_A = rod_mass_per_length(group);
    if (!rho_A)
      throw std::invalid_argument("entry \"" + group.subsection +
                                  "/Mass per length" + needs +
                                  "the mass per length rho A" + or_density);
    const std::optional<double> rho_I =
      stated_or_derived(group.twist_inertia_per_length,
                        group.density,
                        group.section ?
                          std::optional<double>(group.section->I1 +
                                                group.section->I2) :
                          std::nullopt,
                        group.subsection,
                        "Twist inertia per length",
                        "kg m",
                        "I1 + I2");
    if (!rho_I)
      throw std::invalid_argument("entry \"" + group.subsection +
                                  "/Twist inertia per length" + needs +
                                  "the twist inertia per length" + or_density);
    // The rotary inertia rho (I1 + I2) / 2 about either bending axis
    // (doc/theory.md, "Rotary inertia"), unless stated.
    return {*rho_A,
            *rho_I,
            group.rotary_inertia_per_length.value_or(*rho_I / 2)};
  }

  std::vector<RodInertia>
  Scene::inertia() const
  {
    std::vector<RodInertia> result;
    for (const unsigned int g : rod_material)
      result.push_back(inertia_of(scene_materials[g]));
    return result;
  }
} // namespace rodnet
