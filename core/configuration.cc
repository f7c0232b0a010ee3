#include <core/configuration.h>
#include <elements/parallel_transport.h>

#include <Epetra_BlockMap.h>
#include <Epetra_FEVector.h>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    /// The undeformed material frame D^j of segment @p j of rod @p r
    /// (@p rod), whose edge is @p e: d1 is the rod's director hint normal
    /// to the tangent, turned where the rod's frame turns.
    Quaternion
    undeformed_segment_frame(const Rod         &rod,
                             const unsigned int r,
                             const unsigned int j,
                             const Vector3     &e)
    {
      const Vector3 t  = e / e.norm();
      Vector3       d1 = rod.director_hint - rod.director_hint.dot(t) * t;
      if (!(d1.norm() > 1e-8 * rod.director_hint.norm()))
        throw std::invalid_argument(
          "rod " + std::to_string(r) + ", segment " + std::to_string(j) +
          ": the director d1 hint is parallel to the segment; choose "
          "another \"Director d1\"");
      d1.normalize();
      // A turned frame turns evenly along a closed rod.
      const double turn = M_PI * rod.frame_half_turns * j / rod.segments.size();

      d1 = std::cos(turn) * d1 + std::sin(turn) * t.cross(d1);
      Matrix3 R;
      R.col(0) = d1;
      R.col(1) = t.cross(d1);
      R.col(2) = t;
      return Quaternion(R).normalized();
    }

    /// The rest length and the undeformed frame of each segment of the
    /// rods of @p network, per cell, between the vertices @p undeformed.
    void
    set_undeformed_segments(const RodNetwork           &network,
                            const std::vector<Vector3> &undeformed,
                            std::vector<double>        &rest_lengths,
                            std::vector<Quaternion>    &frames)
    {
      const auto &rods = network.rods();
      for (unsigned int r = 0; r < rods.size(); ++r)
        {
          const Rod &rod = rods[r];
          for (unsigned int j = 0; j < rod.segments.size(); ++j)
            {
              const unsigned int cell = rod.segments[j];
              const Vector3      e =
                undeformed[rod.vertices[(j + 1) % rod.vertices.size()]] -
                undeformed[rod.vertices[j]];
              rest_lengths[cell] = e.norm();
              frames[cell]       = undeformed_segment_frame(rod, r, j, e);
            }
        }
    }

    /// The zero displacement of @p layout's DoFs: a scratch vector of this
    /// process alone.
    dealii::TrilinosWrappers::MPI::Vector
    zero_displacement(const DofLayout &layout)
    {
      return dealii::TrilinosWrappers::MPI::Vector(dealii::complete_index_set(
                                                     layout.n_dofs()),
                                                   MPI_COMM_SELF);
    }
  } // namespace

  Configuration::Configuration(
    const RodNetwork                          &network_,
    const DofLayout                           &layout_,
    const std::vector<const HingeKernel *>    &rod_kernels,
    const std::vector<const JunctionKernel *> &rod_junction_kernels)
      : network(&network_)
      , layout(&layout_)
  {
    const unsigned int n_cells = network->n_segments();
    rest_lengths.resize(n_cells);
    frames.resize(n_cells);
    twist_at_reference.assign(n_cells, 0.0);
    for (unsigned int v = 0; v < network->n_vertices(); ++v)
      undeformed.push_back(network->vertex(v));
    segment_index.resize(n_cells);
    for (unsigned int s = 0; s < layout->segments().size(); ++s)
      segment_index[layout->segments()[s].cell] = s;
    set_undeformed_segments(*network, undeformed, rest_lengths, frames);

    add_hinge_references(rod_kernels);
    add_junction_references(rod_junction_kernels);
    set_reference_twists_and_natural_strains();
  }


  void
  Configuration::add_hinge_references(
    const std::vector<const HingeKernel *> &rod_kernels)
  {
    for (const HingeStencil &h : layout->hinges())
      {
        kernels.push_back(rod_kernels[h.rod]);
        voronoi_lengths.push_back(
          0.5 * (rest_lengths[h.segment_prev] + rest_lengths[h.segment_next]));
        closure_flips.push_back(closes_with_a_flip(h));
        HingeReference ref;
        hinge_refs.push_back(ref);
        set_hinge_frames(hinge_refs.size() - 1);
      }
  }


  void
  Configuration::add_junction_references(
    const std::vector<const JunctionKernel *> &rod_junction_kernels)
  {
    accumulated_rotations.assign(network->junctions().size(),
                                 Quaternion::Identity());
    for (const JunctionStencil &e : layout->junctions())
      {
        junction_kernels.push_back(rod_junction_kernels[e.rod]);
        junction_lengths.push_back(0.5 * rest_lengths[e.segment]);
        JunctionReference ref;
        ref.segment_frame = frames[e.segment];
        ref.ghost_frame   = frames[e.segment];
        ref.ghost_first   = e.ghost_first;
        junction_refs.push_back(ref);
      }
  }


  void
  Configuration::set_reference_twists_and_natural_strains()
  {
    // The reference twist of kernels that track it is that of the
    // undeformed configuration, which has zero displacement and turns no
    // junction (the junction family declares the quaternions later).
    const dealii::TrilinosWrappers::MPI::Vector zero =
      zero_displacement(*layout);
    for (unsigned int i = 0; i < hinge_refs.size(); ++i)
      hinge_refs[i].twist =
        kernels[i]->strains(hinge_dofs(zero, layout->hinges()[i]),
                            hinge_refs[i])[2];
    // Natural strains are the undeformed strains with the reference twist
    // just set (for the classic kernel, the twist of the undeformed rod).
    const auto &rods = network->rods();
    for (unsigned int i = 0; i < hinge_refs.size(); ++i)
      {
        const HingeStencil &h = layout->hinges()[i];
        hinge_natural_strains.push_back(
          rods[h.rod].natural_shape == NaturalShape::initial_geometry ?
            kernels[i]->strains(hinge_dofs(zero, h), hinge_refs[i]) :
            Vector3::Zero());
      }
    for (unsigned int i = 0; i < junction_refs.size(); ++i)
      junction_refs[i].twist = junction_kernels[i]->strains(
        junction_dofs_at_reference_rotation(zero, layout->junctions()[i]),
        junction_refs[i])[2];
  }

  bool
  Configuration::closes(const HingeStencil &h) const
  {
    const Rod &rod = network->rods()[h.rod];
    return rod.closed && h.segment_next == rod.segments.front() &&
           h.segment_prev == rod.segments.back();
  }


  bool
  Configuration::closes_with_a_flip(const HingeStencil &h) const
  {
    return closes(h) && network->rods()[h.rod].frame_half_turns % 2 == 1;
  }

  void
  Configuration::set_hinge_frames(const unsigned int i)
  {
    const HingeStencil &h    = layout->hinges()[i];
    hinge_refs[i].frame_prev = frames[h.segment_prev];
    hinge_refs[i].frame_next = frames[h.segment_next];
    // Past the closure of a Möbius band the first segment is met with
    // d1 -> -d1, d2 -> -d2: its frame turned by pi about its tangent.
    if (closure_flips[i])
      hinge_refs[i].frame_next =
        hinge_refs[i].frame_next * Quaternion(0.0, 0.0, 0.0, 1.0);
  }

  Vector3
  Configuration::position(const DofValues &u, const unsigned int v) const
  {
    return undeformed[v] + Vector3(u[layout->vertex_dof(v, 0)],
                                   u[layout->vertex_dof(v, 1)],
                                   u[layout->vertex_dof(v, 2)]);
  }

  HingeVector
  Configuration::hinge_dofs(const DofValues &u, const HingeStencil &hinge) const
  {
    HingeVector local;
    for (unsigned int b = 0; b < 3; ++b)
      local.segment<3>(4 * b) = position(u, hinge.vertices[b]);
    // Twist increments are measured from the reference (Korner eq. 2.8).
    local[3] = u[hinge.dofs[3]] - twist_at_reference[hinge.segment_prev];
    local[7] = u[hinge.dofs[7]] - twist_at_reference[hinge.segment_next];
    return local;
  }

  HingeVector
  Configuration::junction_dofs_at_reference_rotation(
    const DofValues       &u,
    const JunctionStencil &junction) const
  {
    HingeVector local;
    local.segment<3>(0) = position(u, junction.vertices[0]);
    local.segment<3>(3) = position(u, junction.vertices[1]);
    local[6] = u[junction.dofs[6]] - twist_at_reference[junction.segment];
    local.tail<4>() << 1.0, 0.0, 0.0, 0.0;
    return local;
  }

  HingeVector
  Configuration::junction_dofs(const DofValues       &u,
                               const JunctionStencil &junction) const
  {
    HingeVector local = junction_dofs_at_reference_rotation(u, junction);
    // Quaternion DoFs hold q - (1, 0, 0, 0).
    local[7] += u[junction.dofs[7]];
    for (unsigned int c = 1; c < 4; ++c)
      local[7 + c] = u[junction.dofs[7 + c]];
    return local;
  }

  Quaternion
  Configuration::junction_increment(
    const dealii::TrilinosWrappers::MPI::Vector &u,
    const unsigned int                           j) const
  {
    Quaternion q(1.0 + u[layout->rotation_dof(j, 0)],
                 u[layout->rotation_dof(j, 1)],
                 u[layout->rotation_dof(j, 2)],
                 u[layout->rotation_dof(j, 3)]);
    return q.normalized();
  }

  SegmentVector
  Configuration::segment_dofs(const DofValues      &u,
                              const SegmentStencil &segment) const
  {
    SegmentVector local;
    local.head<3>() = position(u, segment.vertices[0]);
    local.tail<3>() = position(u, segment.vertices[1]);
    return local;
  }

  double
  Configuration::segment_length(const DofValues   &u,
                                const unsigned int cell) const
  {
    const SegmentStencil &s = layout->segments()[segment_index[cell]];
    return (position(u, s.vertices[1]) - position(u, s.vertices[0])).norm();
  }

  Quaternion
  Configuration::director_frame(const dealii::TrilinosWrappers::MPI::Vector &u,
                                const unsigned int cell) const
  {
    const SegmentStencil &s = layout->segments()[segment_index[cell]];
    const Vector3         t =
      (position(u, s.vertices[1]) - position(u, s.vertices[0])).normalized();
    return current_director_frame(frames[cell],
                                  t,
                                  u[layout->twist_dof(cell)] -
                                    twist_at_reference[cell]);
  }

  void
  Configuration::reset_reference(const dealii::TrilinosWrappers::MPI::Vector &u)
  {
    // Strains of the kernels that track a reference twist must be read
    // before the frames change.
    std::vector<double> twists(hinge_refs.size());
    for (unsigned int i = 0; i < hinge_refs.size(); ++i)
      twists[i] = kernels[i]->strains(hinge_dofs(u, layout->hinges()[i]),
                                      hinge_refs[i])[2];
    std::vector<double> junction_twists(junction_refs.size());
    for (unsigned int i = 0; i < junction_refs.size(); ++i)
      junction_twists[i] =
        junction_kernels[i]->strains(junction_dofs(u, layout->junctions()[i]),
                                     junction_refs[i])[2];

    // Ghost frames turn with their junction (L&K eq. 5 and 6 compose to
    // d~ = R(q) d~*), and the increment joins the accumulated rotation.
    for (unsigned int i = 0; i < junction_refs.size(); ++i)
      junction_refs[i].ghost_frame =
        (junction_increment(u, layout->junctions()[i].junction) *
         junction_refs[i].ghost_frame)
          .normalized();
    for (unsigned int j = 0; j < accumulated_rotations.size(); ++j)
      if (layout->has_rotation_dofs(j))
        accumulated_rotations[j] = junction_rotation(u, j);

    std::vector<Quaternion> new_frames(frames.size());
    for (unsigned int cell = 0; cell < frames.size(); ++cell)
      new_frames[cell] = director_frame(u, cell).normalized();
    frames = new_frames;
    for (unsigned int cell = 0; cell < frames.size(); ++cell)
      twist_at_reference[cell] = u[layout->twist_dof(cell)];

    for (unsigned int i = 0; i < hinge_refs.size(); ++i)
      {
        set_hinge_frames(i);
        hinge_refs[i].twist = twists[i];
      }
    for (unsigned int i = 0; i < junction_refs.size(); ++i)
      {
        junction_refs[i].segment_frame = frames[layout->junctions()[i].segment];
        junction_refs[i].twist         = junction_twists[i];
      }
  }
} // namespace rodnet
