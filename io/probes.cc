#include <deal.II/base/utilities.h>

#include <io/probes.h>
#include <io/vertex_selector.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// A probe kind as the scene writes it.
    struct KindName
    {
      Probe::Kind kind;
      const char *syntax;
      const char *unit;
    };

    const std::vector<KindName> kind_names = {
      {Probe::Kind::position, "position <vertex> <x|y|z>", "m"},
      {Probe::Kind::reaction, "reaction <vertex> <x|y|z>", "N"},
      {Probe::Kind::energy, "energy", "J"},
      {Probe::Kind::eigenvalue, "eigenvalue", "mixed"},
      {Probe::Kind::rotation, "rotation <junction> <ax>,<ay>,<az>", "rad"},
      {Probe::Kind::moment, "moment <junction> <x|y|z>", "N m"}};

    unsigned int
    parse_component(const std::string &text, const std::string &context)
    {
      if (text == "x")
        return 0;
      if (text == "y")
        return 1;
      if (text == "z")
        return 2;
      throw std::invalid_argument(context + ": component \"" + text +
                                  "\" is not x, y or z");
    }
  } // namespace

  std::string
  unit(const Probe::Kind kind)
  {
    for (const KindName &k : kind_names)
      if (k.kind == kind)
        return k.unit;
    throw std::logic_error("unit: unknown probe kind");
  }

  std::string
  probe_kinds_description()
  {
    std::string text;
    for (const KindName &k : kind_names)
      text += (text.empty() ? "" : ", ") + std::string(k.syntax) + " [" +
              k.unit + "]";
    return text;
  }

  void
  unwrap_rotations(const std::vector<Probe>  &probes,
                   const std::vector<double> &previous,
                   std::vector<double>       &values)
  {
    for (std::size_t i = 0; i < probes.size(); ++i)
      if (probes[i].kind == Probe::Kind::rotation)
        {
          const double reference = previous.empty() ? 0.0 : previous[i];
          const double turn      = 2 * M_PI;
          values[i] += turn * std::round((reference - values[i]) / turn);
        }
  }

  namespace
  {
    /// The words of a probe "name: kind vertex component", with where it
    /// stands for messages.
    struct ProbeWords
    {
      std::string entry, context, kind, vertex, component, extra;
    };

    /// The name of the probe @p item; throws unless it is a name without
    /// spaces, commas or quotes and not among @p probes yet.
    std::string
    probe_name(const std::string        &item,
               const std::string        &context,
               const std::vector<Probe> &probes)
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos)
        throw std::invalid_argument(context + ": expected \"name: kind ...\"");
      const std::string name = dealii::Utilities::trim(item.substr(0, colon));
      if (name.empty() || name.find_first_of(",\" ") != std::string::npos)
        throw std::invalid_argument(context +
                                    ": the name must be non-empty "
                                    "without spaces, commas or quotes");
      for (const Probe &p : probes)
        if (p.name == name)
          throw std::invalid_argument(context + ": the name is used twice");
      return name;
    }

    /// The unit axis "ax,ay,az" of a rotation probe.
    Vector3
    parse_axis(const ProbeWords &w)
    {
      Vector3    axis;
      const auto xyz = dealii::Utilities::split_string_list(w.component, ',');
      try
        {
          if (xyz.size() != 3)
            throw std::invalid_argument("");
          const auto v = dealii::Utilities::string_to_double(xyz);
          axis         = Vector3(v[0], v[1], v[2]);
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(w.context + ": the axis \"" +
                                      w.component +
                                      "\" is not three numbers ax,ay,az");
        }
      if (!(axis.norm() > 0))
        throw std::invalid_argument(w.context + ": the axis is zero");
      return axis.normalized();
    }

    /// "position|reaction <vertex> <x|y|z>" into @p probe; a reaction
    /// names the first support that fixes the component.
    template <class Model>
    void
    parse_vertex_probe(const ProbeWords &w, const Model &model, Probe &probe)
    {
      if (w.vertex.empty() || w.component.empty() || !w.extra.empty())
        throw std::invalid_argument(w.context + ": expected \"" + w.kind +
                                    " <vertex> <x|y|z>\"");
      probe.kind =
        w.kind == "position" ? Probe::Kind::position : Probe::Kind::reaction;
      probe.vertex    = select_vertex(model.network(), w.vertex, w.entry);
      probe.component = parse_component(w.component, w.context);
      if (probe.kind != Probe::Kind::reaction)
        return;
      for (const auto &s : model.supports())
        for (unsigned int k = 0; k < s.vertices.size(); ++k)
          if (s.vertices[k] == probe.vertex && s.fixed[k][probe.component] &&
              probe.support.empty())
            probe.support = s.name;
      if (probe.support.empty())
        throw std::invalid_argument(
          w.context + ": no support fixes component " + w.component +
          " of vertex \"" + w.vertex + "\"");
    }

    /// "rotation <junction> <ax>,<ay>,<az>" or "moment <junction> <x|y|z>"
    /// (or a clamped end for a moment) into @p probe.
    template <class Model>
    void
    parse_junction_probe(const ProbeWords &w, const Model &model, Probe &probe)
    {
      // Here "vertex" holds the junction name, "component" the axis.
      if (w.vertex.empty() || w.component.empty() || !w.extra.empty())
        throw std::invalid_argument(
          w.context + ": expected \"" + w.kind + " <junction> " +
          (w.kind == "rotation" ? "<ax>,<ay>,<az>" : "<x|y|z>") + "\"");
      const RotationTarget target =
        select_rotation_target(model.network(), w.vertex, w.context);
      if (!model.has_junction_rotations())
        throw std::invalid_argument(
          w.context + ": junction rotations and moments are those of the "
                      "discrete rods' quaternions; the dynamic relaxation "
                      "element has none");
      // A clamp of a rod end has a reaction moment, no junction.
      const Support *clamp = model.clamp_at(target.vertex);
      if (w.kind == "moment" && clamp != nullptr)
        probe.support = clamp->name;
      else if (!target.junction)
        throw std::invalid_argument(
          w.context + ": \"" + w.vertex + "\" is no junction" +
          (w.kind == "moment" ? " or clamped end" : ""));
      else if (!model.has_rotation(*target.junction))
        throw std::invalid_argument(w.context + ": junction \"" + w.vertex +
                                    "\" is pinned and has no rotation");
      probe.junction = target.junction.value_or(0);
      if (w.kind == "moment")
        {
          probe.kind      = Probe::Kind::moment;
          probe.component = parse_component(w.component, w.context);
        }
      else
        {
          probe.kind = Probe::Kind::rotation;
          probe.axis = parse_axis(w);
        }
    }
  } // namespace

  template <class Model>
  std::vector<Probe>
  parse_probes(const std::string &text,
               const Model       &model,
               const std::string &entry)
  {
    std::vector<Probe> probes;
    for (const std::string &item :
         dealii::Utilities::split_string_list(text, ';'))
      {
        ProbeWords w;
        w.entry   = entry;
        w.context = "entry \"" + entry + "\", probe \"" + item + "\"";
        Probe probe;
        probe.name = probe_name(item, w.context, probes);
        std::istringstream words(item.substr(item.find(':') + 1));
        words >> w.kind >> w.vertex >> w.component >> w.extra;
        if (w.kind == "position" || w.kind == "reaction")
          parse_vertex_probe(w, model, probe);
        else if (w.kind == "rotation" || w.kind == "moment")
          parse_junction_probe(w, model, probe);
        else if ((w.kind == "energy" || w.kind == "eigenvalue") &&
                 w.vertex.empty())
          {
            probe.kind = w.kind == "energy" ? Probe::Kind::energy :
                                              Probe::Kind::eigenvalue;
            if (probe.kind == Probe::Kind::eigenvalue && !model.has_tangent())
              throw std::invalid_argument(
                w.context + ": dynamic relaxation has no tangent to take the "
                            "eigenvalue of");
          }
        else
          throw std::invalid_argument(
            w.context + ": unknown probe kind \"" + w.kind +
            "\"; known: " + probe_kinds_description());
        probes.push_back(probe);
      }
    return probes;
  }

  template std::vector<Probe>
  parse_probes(const std::string &, const RodModel &, const std::string &);
  template std::vector<Probe>
  parse_probes(const std::string &, const DrModel &, const std::string &);

  template <class State>
  std::vector<double>
  evaluate_probes(const std::vector<Probe> &probes,
                  const Model<State>       &model,
                  const State              &u,
                  const double              load_factor,
                  const double              lowest_eigenvalue)
  {
    std::vector<double> values;
    for (const Probe &p : probes)
      switch (p.kind)
        {
          case Probe::Kind::position:
            values.push_back(model.position(u, p.vertex)[p.component]);
            break;
          case Probe::Kind::reaction:
            values.push_back(model.reaction(model.support(p.support),
                                            u,
                                            load_factor)[p.component]);
            break;
          case Probe::Kind::energy:
            values.push_back(model.elastic_energy(u));
            break;
          case Probe::Kind::eigenvalue:
            values.push_back(lowest_eigenvalue);
            break;
          case Probe::Kind::rotation:
            {
              // The twist part of the rotation about the axis (swing-twist
              // split): exact for rotations about the axis, up to 360 deg.
              const Quaternion q = model.junction_rotation(u, p.junction);
              values.push_back(2.0 * std::atan2(q.vec().dot(p.axis), q.w()));
              break;
            }
          case Probe::Kind::moment:
            values.push_back(
              (p.support.empty() ?
                 model.reaction_moment(p.junction, u, load_factor) :
                 model.reaction_moment(model.support(p.support),
                                       u,
                                       load_factor))[p.component]);
            break;
        }
    return values;
  }

  template std::vector<double>
  evaluate_probes(const std::vector<Probe> &,
                  const Model<VectorType> &,
                  const VectorType &,
                  double,
                  double);
  template std::vector<double>
  evaluate_probes(const std::vector<Probe> &,
                  const Model<DrVector> &,
                  const DrVector &,
                  double,
                  double);

  ProbeTable::ProbeTable(const std::string              &path,
                         const std::vector<Probe>       &probes,
                         const std::string              &abscissa,
                         const std::vector<std::string> &check_columns)
      : file(path)
  {
    if (!file)
      throw std::runtime_error("cannot write the probe file " + path);
    file << "step," << abscissa;
    for (const Probe &p : probes)
      file << ',' << p.name;
    for (const std::string &name : check_columns)
      file << ',' << name;
    file << std::endl;
  }

  void
  ProbeTable::add_row(const unsigned int         step,
                      const double               abscissa,
                      const std::vector<double> &values,
                      const std::vector<double> &checks)
  {
    file << step << ',' << std::setprecision(10) << abscissa;
    for (const double v : values)
      file << ',' << std::setprecision(12) << v;
    for (const double c : checks)
      file << ',' << c;
    file << std::endl;
  }
} // namespace rodnet
