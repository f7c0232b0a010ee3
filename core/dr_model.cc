#include <base/phase_times.h>
#include <core/dr_model.h>
#include <core/require_positive.h>
#include <materials/dr_beam_energy.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    constexpr unsigned int invalid = std::numeric_limits<unsigned int>::max();

    /// Smallest z component of an initial normal: the element's normal
    /// (n_x, n_y, sqrt(1 - n_x^2 - n_y^2)) is singular on the xy plane.
    constexpr double min_normal_z = 1e-3;

    /// Strains or stresses of an element as one vector, in the order
    /// (stretch, twist, tilt_a, tilt_b, turn_a, turn_b).
    using StrainVector = Eigen::Matrix<double, 6, 1>;

    template <typename T>
    StrainVector
    pack(const T &s)
    {
      StrainVector v;
      v << s.stretch, s.twist, s.tilt[0], s.tilt[1], s.turn[0], s.turn[1];
      return v;
    }

    template <typename T>
    T
    unpack(const StrainVector &v)
    {
      T s;
      s.stretch = v[0];
      s.twist   = v[1];
      s.tilt    = {{v[2], v[3]}};
      s.turn    = {{v[4], v[5]}};
      return s;
    }

    /**
     * Throws unless rod @p r of @p network is straight at rest (no hinge
     * turning by more than 1e-6 rad, round-off of mesh coordinates): the
     * element is stress free in its initial geometry, so it cannot bend a
     * curved rod of natural shape straight, and for a curved rod of
     * natural shape initial geometry its answers are off (a quarter-circle
     * cantilever's tip deflection by 2% to 12%, not converging as the
     * elements get shorter; doc/dynamic_relaxation.md).
     */
    void
    check_straight_at_rest(const RodNetwork &network, const unsigned int r)
    {
      const Rod         &rod     = network.rods()[r];
      const unsigned int n       = rod.vertices.size();
      const auto         tangent = [&](const unsigned int s) -> Vector3 {
        return (network.vertex(rod.vertices[(s + 1) % n]) -
                network.vertex(rod.vertices[s]))
          .normalized();
      };
      // The hinges: every vertex of a closed rod, the interior ones else.
      const unsigned int end = rod.closed ? n : n - 1;
      for (unsigned int i = rod.closed ? 0 : 1; i < end; ++i)
        {
          const Vector3 a = tangent((i + n - 1) % n), b = tangent(i);
          const double  angle = std::atan2(a.cross(b).norm(), a.dot(b));
          if (!(angle > 1e-6))
            continue;
          std::ostringstream message;
          message << "DrModel: rod " << r << ", vertex " << i
                  << ": the rod turns by " << angle * 180 / M_PI
                  << " degrees there; the bending-active element of dynamic "
                     "relaxation takes rods that are straight at rest only "
                     "(curved ones come out wrong, see "
                     "doc/dynamic_relaxation.md); use the Newton solver";
          throw std::invalid_argument(message.str());
        }
    }

    constexpr std::array<unsigned int, 2> node_block = {
      {dr_dof::node_a, dr_dof::node_b}};
    constexpr std::array<unsigned int, 2> far_block = {
      {dr_dof::far_a, dr_dof::far_b}};

    /**
     * The material tangent C = d^2 W / d strain^2 of an element of rest
     * length @p l0 at @p strain, by central differences of the stress:
     * exact for an energy quadratic in the strains, the tangent at the
     * state otherwise. The stretch is a length, hence its step 1e-4 l0.
     */
    Eigen::Matrix<double, 6, 6>
    stress_tangent(const RodStiffness &k,
                   const double        l0,
                   const StrainVector &strain)
    {
      Eigen::Matrix<double, 6, 6> C;
      for (unsigned int q = 0; q < 6; ++q)
        {
          const double h     = q == 0 ? 1e-4 * l0 : 1e-4;
          StrainVector shift = StrainVector::Zero();
          shift[q]           = h;
          DrBeamStress plus, minus;
          dr_beam_energy(k, l0, unpack<DrBeamStrains>(strain + shift), &plus);
          dr_beam_energy(k, l0, unpack<DrBeamStrains>(strain - shift), &minus);
          C.col(q) = (pack(plus) - pack(minus)) / (2 * h);
        }
      return C;
    }

    /// |J|, the strain Jacobian of @p kinematics with its entries' absolute
    /// values, row by row: the pull-back of a unit stress is a strain
    /// gradient.
    Eigen::Matrix<double, 6, n_dr_element_dofs>
    abs_strain_jacobian(const DrBeamKinematics &kinematics)
    {
      Eigen::Matrix<double, 6, n_dr_element_dofs> abs_J;
      DrElementVector                             gradient;
      for (unsigned int p = 0; p < 6; ++p)
        {
          kinematics.pull_back(unpack<DrBeamStress>(StrainVector::Unit(p)),
                               gradient);
          abs_J.row(p) = gradient.transpose().cwiseAbs();
        }
      return abs_J;
    }

    /**
     * The bound of the Gershgorin row sums of one element's stiffness at
     * its local DoFs @p local (see DrModel::fictitious_masses()): the
     * material part |J|^T |C| |J| 1 and the geometric stiffness 2 |N| / L
     * of the axial force on the translations of both ends.
     */
    DrElementVector
    element_row_sum_bound(const DrElementVector &local,
                          const DrBeamReference &reference,
                          const RodStiffness    &k)
    {
      const DrBeamKinematics            kinematics(local, reference);
      const double                      l0 = reference.rest_length;
      const Eigen::Matrix<double, 6, 6> C =
        stress_tangent(k, l0, pack(kinematics.strains()));
      const Eigen::Matrix<double, 6, n_dr_element_dofs> abs_J =
        abs_strain_jacobian(kinematics);
      DrElementVector bound =
        abs_J.transpose() * (C.cwiseAbs() * abs_J.rowwise().sum());

      DrBeamStress stress;
      dr_beam_energy(k, l0, kinematics.strains(), &stress);
      const double geometric =
        2 * std::abs(stress.stretch) /
        (local.segment<3>(dr_dof::node_b) - local.segment<3>(dr_dof::node_a))
          .norm();
      for (const unsigned int block : node_block)
        bound.segment<3>(block + dr_dof::position).array() += geometric;
      return bound;
    }
  } // namespace


  DrModel::DrModel(std::unique_ptr<RodNetwork> network,
                   std::vector<RodStiffness>   stiffness_per_rod,
                   const MPI_Comm              communicator)
      : network_(std::move(network))
      , stiffness(std::move(stiffness_per_rod))
      , communicator(communicator)
  {
    // The output draws the rods on the network's triangulation.
    if (network_->triangulation().n_active_cells() == 0)
      network_->create_triangulation();
    check_stiffness();
    for (unsigned int r = 0; r < network_->rods().size(); ++r)
      check_straight_at_rest(*network_, r);
    number_nodes();
    length = rodnet::length_scale(*network_);
    create_elements();
    initialize_frames();
    for (const Junction &j : network_->junctions())
      if (j.kind == JunctionKind::clamped)
        clamp_vertex(j.name, j.vertex);
      else if (j.kind == JunctionKind::welded_pinned)
        fix_components(j.name, j.vertex, {{true, true, true}});
  }


  void
  DrModel::check_stiffness() const
  {
    const auto &rods = network_->rods();
    if (stiffness.size() != rods.size())
      throw std::invalid_argument(
        "DrModel: " + std::to_string(rods.size()) + " rods but " +
        std::to_string(stiffness.size()) + " stiffnesses");
    for (unsigned int r = 0; r < rods.size(); ++r)
      for (const auto &[name, value] : {std::make_pair("EA", stiffness[r].EA),
                                        std::make_pair("EI1", stiffness[r].EI1),
                                        std::make_pair("EI2", stiffness[r].EI2),
                                        std::make_pair("GJ", stiffness[r].GJ)})
        require_positive(value,
                         "DrModel: rod " + std::to_string(r) + ": " + name);
  }


  void
  DrModel::number_nodes()
  {
    // The rod ends at a junction share the position of its vertex and,
    // except at a pinned junction, its frame.
    const RodNetwork         &network    = *network_;
    const unsigned int        n_vertices = network.n_vertices();
    std::vector<unsigned int> position_owner(n_vertices);
    std::iota(position_owner.begin(), position_owner.end(), 0u);
    std::vector<unsigned int> frame_owner = position_owner;
    for (const Junction &j : network.junctions())
      for (const RodEnd &end : j.ends)
        {
          const unsigned int v = network.end_vertex(end);
          position_owner[v]    = j.vertex;
          if (j.kind != JunctionKind::pinned)
            frame_owner[v] = j.vertex;
        }

    // Nodes are numbered along the rods, so that an element's DoFs lie
    // close together in memory.
    position_node.assign(n_vertices, invalid);
    frame_node.assign(n_vertices, invalid);
    for (const Rod &rod : network.rods())
      for (const unsigned int v : rod.vertices)
        {
          unsigned int &p = position_node[position_owner[v]];
          if (p == invalid)
            {
              p = position_dofs.size();
              position_dofs.push_back(initial.size());
              for (unsigned int c = 0; c < 3; ++c)
                initial.push_back(network.vertex(v)[c]);
            }
          position_node[v] = p;
          unsigned int &f  = frame_node[frame_owner[v]];
          if (f == invalid)
            {
              f = frame_dofs.size();
              frame_dofs.push_back(initial.size());
              initial.insert(initial.end(), 3, 0.0);
            }
          frame_node[v] = f;
        }
  }


  void
  DrModel::create_elements()
  {
    const auto &rods = network_->rods();
    for (unsigned int r = 0; r < rods.size(); ++r)
      {
        const Rod         &rod        = rods[r];
        const unsigned int n          = rod.vertices.size();
        const unsigned int n_segments = rod.closed ? n : n - 1;
        for (unsigned int j = 0; j < n_segments; ++j)
          {
            Element e;
            e.rod      = r;
            e.segment  = j;
            e.vertices = {{rod.vertices[j], rod.vertices[(j + 1) % n]}};
            elements.push_back(e);
          }
      }
  }


  void
  DrModel::initialize_frames()
  {
    // Reference element of each frame: the first element it belongs to;
    // the frame's normal is the director d1 of that element's rod there.
    far_vertex.assign(frame_dofs.size(), invalid);
    for (const Element &e : elements)
      for (unsigned int end = 0; end < 2; ++end)
        {
          const unsigned int f = frame_node[e.vertices[end]];
          if (far_vertex[f] != invalid)
            continue;
          far_vertex[f]              = e.vertices[1 - end];
          const Vector3 d1           = initial_normal(e, end);
          initial[frame_dofs[f] + 0] = d1[0];
          initial[frame_dofs[f] + 1] = d1[1];
        }
    frame_clamped.assign(frame_dofs.size(), false);
  }


  Vector3
  DrModel::initial_normal(const Element &e, const unsigned int end) const
  {
    const RodNetwork  &network    = *network_;
    const Rod         &rod        = network.rods()[e.rod];
    const unsigned int n          = rod.vertices.size();
    const unsigned int i          = (e.segment + end) % n;
    const auto         tangent_of = [&](const unsigned int s) -> Vector3 {
      return (network.vertex(rod.vertices[(s + 1) % n]) -
              network.vertex(rod.vertices[s]))
        .normalized();
    };
    Vector3 tangent = Vector3::Zero();
    if (rod.closed || i > 0)
      tangent += tangent_of((i + n - 1) % n);
    if (rod.closed || i + 1 < n)
      tangent += tangent_of(i);
    const std::string where =
      "DrModel: rod " + std::to_string(e.rod) + ", vertex " + std::to_string(i);
    if (!(tangent.norm() > 1e-8))
      throw std::invalid_argument(where + ": the rod folds back on "
                                          "itself there");
    tangent.normalize();
    const Vector3 hint = rod.director_hint;
    Vector3       d1   = hint - hint.dot(tangent) * tangent;
    if (!(d1.norm() > 1e-8 * hint.norm()))
      throw std::invalid_argument(
        where + ": the director d1 hint is parallel to the rod");
    d1.normalize();
    if (d1[2] < 0)
      d1 = -d1;
    if (!(d1[2] >= min_normal_z))
      throw std::invalid_argument(
        where + ": the normal d1 lies (nearly) in the xy plane, where the "
                "element's "
                "normal (n_x, n_y, sqrt(1 - n_x^2 - n_y^2)) is singular; turn "
                "the structure or choose a director hint with a z component");
    return d1;
  }


  void
  DrModel::clamp_vertex(const std::string &name, const unsigned int vertex)
  {
    Support s;
    s.name     = name;
    s.vertices = {vertex};
    s.fixed    = {{{true, true, true}}};
    s.clamped  = true;
    for (unsigned int c = 0; c < 3; ++c)
      {
        fixed_dofs[position_dof(vertex, c)] = 0.0;
        fixed_dofs[frame_dof(vertex, c)]    = 0.0;
      }
    frame_clamped[frame_node[vertex]] = true;
    support_list.push_back(s);
  }


  void
  DrModel::clamp_end(const std::string &name,
                     const unsigned int rod_index,
                     const bool         at_start)
  {
    require_not_finalized("DrModel::clamp_end \"" + name + "\"");
    if (rod_index >= network_->rods().size())
      throw std::invalid_argument("support \"" + name + "\": rod " +
                                  std::to_string(rod_index) +
                                  " does not exist");
    const Rod &rod = network_->rods()[rod_index];
    if (rod.closed)
      throw std::invalid_argument("support \"" + name + "\": rod " +
                                  std::to_string(rod_index) +
                                  " is closed and has no end to clamp");
    clamp_vertex(name, at_start ? rod.vertices.front() : rod.vertices.back());
  }


  void
  DrModel::clamp_junction(const std::string &name, const unsigned int junction)
  {
    require_not_finalized("DrModel::clamp_junction \"" + name + "\"");
    if (junction >= network_->junctions().size())
      throw std::invalid_argument("support \"" + name + "\": junction " +
                                  std::to_string(junction) + " does not exist");
    const Junction &j = network_->junctions()[junction];
    if (!j.has_rotation())
      throw std::invalid_argument(
        "support \"" + name + "\": junction \"" + j.name +
        "\" is pinned, so each rod end turns on its own there and there is "
        "no rotation to hold; clamp the rod ends one by one (<rod>:start or "
        "<rod>:end) or make the junction clamped");
    clamp_end(name, j.ends.front().rod, j.ends.front().at_start);
  }


  void
  DrModel::fix_components(const std::string         &name,
                          const unsigned int         vertex,
                          const std::array<bool, 3> &mask,
                          const Vector3             &displacement)
  {
    require_not_finalized("DrModel::fix_components \"" + name + "\"");
    const Support s = vertex_support(name, vertex, mask);
    for (unsigned int c = 0; c < 3; ++c)
      if (mask[c])
        fixed_dofs[position_dof(vertex, c)] = displacement[c];
    support_list.push_back(s);
  }


  void
  DrModel::add_rotational_loads(
    const std::vector<SupportsAndLoads::AxisLoad> &rotations,
    const std::vector<SupportsAndLoads::AxisLoad> &moments)
  {
    if (!rotations.empty() || !moments.empty())
      throw std::invalid_argument(
        "Supports/Prescribed rotations and Loads/Moments act on junction "
        "quaternions, which the dynamic relaxation element does not have");
  }


  void
  DrModel::add_point_force(const unsigned int vertex, const Vector3 &force)
  {
    require_not_finalized("DrModel::add_point_force at vertex " +
                          std::to_string(vertex));
    loads.add_point_force(*network_, vertex, force);
  }


  void
  DrModel::add_held_point_force(const unsigned int vertex, const Vector3 &)
  {
    throw std::invalid_argument(
      "held point force at vertex " + std::to_string(vertex) +
      ": dynamic relaxation ramps every load with the load factor");
  }


  void
  DrModel::add_distributed_force(const unsigned int rod,
                                 const Vector3     &force_per_length)
  {
    require_not_finalized("DrModel::add_distributed_force on rod " +
                          std::to_string(rod));
    loads.add_distributed_force(*network_, rod, force_per_length);
  }


  void
  DrModel::finalize()
  {
    if (finalized)
      throw std::logic_error("DrModel::finalize called twice");
    add_anchors();
    build_element_stencils();

    fixed_mask.assign(n_dofs(), false);
    for (const auto &[dof, value] : fixed_dofs)
      fixed_mask[dof] = true;
    share = std::make_unique<DrProcessShare>(
      communicator,
      elements.size(),
      n_dr_element_dofs,
      [this](const unsigned int e) { return elements[e].dofs.data(); },
      fixed_mask);

    // Dead loads, distributed ones lumped with half of each element.
    f_ext.reinit(n_dofs());
    const std::vector<Vector3> forces = loads.vertex_forces(*network_);
    for (unsigned int v = 0; v < forces.size(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        f_ext[position_dof(v, c)] += forces[v][c];
    finalized = true;
  }


  void
  DrModel::add_anchors()
  {
    // A clamped frame is measured from a fixed point where its reference
    // element's far end starts, so that n_r = 0 holds the chord's rotation
    // about the normal.
    anchor_dofs.assign(frame_dofs.size(), invalid);
    for (unsigned int f = 0; f < frame_dofs.size(); ++f)
      if (frame_clamped[f])
        {
          anchor_dofs[f] = initial.size();
          for (unsigned int c = 0; c < 3; ++c)
            {
              fixed_dofs[initial.size()] = 0.0;
              initial.push_back(network_->vertex(far_vertex[f])[c]);
            }
        }
  }


  void
  DrModel::build_element_stencils()
  {
    const DrVector zero(n_dofs());
    for (Element &e : elements)
      {
        for (unsigned int end = 0; end < 2; ++end)
          {
            const unsigned int v = e.vertices[end];
            const unsigned int f = frame_node[v];
            const unsigned int far =
              anchor_dofs[f] != invalid ?
                anchor_dofs[f] :
                position_dofs[position_node[far_vertex[f]]];
            for (unsigned int c = 0; c < 3; ++c)
              {
                e.dofs[node_block[end] + dr_dof::position + c] =
                  position_dof(v, c);
                e.dofs[node_block[end] + dr_dof::normal_x + c] =
                  frame_dof(v, c);
                e.dofs[far_block[end] + c] = far + c;
              }
          }
        try
          {
            e.reference = dr_beam_reference(local_dofs(e, zero));
          }
        catch (const std::invalid_argument &error)
          {
            throw std::invalid_argument(
              "DrModel: rod " + std::to_string(e.rod) + ", segment " +
              std::to_string(e.segment) + ": " + error.what());
          }
      }
  }


  dealii::ArrayView<const DrModel::Element>
  DrModel::own_elements() const
  {
    const auto [first, end] = share->elements();
    return {elements.data() + first, end - first};
  }


  DrElementVector
  DrModel::local_dofs(const Element &e, const DrVector &u) const
  {
    DrElementVector local;
    for (unsigned int i = 0; i < n_dr_element_dofs; ++i)
      local[i] = initial[e.dofs[i]] + u[e.dofs[i]];
    return local;
  }


  void
  DrModel::residual(const DrVector &u,
                    const double    load_factor,
                    DrVector       &r) const
  {
    if (!finalized)
      throw std::logic_error("DrModel::residual before finalize()");
    const phase_times::Scope phase(phase_times::Phase::gradient_assembly);
    r.reinit(n_dofs());
    DrElementVector gradient;
    for (const Element &e : own_elements())
      {
        const DrBeamKinematics kinematics(local_dofs(e, u), e.reference);
        DrBeamStress           stress;
        dr_beam_energy(stiffness[e.rod],
                       e.reference.rest_length,
                       kinematics.strains(),
                       &stress);
        kinematics.pull_back(stress, gradient);
        for (unsigned int i = 0; i < n_dr_element_dofs; ++i)
          r[e.dofs[i]] += gradient[i];
      }
    share->add_shared(r);
    r.add(-load_factor, f_ext);
  }


  double
  DrModel::elastic_energy(const DrVector &u, double) const
  {
    if (!finalized)
      throw std::logic_error("DrModel::energy before finalize()");
    const phase_times::Scope phase(phase_times::Phase::energy_assembly);
    double                   total = 0;
    for (const Element &e : own_elements())
      total += dr_beam_energy(
        stiffness[e.rod],
        e.reference.rest_length,
        DrBeamKinematics(local_dofs(e, u), e.reference).strains());
    return share->sum(total);
  }


  double
  DrModel::energy(const DrVector &u, const double load_factor) const
  {
    // The work of the loads counts each DoF on its owner.
    double work = 0;
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (share->owns(i))
        work += f_ext[i] * u[i];
    return elastic_energy(u, load_factor) - load_factor * share->sum(work);
  }


  void
  DrModel::apply_boundary_values(DrVector &u, const double load_factor) const
  {
    for (const auto &[dof, value] : fixed_dofs)
      u[dof] = load_factor * value;
  }


  void
  DrModel::fictitious_masses(const DrVector &u,
                             const double    mass_scaling,
                             DrVector       &masses) const
  {
    if (!finalized)
      throw std::logic_error("DrModel::fictitious_masses before finalize()");
    require_positive(mass_scaling, "fictitious masses: the mass scaling");
    DrVector row_sums(n_dofs());
    for (const Element &e : own_elements())
      {
        const DrElementVector bound = element_row_sum_bound(local_dofs(e, u),
                                                            e.reference,
                                                            stiffness[e.rod]);
        for (unsigned int i = 0; i < n_dr_element_dofs; ++i)
          row_sums[e.dofs[i]] += bound[i];
      }
    share->add_shared(row_sums);
    equalize_node_row_sums(row_sums);

    // A DoF without stiffness (none in a connected model) gets the largest
    // mass rather than a division by zero.
    const double largest = share->max(row_sums.linfty_norm());
    masses.reinit(n_dofs());
    for (unsigned int i = 0; i < n_dofs(); ++i)
      masses[i] =
        0.5 * mass_scaling * (row_sums[i] > 0 ? row_sums[i] : largest);
  }


  void
  DrModel::equalize_node_row_sums(DrVector &row_sums) const
  {
    // Elements turn during a relaxation, and with them the directions in
    // which a node is stiff: an axial row sum EA/L0 along a straight rod
    // becomes a bending one 24 EI/L0^3 when its elements turn by 90 degrees.
    // Masses that are the same for x, y and z (and for n_x, n_y, which trade
    // twist and tilt as the element turns about the normal) keep the
    // bound under such rotations, as in Barnes' isotropic nodal masses.
    for (const unsigned int d : position_dofs)
      {
        const double largest =
          std::max({row_sums[d], row_sums[d + 1], row_sums[d + 2]});
        for (unsigned int c = 0; c < 3; ++c)
          row_sums[d + c] = largest;
      }
    for (const unsigned int d : frame_dofs)
      row_sums[d] = row_sums[d + 1] = std::max(row_sums[d], row_sums[d + 1]);
  }


  Vector3
  DrModel::position(const DrVector &u, const unsigned int vertex) const
  {
    return network_->vertex(vertex) + Vector3(u[position_dof(vertex, 0)],
                                              u[position_dof(vertex, 1)],
                                              u[position_dof(vertex, 2)]);
  }


  Vector3
  DrModel::normal(const DrVector &u, const unsigned int vertex) const
  {
    const unsigned int x = frame_dof(vertex, 0), y = frame_dof(vertex, 1);
    return dr_normal(initial[x] + u[x], initial[y] + u[y]);
  }


  Vector3
  DrModel::reaction(const Support  &s,
                    const DrVector &u,
                    const double    load_factor) const
  {
    DrVector r;
    residual(u, load_factor, r);
    return support_force(s, r);
  }


  Vector3
  DrModel::support_force(const Support &s, const DrVector &r) const
  {
    // At a fixed DoF the support force F balances the residual:
    // dPhi/du - F = 0. A clamp also holds its anchor.
    Vector3 total = Vector3::Zero();
    for (unsigned int k = 0; k < s.vertices.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        {
          if (s.fixed[k][c])
            total[c] += r[position_dof(s.vertices[k], c)];
          if (s.clamped)
            total[c] += r[anchor_dofs[frame_node[s.vertices[k]]] + c];
        }
    return total;
  }


  Vector3
  DrModel::reaction_moment(const Support &,
                           const DrVector &,
                           const double) const
  {
    throw std::logic_error("DrModel: the dynamic relaxation element has no "
                           "reaction moments");
  }


  Vector3
  DrModel::reaction_moment(const unsigned int,
                           const DrVector &,
                           const double) const
  {
    throw std::logic_error("DrModel: the dynamic relaxation element has no "
                           "junction rotations");
  }


  Quaternion
  DrModel::junction_rotation(const DrVector &, const unsigned int) const
  {
    throw std::logic_error("DrModel: the dynamic relaxation element has no "
                           "junction rotations");
  }


  OutputFields
  DrModel::output_fields(const DrVector &u) const
  {
    OutputFields        output;
    OutputFields::Field normals{"normal", 3, {}, "-"};
    for (unsigned int v = 0; v < network_->n_vertices(); ++v)
      {
        output.displacement.emplace_back(u[position_dof(v, 0)],
                                         u[position_dof(v, 1)],
                                         u[position_dof(v, 2)]);
        const Vector3 n = normal(u, v);
        normals.values.insert(normals.values.end(), n.data(), n.data() + 3);
      }
    output.vertex_fields = {normals};
    return output;
  }
} // namespace rodnet
