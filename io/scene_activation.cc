#include <io/activation_fields.h>
#include <io/run_limits.h>
#include <io/scene.h>

#include <functional>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The undeformed length of the polygon of rod @p rod of @p network,
    /// and the length of its first segment.
    std::pair<double, double>
    polygon_lengths(const RodNetwork &network, const Rod &rod)
    {
      double length = 0., first = 0.;
      for (unsigned int j = 0; j < rod.segments.size(); ++j)
        {
          const double l =
            (network.vertex(rod.vertices[(j + 1) % rod.vertices.size()]) -
             network.vertex(rod.vertices[j]))
              .norm();
          length += l;
          if (j == 0)
            first = l;
        }
      return {length, first};
    }
  } // namespace

  bool
  Scene::ramps_activation(const bool in_time_too) const
  {
    for (const std::vector<ActivationItem> &items : rod_activation)
      for (const ActivationItem &item : items)
        if (item.drive.kind == ActivationDrive::Kind::load_factor ||
            (in_time_too && item.drive.kind == ActivationDrive::Kind::time))
          return true;
    return false;
  }

  void
  Scene::check_activation_drives() const
  {
    for (const std::vector<ActivationItem> &items : rod_activation)
      for (const ActivationItem &item : items)
        if (item.drive.kind == ActivationDrive::Kind::time)
          check_time_function(*item.drive.of_time,
                              "entry \"" + item.entry + "\", item \"" +
                                item.text +
                                "\": a function of time drives "
                                "a field",
                              "drive it by the load factor (\"ramped\")");
  }

  void
  Scene::check_time_function(const std::function<double(double)> &f,
                             const std::string                   &what,
                             const std::string                   &instead) const
  {
    const TimeIntegrator::Parameters &p = time_stepping;
    if (method != SolutionMethod::time_stepping)
      throw std::invalid_argument(what +
                                  " in time stepping only; set Solver/Method "
                                  "= time stepping, or " +
                                  instead);
    // At the times the steps end on, before any step: the function
    // throws, naming the time, where it is not finite. (A run of too
    // many steps is refused by check_run_length().)
    if ((p.end_time - p.start_time) / p.time_step > run_limits::max_time_steps)
      return;
    if (p.preload_time > 0)
      for (unsigned int k = 0; k <= p.preload_steps; ++k)
        f(p.initial_time() + k * p.preload_time / p.preload_steps);
    for (double k = 0; p.start_time + k * p.time_step < p.end_time; ++k)
      f(p.start_time + k * p.time_step);
    f(p.end_time);
  }

  void
  Scene::add_activation_fields(RodModel &model) const
  {
    const RodNetwork &network = model.network();
    for (unsigned int r = 0; r < rod_activation.size(); ++r)
      {
        if (rod_activation[r].empty())
          continue;
        const auto [polygon, first] =
          polygon_lengths(network, network.rods()[r]);
        // Under a midpoint clamp the rod starts half its first segment in.
        const double offset = midpoint_clamp ? 0.5 * first : 0.;
        for (const ActivationItem &item : rod_activation[r])
          try
            {
              model.add_activation(
                r,
                activation_field(item, polygon - offset, offset, rod_name(r)),
                item.drive);
            }
          catch (const std::invalid_argument &e)
            {
              const std::string what = e.what();
              // The field's own messages name the entry already, the
              // model's the rod.
              throw std::invalid_argument(what.rfind("entry ", 0) == 0 ?
                                            what :
                                            "entry \"" + item.entry +
                                              "\": " + what);
            }
      }
  }
} // namespace rodnet
