#include <core/every_entry.h>
// The supports and rotational loads of a RodModel: clamps that move
// rigidly, fixed and prescribed position components, held and prescribed
// junction rotations and moments, their resolution into fixed DoFs with
// the checks that no DoF is held at two values and no rod is held
// entirely, and the reactions (doc/junctions.md, "Supports").
#include <core/axis_moment_family.h>
#include <core/rod_model.h>
#include <elements/junction_moment.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    const char *const component_names[3] = {"x", "y", "z"};

    std::string
    in_quotes(const std::string &name)
    {
      return "\"" + name + "\"";
    }

    std::string
    number(const double value)
    {
      std::ostringstream s;
      s << value;
      return s.str();
    }

    /// Junction @p j of @p network; throws for @p what ("moment at") if
    /// there is none.
    const Junction &
    existing_junction(const RodNetwork  &network,
                      const unsigned int j,
                      const std::string &what)
    {
      if (j >= network.junctions().size())
        throw std::invalid_argument(what + " junction " + std::to_string(j) +
                                    ", which does not exist");
      return network.junctions()[j];
    }

    void
    require_unit_axis(const Vector3 &axis, const std::string &where)
    {
      if (!(std::abs(axis.norm() - 1.0) < 1e-9))
        throw std::invalid_argument(where + ": the axis must be a unit vector");
    }

    /// Whether two rotations given as axis and angle are the same.
    bool
    same_rotation(const Vector3 &axis_a,
                  const double   angle_a,
                  const Vector3 &axis_b,
                  const double   angle_b)
    {
      return (angle_a * axis_a - angle_b * axis_b).norm() <=
             1e-12 * (std::abs(angle_a) + std::abs(angle_b));
    }
  } // namespace

  void
  RodModel::add_position_support(const std::string         &name,
                                 const unsigned int         vertex,
                                 const std::array<bool, 3> &mask,
                                 const Vector3             &displacement,
                                 const bool                 yields,
                                 const TimeFunction        &in_time)
  {
    const Support s = vertex_support(name, vertex, mask);
    for (unsigned int c = 0; c < 3; ++c)
      if (mask[c])
        holds.emplace(layout_->vertex_dof(vertex, c),
                      Hold{static_cast<unsigned int>(support_list.size()),
                           vertex,
                           c,
                           displacement[c],
                           yields,
                           in_time});
    support_list.push_back(s);
  }

  void
  RodModel::move_components(const std::string         &name,
                            const unsigned int         vertex,
                            const std::array<bool, 3> &mask,
                            const Vector3             &displacement,
                            const TimeFunction        &in_time)
  {
    require_not_finalized("RodModel::move_components " + in_quotes(name));
    add_position_support(name, vertex, mask, displacement, false, in_time);
  }

  void
  RodModel::fix_components(const std::string         &name,
                           const unsigned int         vertex,
                           const std::array<bool, 3> &mask,
                           const Vector3             &displacement)
  {
    require_not_finalized("RodModel::fix_components " + in_quotes(name));
    add_position_support(name, vertex, mask, displacement, false);
  }

  void
  RodModel::clamp_end(const std::string &name,
                      const unsigned int rod_index,
                      const bool         at_start)
  {
    require_not_finalized("RodModel::clamp_end " + in_quotes(name));
    if (rod_index >= network_->rods().size())
      throw std::invalid_argument("support " + in_quotes(name) + ": rod " +
                                  std::to_string(rod_index) +
                                  " does not exist");
    const Rod &rod = network_->rods()[rod_index];
    if (rod.closed)
      throw std::invalid_argument("support " + in_quotes(name) + ": rod " +
                                  std::to_string(rod_index) +
                                  " is closed and has no end to clamp");
    // Both vertices of a single segment held: nothing of the rod could
    // move, and every load on it would vanish into the clamp.
    if (rod.segments.size() < 2)
      throw std::invalid_argument(
        "support " + in_quotes(name) + ": rod " + std::to_string(rod_index) +
        " has a single segment, which a clamp would hold whole (a clamp "
        "holds the two vertices of the end segment), and every load on the "
        "rod would go into the support; give the rod at least 2 segments");
    const unsigned int n = rod.vertices.size();
    Clamp              clamp;
    clamp.support = support_list.size();
    clamp.vertices =
      at_start ?
        std::array<unsigned int, 2>{{rod.vertices[0], rod.vertices[1]}} :
        std::array<unsigned int, 2>{{rod.vertices[n - 1], rod.vertices[n - 2]}};
    clamp.segment = at_start ? rod.segments.front() : rod.segments.back();
    // Before any solve the reference is the undeformed configuration.
    clamp.undeformed_frame =
      configuration_->director_frame(create_vector(), clamp.segment);
    clamps.push_back(clamp);

    // The end vertex yields to a prescribed displacement there, which
    // moves the clamp; the inner vertex and the twist follow the clamp.
    add_position_support(name,
                         clamp.vertices[0],
                         {{true, true, true}},
                         Vector3::Zero(),
                         true);
    Support &s = support_list.back();
    s.vertices.push_back(clamp.vertices[1]);
    s.fixed.push_back({{true, true, true}});
    s.clamped         = true;
    s.clamped_segment = clamp.segment;
  }

  void
  RodModel::rotate_clamp(const std::string  &name,
                         const Vector3      &axis,
                         const double        angle,
                         const TimeFunction &in_time)
  {
    const std::string where = "rotation of clamp " + in_quotes(name);
    require_not_finalized("RodModel::rotate_clamp: " + where);
    require_unit_axis(axis, where);
    // Every clamp of the same rod end turns with it.
    std::vector<unsigned int> segments;
    for (const Clamp &clamp : clamps)
      if (support_list[clamp.support].name == name)
        segments.push_back(clamp.segment);
    if (segments.empty())
      throw std::invalid_argument(where + ": there is no such clamp");
    for (Clamp &clamp : clamps)
      if (std::find(segments.begin(), segments.end(), clamp.segment) !=
          segments.end())
        {
          if (clamp.angle != 0 &&
              (!same_rotation(clamp.axis, clamp.angle, axis, angle) ||
               clamp.rotation_in_time != in_time))
            throw std::invalid_argument(
              where + ": the clamp is turned twice, by different rotations");
          clamp.axis             = axis;
          clamp.angle            = angle;
          clamp.rotation_in_time = in_time;
        }
  }

  void
  RodModel::clamp_junction(const std::string &name, const unsigned int junction)
  {
    require_not_finalized("RodModel::clamp_junction " + in_quotes(name));
    const Junction &j = existing_junction(*network_,
                                          junction,
                                          "support " + in_quotes(name) + ":");
    if (!j.has_rotation())
      throw std::invalid_argument(
        "support " + in_quotes(name) + ": junction " + in_quotes(j.name) +
        " is pinned, so each rod end turns on its own there and there is no "
        "rotation to hold; clamp the rod ends one by one (<rod>:start or "
        "<rod>:end) or make the junction clamped");
    rotation_held[junction] = true;
    add_position_support(name,
                         j.vertex,
                         {{true, true, true}},
                         Vector3::Zero(),
                         true);
    support_list.back().clamped = true;
  }

  void
  RodModel::add_rotational_loads(
    const std::vector<SupportsAndLoads::AxisLoad> &rotations,
    const std::vector<SupportsAndLoads::AxisLoad> &moments)
  {
    for (const SupportsAndLoads::AxisLoad &rotation : rotations)
      if (const Support *clamp = clamp_at(rotation.vertex))
        rotate_clamp(clamp->name,
                     rotation.axis,
                     rotation.value,
                     rotation.in_time);
      else
        prescribe_rotation(rotation.junction.value(),
                           rotation.axis,
                           rotation.value,
                           rotation.in_time);
    for (const SupportsAndLoads::AxisLoad &moment : moments)
      {
        if (const Support *clamp = clamp_at(moment.vertex))
          throw std::invalid_argument(
            moment.where + " is held by the clamp \"" + clamp->name +
            "\", which would take up the whole moment; load a free "
            "vertex, or prescribe a rotation of the clamp instead");
        try
          {
            add_moment(moment.junction.value(),
                       moment.axis,
                       moment.value,
                       moment.ramp);
          }
        catch (const std::invalid_argument &e)
          {
            // The junction cannot take it: say which entry asked.
            throw std::invalid_argument(moment.where + ": " + e.what());
          }
      }
  }

  void
  RodModel::add_moment(const unsigned int junction,
                       const Vector3     &axis,
                       const double       moment,
                       const LoadRamp     ramp)
  {
    require_not_finalized("RodModel::add_moment at junction " +
                          std::to_string(junction));
    const Junction &j = existing_junction(*network_, junction, "moment at");
    if (!j.has_rotation() || j.kind == JunctionKind::clamped)
      throw std::invalid_argument("moment at junction " + in_quotes(j.name) +
                                  ": a " + to_string(j.kind) +
                                  " junction has no free rotation to load");
    require_unit_axis(axis, "moment at junction " + in_quotes(j.name));
    moments.push_back({junction, axis, moment, ramp});
    // The first moment brings the family of moments (a scene without
    // moments does not pay for it).
    if (axis_moment_family == nullptr)
      {
        auto family        = std::make_unique<AxisMomentFamily>(*layout_);
        axis_moment_family = family.get();
        add_element_family(std::move(family));
      }
    axis_moment_family->add({junction, axis, moment, ramp == LoadRamp::held});
  }

  void
  RodModel::prescribe_rotation(const unsigned int  junction,
                               const Vector3      &axis,
                               const double        angle,
                               const TimeFunction &in_time)
  {
    require_not_finalized("RodModel::prescribe_rotation of junction " +
                          std::to_string(junction));
    const Junction &j =
      existing_junction(*network_, junction, "prescribed rotation of");
    const std::string where =
      "prescribed rotation of junction " + in_quotes(j.name);
    if (!j.has_rotation())
      throw std::invalid_argument(where +
                                  ": a pinned junction has no rotation of its "
                                  "own to prescribe");
    require_unit_axis(axis, where);
    for (const AxisLoad &p : prescribed_rotations)
      if (p.junction == junction)
        {
          if (same_rotation(p.axis, p.value, axis, angle) &&
              p.in_time == in_time)
            return;
          throw std::invalid_argument(
            where + ": the junction is turned twice, by different rotations");
        }
    rotation_held[junction] = true;
    prescribed_rotations.push_back(
      {junction, axis, angle, LoadRamp::ramped, in_time});
  }

  void
  RodModel::prescribe_rotation(const unsigned int junction,
                               const Quaternion  &rotation)
  {
    if (!(std::abs(rotation.norm() - 1.0) < 1e-9))
      throw std::invalid_argument("prescribed rotation of junction " +
                                  std::to_string(junction) +
                                  ": the quaternion has norm " +
                                  std::to_string(rotation.norm()) + ", not 1");
    const Eigen::AngleAxisd angle_axis(rotation);
    prescribe_rotation(junction, angle_axis.axis(), angle_axis.angle());
  }

  Vector3
  RodModel::clamp_displacement(const Clamp         &clamp,
                               const unsigned int   vertex,
                               const SupportFactor &factor) const
  {
    const Vector3 arm =
      network_->vertex(vertex) - network_->vertex(clamp.vertices[0]);
    Vector3 translation;
    for (unsigned int c = 0; c < 3; ++c)
      translation[c] =
        factor(clamp.translation_in_time[c]) * clamp.translation[c];
    return translation +
           rotation_about(clamp.axis,
                          factor(clamp.rotation_in_time) * clamp.angle) *
             arm -
           arm;
  }

  namespace
  {
    /// "0.1 m at load factor 1" or "0.1 m times sin(t)".
    std::string
    held_value(const double value, const TimeFunction &in_time)
    {
      return number(value) + " m " +
             (in_time.given() ? "times " + in_time.expression :
                                std::string("at load factor 1"));
    }
  } // namespace

  std::string
  RodModel::held_values(const Hold &a, const Hold &b)
  {
    if (!a.in_time.given() && !b.in_time.given())
      return number(a.value) + " m and " + number(b.value) +
             " m at load factor 1";
    return held_value(a.value, a.in_time) + " and " +
           held_value(b.value, b.in_time);
  }

  void
  RodModel::resolve_position_holds()
  {
    resolve_held_components();
    resolve_clamps();
  }

  void
  RodModel::resolve_held_components()
  {
    const auto same_value = [this](const double a, const double b) {
      return std::abs(a - b) <= 1e-12 * (length + std::abs(a) + std::abs(b));
    };
    // Two holds agree at the same value scaled alike, or both at zero.
    const auto agree = [&](const Hold &a, const Hold &b) {
      return same_value(a.value, b.value) &&
             (a.in_time == b.in_time || same_value(a.value, 0.0));
    };
    for (auto first = holds.begin(); first != holds.end();
         first      = holds.upper_bound(first->first))
      {
             const Hold *set   = nullptr;
             const auto  range = holds.equal_range(first->first);
             for (auto h = range.first; h != range.second; ++h)
          {
                 if (h->second.yields)
              continue;
            if (set != nullptr && !agree(*set, h->second))
              throw std::invalid_argument(
                "the supports " + in_quotes(support_list[set->support].name) +
                " and " + in_quotes(support_list[h->second.support].name) +
                " hold " + component_names[set->component] + " of " +
                network_->describe_vertex(set->vertex) +
                " at different values, " + held_values(*set, h->second) +
                "; a position may be held twice only at the same value");
            if (set == nullptr)
              set = &h->second;
          }
             fixed_dofs[first->first] = set != nullptr ? set->value : 0.0;
             if (set != nullptr && set->in_time.given())
          timed_dofs[first->first] = set->in_time;
      }
  }

  void
  RodModel::resolve_clamps()
  {
    // A clamp moves with its end vertex, and whatever else holds its inner
    // vertex must move with it.
    for (Clamp &clamp : clamps)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const global_dof_index dof =
            layout_->vertex_dof(clamp.vertices[0], c);
          clamp.translation[c] = fixed_dofs.at(dof);
          const auto timed     = timed_dofs.find(dof);
          if (timed != timed_dofs.end())
            clamp.translation_in_time[c] = timed->second;
        }
    for (const Clamp &clamp : clamps)
      {
        check_clamp_inner_holds(clamp);
        for (unsigned int c = 0; c < 3; ++c)
          fixed_dofs[layout_->vertex_dof(clamp.vertices[1], c)] = 0.0;
        for (const Clamp &other : clamps)
          if (other.segment == clamp.segment &&
              (!same_rotation(clamp.axis,
                              clamp.angle,
                              other.axis,
                              other.angle) ||
               (clamp.angle != 0 &&
                clamp.rotation_in_time != other.rotation_in_time)))
            throw std::invalid_argument(
              "the clamps " + in_quotes(support_list[clamp.support].name) +
              " and " + in_quotes(support_list[other.support].name) +
              " hold the same rod end but turn it differently");
        fixed_dofs[layout_->twist_dof(clamp.segment)] = 0.0;
      }
  }

  void
  RodModel::check_clamp_inner_holds(const Clamp &clamp) const
  {
    const auto same_value = [this](const double a, const double b) {
      return std::abs(a - b) <= 1e-12 * (length + std::abs(a) + std::abs(b));
    };
    // Samples of the factors: the load factor at 0.5 and 1, each distinct
    // function of time at its own multiple of them, so that motions
    // scaled differently cannot agree at both.
    std::vector<std::string> expressions;
    for (const double load_factor : {0.5, 1.0})
      {
        const SupportFactor sample = [&](const TimeFunction &f) {
          if (!f.given())
            return load_factor;
          auto known =
            std::find(expressions.begin(), expressions.end(), f.expression);
          if (known == expressions.end())
            known = expressions.insert(known, f.expression);
          return load_factor * (1.25 + 0.5 * (known - expressions.begin()));
        };
        for (unsigned int c = 0; c < 3; ++c)
          {
            const auto range =
              holds.equal_range(layout_->vertex_dof(clamp.vertices[1], c));
            for (auto h = range.first; h != range.second; ++h)
              {
                if (h->second.yields)
                  continue;
                const double held = sample(h->second.in_time) * h->second.value;
                const double moved =
                  clamp_displacement(clamp, clamp.vertices[1], sample)[c];
                if (!same_value(held, moved))
                  throw std::invalid_argument(
                    "the support " +
                    in_quotes(support_list[h->second.support].name) +
                    " holds " + component_names[c] + " of " +
                    network_->describe_vertex(clamp.vertices[1]) + " at " +
                    held_value(h->second.value, h->second.in_time) +
                    ", but the clamp " +
                    in_quotes(support_list[clamp.support].name) +
                    " holds that vertex and moves it otherwise; a clamp "
                    "moves rigidly: prescribe the displacement of its end "
                    "vertex instead");
              }
          }
      }
  }

  void
  RodModel::resolve_supports()
  {
    resolve_position_holds();
    // The gauge of every junction quaternion: the real part of every
    // increment stays 1 (stored as 0); held rotations fix the rest.
    for (unsigned int j = 0; j < network_->junctions().size(); ++j)
      if (layout_->has_rotation_dofs(j))
        for (unsigned int c = 0; c < (rotation_held[j] ? 4 : 1); ++c)
          fixed_dofs[layout_->rotation_dof(j, c)] = 0.0;
    for (const AxisLoad &m : moments)
      if (rotation_held[m.junction])
        throw std::invalid_argument(
          "moment at junction " +
          in_quotes(network_->junctions()[m.junction].name) +
          ": its rotation is held (by a prescribed rotation or a clamp), "
          "which would take up the whole moment; remove one of the two");
  }

  bool
  RodModel::moves_supports_in_time() const
  {
    if (!timed_dofs.empty())
      return true;
    for (const AxisLoad &p : prescribed_rotations)
      if (p.in_time.given())
        return true;
    for (const Clamp &clamp : clamps)
      if (clamp.angle != 0 && clamp.rotation_in_time.given())
        return true;
    return false;
  }

  std::vector<double>
  RodModel::support_time_factors(const double time) const
  {
    std::vector<double> factors;
    for (const auto &[dof, in_time] : timed_dofs)
      factors.push_back((*in_time.of_time)(time));
    for (const AxisLoad &p : prescribed_rotations)
      if (p.in_time.given())
        factors.push_back((*p.in_time.of_time)(time));
    for (const Clamp &clamp : clamps)
      if (clamp.angle != 0 && clamp.rotation_in_time.given())
        factors.push_back((*clamp.rotation_in_time.of_time)(time));
    return factors;
  }

  void
  RodModel::check_rotation_step(const double load_factor_0,
                                const double time_0,
                                const double load_factor_1,
                                const double time_1) const
  {
    require_rotation_step_below_half_turn(
      [&](const TimeFunction &in_time) {
        return in_time.factor(load_factor_1, time_1) -
               in_time.factor(load_factor_0, time_0);
      },
      "from t = " + number(time_0) + " to " + number(time_1) + " s",
      "take a smaller time step (or more load steps)");
  }

  void
  RodModel::check_rotation_step(const double load_factor_0,
                                const double load_factor_1) const
  {
    require_rotation_step_below_half_turn(
      [&](const TimeFunction &in_time) {
        return in_time.given() ? 0.0 : load_factor_1 - load_factor_0;
      },
      "from load factor " + number(load_factor_0) + " to " +
        number(load_factor_1),
      "use more load steps (Loads/Steps)");
  }

  void
  RodModel::require_rotation_step_below_half_turn(
    const SupportFactor &change,
    const std::string   &step,
    const std::string   &remedy) const
  {
    // The largest turn an increment (1, v) with real part above 1e-3
    // reaches (apply_boundary_values()).
    const double limit = 2 * std::acos(1e-3);
    const auto   check = [&](const double        angle,
                           const TimeFunction &in_time,
                           const std::string  &what) {
      const double turn = std::abs(angle * change(in_time));
      if (!(turn < limit))
        throw std::runtime_error("the prescribed rotation of " + what +
                                 " turns by " + number(turn * 180 / M_PI) +
                                 " degrees " + step +
                                 ", and a step turns by less than 180 "
                                   "degrees; " +
                                 remedy);
    };
    for (const AxisLoad &p : prescribed_rotations)
      check(p.value,
            p.in_time,
            "junction " + in_quotes(network_->junctions()[p.junction].name));
    for (const Clamp &clamp : clamps)
      check(clamp.angle,
            clamp.rotation_in_time,
            "the clamp " + in_quotes(support_list[clamp.support].name));
  }

  void
  RodModel::apply_boundary_values(VectorType &u, const double load_factor) const
  {
    apply_boundary_values(u, load_factor, support_time);
  }

  namespace
  {
    /// Throws std::runtime_error where the @p increment of a prescribed
    /// rotation of @p what within one step reaches about 180 degrees (the
    /// increments (1, v) of the junction DoFs cannot, and a clamp's twist
    /// would be taken modulo a turn).
    void
    require_increment_below_half_turn(Quaternion         increment,
                                      const std::string &what)
    {
      if (increment.w() < 0)
        increment.coeffs() *= -1.0;
      if (!(increment.w() > 1e-3))
        throw std::runtime_error(
          "the prescribed rotation of " + what +
          " turns by nearly 180 degrees or more within one step; use more "
          "load steps or a smaller time step");
    }
  } // namespace

  void
  RodModel::apply_boundary_values(VectorType  &u,
                                  const double load_factor,
                                  const double time) const
  {
    // On several processes: on a copy of every entry, which the supports
    // read and write anywhere; this process keeps its own entries.
    if (own_stencils.empty())
      return set_support_values(u, load_factor, time);
    VectorType all = replica(u);
    set_support_values(all, load_factor, time);
    for (const global_dof_index i : owned_dofs)
      u[i] = all[i];
    u.compress(dealii::VectorOperation::insert);
  }


  void
  RodModel::set_support_values(VectorType  &u,
                               const double load_factor,
                               const double time) const
  {
    const SupportFactor factor = [&](const TimeFunction &f) {
      if (f.given() && !std::isfinite(time))
        throw std::logic_error("a support moves by the function of time " +
                               f.expression +
                               ", but the model has no time: set_time() "
                               "first (time stepping)");
      return f.factor(load_factor, time);
    };
    // A turned clamp's twist continues from its current value (below); its
    // turn within the step is measured from its current frame.
    std::vector<double> clamp_twists;
    for (const Clamp &clamp : clamps)
      {
        clamp_twists.push_back(u[layout_->twist_dof(clamp.segment)]);
        if (clamp.angle != 0)
          require_increment_below_half_turn(
            rotation_about(clamp.axis,
                           factor(clamp.rotation_in_time) * clamp.angle) *
              clamp.undeformed_frame *
              configuration_->director_frame(u, clamp.segment).conjugate(),
            "the clamp " + in_quotes(support_list[clamp.support].name));
      }
    for (const auto &[dof, value] : fixed_dofs)
      u[dof] = load_factor * value;
    for (const auto &[dof, in_time] : timed_dofs)
      u[dof] = factor(in_time) * fixed_dofs.at(dof);
    // A prescribed rotation is reached from the reference rotation by an
    // increment (1, v) in the gauge of the quaternion DoFs.
    for (const AxisLoad &p : prescribed_rotations)
      {
        Quaternion increment =
          rotation_about(p.axis, factor(p.in_time) * p.value) *
          configuration_->reference_rotation(p.junction).conjugate();
        require_increment_below_half_turn(
          increment,
          "junction " + in_quotes(network_->junctions()[p.junction].name));
        if (increment.w() < 0)
          increment.coeffs() *= -1.0;
        u[layout_->rotation_dof(p.junction, 0)] = 0.0;
        for (unsigned int c = 1; c < 4; ++c)
          u[layout_->rotation_dof(p.junction, c)] =
            increment.vec()[c - 1] / increment.w();
      }
    for (unsigned int i = 0; i < clamps.size(); ++i)
      {
        const Clamp  &clamp = clamps[i];
        const Vector3 inner =
          clamp_displacement(clamp, clamp.vertices[1], factor);
        for (unsigned int c = 0; c < 3; ++c)
          u[layout_->vertex_dof(clamp.vertices[1], c)] = inner[c];
        if (clamp.angle != 0)
          u[layout_->twist_dof(clamp.segment)] = clamp_twists[i];
      }
    u.compress(dealii::VectorOperation::insert);
    turn_clamp_twists(u, clamp_twists, factor);
    // The other rod ends at a junction move with its vertex.
    layout_->junction_constraints().distribute(u);
  }

  void
  RodModel::turn_clamp_twists(VectorType                &u,
                              const std::vector<double> &clamp_twists,
                              const SupportFactor       &factor) const
  {
    // The end segment of a turned clamp has the tangent R t0 now; its
    // twist turns the director frame there from the parallel-transported
    // one to R D0 (both share d3, so the angle between their d1 about it).
    std::vector<double> twists(clamps.size());
    for (unsigned int i = 0; i < clamps.size(); ++i)
      if (clamps[i].angle != 0)
        {
          const Clamp  &clamp = clamps[i];
          const Matrix3 frame =
            configuration_->director_frame(u, clamp.segment).toRotationMatrix();
          const Matrix3 target =
            (rotation_about(clamp.axis,
                            factor(clamp.rotation_in_time) * clamp.angle) *
             clamp.undeformed_frame)
              .toRotationMatrix();
          twists[i] =
            clamp_twists[i] +
            std::atan2(frame.col(0).cross(target.col(0)).dot(target.col(2)),
                       frame.col(0).dot(target.col(0)));
        }
    for (unsigned int i = 0; i < clamps.size(); ++i)
      if (clamps[i].angle != 0)
        u[layout_->twist_dof(clamps[i].segment)] = twists[i];
    u.compress(dealii::VectorOperation::insert);
  }

  VectorType
  RodModel::reactions_at(const VectorType &u, const double load_factor) const
  {
    VectorType r = create_vector();
    assemble(u, load_factor, &r, nullptr, false);
    return *EveryEntry(r);
  }

  Vector3
  RodModel::reaction(const Support    &s,
                     const VectorType &u,
                     const double      load_factor) const
  {
    const VectorType r     = reactions_at(u, load_factor);
    Vector3          total = Vector3::Zero();
    for (unsigned int k = 0; k < s.vertices.size(); ++k)
      total += support_force(s, k, r);
    return total;
  }

  Vector3
  RodModel::support_force(const Support     &s,
                          const unsigned int k,
                          const VectorType  &r) const
  {
    // At a fixed DoF the support force F balances the residual:
    // dPhi/du - F = 0, so F is the residual there.
    Vector3 force = Vector3::Zero();
    for (unsigned int c = 0; c < 3; ++c)
      if (s.fixed[k][c])
        force[c] = r[layout_->vertex_dof(s.vertices[k], c)];
    return force;
  }

  Vector3
  RodModel::reaction_moment(const Support    &s,
                            const VectorType &state,
                            const double      load_factor) const
  {
    const VectorType  r = reactions_at(state, load_factor);
    const EveryEntry  every_entry(state);
    const VectorType &u = *every_entry;
    // Virtual work of a rigid rotation omega of the support about x_0:
    // dx_k = omega x (x_k - x_0), dphi = omega . t (a rotation normal to
    // the tangent is the parallel transport, which leaves the twist).
    const Vector3 pivot = configuration_->position(u, s.vertices[0]);
    Vector3       total = Vector3::Zero();
    for (unsigned int k = 0; k < s.vertices.size(); ++k)
      total += (configuration_->position(u, s.vertices[k]) - pivot)
                 .cross(support_force(s, k, r));
    if (s.clamped_segment)
      total += r[layout_->twist_dof(*s.clamped_segment)] *
               configuration_->director_frame(u, *s.clamped_segment)
                 .toRotationMatrix()
                 .col(2);
    return total;
  }

  Vector3
  RodModel::reaction_moment(const unsigned int junction,
                            const VectorType  &state,
                            const double       load_factor) const
  {
    if (junction >= network_->junctions().size() ||
        !layout_->has_rotation_dofs(junction))
      throw std::invalid_argument("reaction moment: junction " +
                                  std::to_string(junction) +
                                  " does not exist or has no rotation");
    const VectorType  r = reactions_at(state, load_factor);
    const EveryEntry  every_entry(state);
    const VectorType &u = *every_entry;
    Eigen::Vector4d   q, gradient;
    for (unsigned int c = 0; c < 4; ++c)
      {
        q[c]        = u[layout_->rotation_dof(junction, c)] + (c == 0);
        gradient[c] = r[layout_->rotation_dof(junction, c)];
      }
    return spatial_moment(q, gradient);
  }
} // namespace rodnet
