// Configuration: activation fields, natural strains given along the rods.
#include <core/configuration.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    /// The bending and twisting part of an integral of an activation field.
    Vector3
    bending_part(const Eigen::Vector4d &integral)
    {
      return integral.head<3>();
    }

    /// Whether @p a and @p b are the same drive: the same kind, and for
    /// functions of time the same function.
    bool
    same_drive(const ActivationDrive &a, const ActivationDrive &b)
    {
      return a.kind == b.kind && a.of_time == b.of_time;
    }
  } // namespace

  void
  Configuration::start_activation()
  {
    const auto &rods           = network->rods();
    activation.hinge_geometric = hinge_natural_strains;
    activation.junction_now.assign(junction_refs.size(), Vector3::Zero());
    activation.segment_now.assign(rest_lengths.size(), 0.);
    activation.rod_hinges.assign(rods.size(), {});
    activation.rod_junctions.assign(rods.size(), {});
    activation.cell_position.assign(rest_lengths.size(), 0);
    for (unsigned int h = 0; h < layout->hinges().size(); ++h)
      activation.rod_hinges[layout->hinges()[h].rod].push_back(h);
    for (unsigned int e = 0; e < layout->junctions().size(); ++e)
      activation.rod_junctions[layout->junctions()[e].rod].push_back(e);
    for (const Rod &rod : rods)
      for (unsigned int j = 0; j < rod.segments.size(); ++j)
        activation.cell_position[rod.segments[j]] = j;
  }


  Configuration::ActivationShare &
  Configuration::activation_share(const ActivationDrive &drive)
  {
    for (ActivationShare &share : activation.shares)
      if (same_drive(share.drive, drive))
        return share;
    ActivationShare share;
    share.drive = drive;
    share.hinge.assign(hinge_refs.size(), Vector3::Zero());
    share.junction.assign(junction_refs.size(), Vector3::Zero());
    share.cell.assign(rest_lengths.size(), Eigen::Vector4d::Zero());
    // A function of time has no factor until the time is set.
    share.factor =
      drive.kind == ActivationDrive::Kind::fixed ? 1. :
      drive.kind == ActivationDrive::Kind::time  ? 0. :
                                                   activation.factor;
    activation.shares.push_back(share);
    return activation.shares.back();
  }


  std::vector<double>
  Configuration::vertex_arc_lengths(const unsigned int rod) const
  {
    const std::vector<unsigned int> &cells = network->rods()[rod].segments;
    std::vector<double>              t(cells.size() + 1, 0.);
    for (unsigned int j = 0; j < cells.size(); ++j)
      t[j + 1] = t[j] + rest_lengths[cells[j]];
    return t;
  }


  void
  Configuration::add_activation(const unsigned int     rod,
                                const ActivationField &field,
                                const ActivationDrive &drive)
  {
    if (network->rods()[rod].developable)
      throw std::invalid_argument(
        "rod " + std::to_string(rod) +
        " is a developable ribbon, straight and flat when unstressed: it "
        "takes no activation field");
    if (activation.empty())
      start_activation();
    const std::vector<double> t = vertex_arc_lengths(rod);
    const auto      &p = activation.cell_position; // a cell's place in its rod
    ActivationShare &share = activation_share(drive);

    // A hinge's Voronoi cell: the second half of its previous segment and
    // the first half of its next one (across the closure of a ring too).
    for (const unsigned int h : activation.rod_hinges[rod])
      {
        const HingeStencil &hinge = layout->hinges()[h];
        const unsigned int  prev  = p[hinge.segment_prev] + 1;
        const unsigned int  next  = p[hinge.segment_next];
        share.hinge[h] += bending_part(
          field(t[prev] - 0.5 * rest_lengths[hinge.segment_prev], t[prev]) +
          field(t[next], t[next] + 0.5 * rest_lengths[hinge.segment_next]));
      }
    // A junction element covers the half of its segment next to the
    // junction (junction_voronoi_length()).
    for (const unsigned int e : activation.rod_junctions[rod])
      {
        const JunctionStencil &element = layout->junctions()[e];
        const unsigned int     j       = p[element.segment];
        const double           half    = 0.5 * rest_lengths[element.segment];
        share.junction[e] +=
          bending_part(element.ghost_first ? field(t[j], t[j] + half) :
                                             field(t[j + 1] - half, t[j + 1]));
      }
    const Rod &whole = network->rods()[rod];
    for (unsigned int j = 0; j < whole.segments.size(); ++j)
      {
        const unsigned int    cell = whole.segments[j];
        const Eigen::Vector4d mean = field(t[j], t[j + 1]) / rest_lengths[cell];
        // The length constraint of an inextensible segment (and the
        // ribbon's) would ignore it: refused, not dropped.
        if (mean[3] != 0. && whole.inextensible)
          throw std::invalid_argument(
            "rod " + std::to_string(rod) +
            " is inextensible: an axial eigenstrain cannot change its length");
        share.cell[cell] += mean;
      }
    sum_activation();
  }


  void
  Configuration::follow_activation(const double factor)
  {
    if (activation.empty() || factor == activation.factor)
      return;
    for (ActivationShare &share : activation.shares)
      if (share.drive.kind == ActivationDrive::Kind::load_factor)
        share.factor = factor;
    activation.factor = factor;
    sum_activation();
  }


  void
  Configuration::set_activation_time(const double time)
  {
    bool moved = false;
    for (ActivationShare &share : activation.shares)
      if (share.drive.kind == ActivationDrive::Kind::time)
        {
          const double factor = (*share.drive.of_time)(time);
          moved               = moved || factor != share.factor;
          share.factor        = factor;
        }
    if (moved)
      sum_activation();
  }


  std::vector<double>
  Configuration::activation_time_factors() const
  {
    std::vector<double> factors;
    for (const ActivationShare &share : activation.shares)
      if (share.drive.kind == ActivationDrive::Kind::time)
        factors.push_back(share.factor);
    return factors;
  }


  bool
  Configuration::has_activation_driven_by(
    const ActivationDrive::Kind kind) const
  {
    for (const ActivationShare &share : activation.shares)
      if (share.drive.kind == kind)
        return true;
    return false;
  }


  void
  Configuration::sum_activation()
  {
    hinge_natural_strains = activation.hinge_geometric;
    std::fill(activation.junction_now.begin(),
              activation.junction_now.end(),
              Vector3::Zero());
    std::fill(activation.segment_now.begin(), activation.segment_now.end(), 0.);
    for (const ActivationShare &share : activation.shares)
      {
        for (unsigned int h = 0; h < share.hinge.size(); ++h)
          hinge_natural_strains[h] += share.factor * share.hinge[h];
        for (unsigned int e = 0; e < share.junction.size(); ++e)
          activation.junction_now[e] += share.factor * share.junction[e];
        for (unsigned int c = 0; c < share.cell.size(); ++c)
          activation.segment_now[c] += share.factor * share.cell[c][3];
      }
  }


  std::vector<Eigen::Vector4d>
  Configuration::segment_activation() const
  {
    std::vector<Eigen::Vector4d> densities;
    if (activation.empty())
      return densities;
    densities.assign(rest_lengths.size(), Eigen::Vector4d::Zero());
    for (const ActivationShare &share : activation.shares)
      for (unsigned int c = 0; c < share.cell.size(); ++c)
        densities[c] += share.factor * share.cell[c];
    return densities;
  }
} // namespace rodnet
