#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>

#include <core/dof_layout.h>

#include <algorithm>
#include <stdexcept>

namespace rodnet
{
  DofLayout::DofLayout(const RodNetwork &network)
      : fe_collection(
          dealii::FESystem<1, 3>(dealii::FE_Q<1, 3>(1),
                                 3,
                                 dealii::FE_DGQ<1, 3>(0),
                                 1),
          // The same structure of base elements, as deal.II's comparison
          // of the two elements at a shared vertex requires.
          dealii::FESystem<1, 3>(dealii::FE_Nothing<1, 3>(),
                                 3,
                                 dealii::FE_Nothing<1, 3>(),
                                 1))
      , handler(network.triangulation())
  {
    number_field_dofs(network);
    share_junction_vertices(network);

    // Handles inside a rod replace the hinge at their vertex.
    const auto                    &rods = network.rods();
    std::vector<std::vector<bool>> handle_inside(rods.size());
    for (unsigned int r = 0; r < rods.size(); ++r)
      handle_inside[r].assign(rods[r].vertices.size(), false);
    for (const Junction &junction : network.junctions())
      if (junction.interior)
        handle_inside[junction.interior->rod][junction.interior->index] = true;
    for (unsigned int r = 0; r < rods.size(); ++r)
      {
        add_segment_stencils(r, rods[r]);
        add_hinge_stencils(r, rods[r], handle_inside[r]);
      }
    add_junction_stencils(network);
  }


  void
  DofLayout::number_field_dofs(const RodNetwork &network)
  {
    for (const auto &cell : handler.active_cell_iterators())
      if (!RodNetwork::is_segment(*cell))
        cell->set_active_fe_index(1);
    handler.distribute_dofs(fe_collection);

    constexpr auto invalid = dealii::numbers::invalid_dof_index;
    vertex_dofs.assign(network.n_vertices(), {{invalid, invalid, invalid}});
    twist_dofs.assign(network.n_segments(), invalid);

    const dealii::FiniteElement<1, 3> &fe = segment_fe();
    std::vector<global_dof_index>      cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : segment_cells())
      {
        cell->get_dof_indices(cell_dofs);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int component =
              fe.system_to_component_index(i).first;
            if (component < 3)
              vertex_dofs[cell->vertex_index(i / fe.n_dofs_per_vertex())]
                         [component] = cell_dofs[i];
            else
              twist_dofs[cell->active_cell_index()] = cell_dofs[i];
          }
      }
  }


  void
  DofLayout::share_junction_vertices(const RodNetwork &network)
  {
    // The junction family declares the quaternions (add_block()).
    rotation_dofs.assign(network.junctions().size(),
                         dealii::numbers::invalid_dof_index);
    for (unsigned int j = 0; j < network.junctions().size(); ++j)
      junction_of_vertex[network.junctions()[j].vertex] = j;

    // x_end = x_junction for every other rod end at a junction; the
    // stencils then take the junction vertex's DoFs for the end.
    junction_identities.reinit(dealii::complete_index_set(n_dofs()));
    for (const Junction &junction : network.junctions())
      for (const RodEnd &end : junction.ends)
        {
          const unsigned int v = network.end_vertex(end);
          if (v == junction.vertex)
            continue;
          for (unsigned int c = 0; c < 3; ++c)
            {
              junction_identities.add_line(vertex_dofs[v][c]);
              junction_identities.add_entry(vertex_dofs[v][c],
                                            vertex_dofs[junction.vertex][c],
                                            1.0);
            }
          vertex_dofs[v] = vertex_dofs[junction.vertex];
        }
    junction_identities.close();
  }


  void
  DofLayout::add_segment_stencils(const unsigned int r, const Rod &rod)
  {
    const unsigned int n = rod.vertices.size();
    for (unsigned int j = 0; j < rod.segments.size(); ++j)
      {
        SegmentStencil s;
        s.rod      = r;
        s.cell     = rod.segments[j];
        s.vertices = {{rod.vertices[j], rod.vertices[(j + 1) % n]}};
        for (unsigned int c = 0; c < 3; ++c)
          {
            s.dofs[c]     = vertex_dofs[rod.vertices[j]][c];
            s.dofs[3 + c] = vertex_dofs[rod.vertices[(j + 1) % n]][c];
          }
        segment_list.push_back(s);
      }
  }


  void
  DofLayout::add_hinge_stencils(const unsigned int       r,
                                const Rod               &rod,
                                const std::vector<bool> &handle_inside)
  {
    // Hinge i sits at vertex i between segments i-1 and i; a closed rod
    // also has one at its first vertex.
    const unsigned int n     = rod.vertices.size();
    const unsigned int first = rod.closed ? 0 : 1;
    const unsigned int last  = rod.closed ? n : n - 1;
    for (unsigned int i = first; i < last; ++i)
      {
        if (handle_inside[i % n])
          continue;
        const unsigned int prev_segment =
          (i + rod.segments.size() - 1) % rod.segments.size();
        HingeStencil h;
        h.rod          = r;
        h.vertices     = {{rod.vertices[(i + n - 1) % n],
                           rod.vertices[i % n],
                           rod.vertices[(i + 1) % n]}};
        h.segment_prev = rod.segments[prev_segment];
        h.segment_next = rod.segments[i % rod.segments.size()];
        for (unsigned int c = 0; c < 3; ++c)
          {
            h.dofs[c]     = vertex_dofs[h.vertices[0]][c];
            h.dofs[4 + c] = vertex_dofs[h.vertices[1]][c];
            h.dofs[8 + c] = vertex_dofs[h.vertices[2]][c];
          }
        h.dofs[3] = twist_dofs[h.segment_prev];
        h.dofs[7] = twist_dofs[h.segment_next];
        hinge_list.push_back(h);
      }
  }


  void
  DofLayout::add_junction_stencils(const RodNetwork &network)
  {
    const auto &rods = network.rods();
    for (unsigned int j = 0; j < network.junctions().size(); ++j)
      {
        const Junction &junction = network.junctions()[j];
        if (!junction.has_rotation())
          continue;
        for (const RodEnd &end : junction.ends)
          {
            const Rod &rod = rods[end.rod];
            add_junction_stencil(j,
                                 end.rod,
                                 rod,
                                 end.at_start ? 0 : rod.segments.size() - 1,
                                 end.at_start);
          }
        // A handle inside a rod ties the segment before its vertex (the
        // ghost follows it) and the one after (the ghost comes first).
        if (junction.interior)
          {
            const auto [r, i]             = *junction.interior;
            const unsigned int n_segments = rods[r].segments.size();
            add_junction_stencil(j,
                                 r,
                                 rods[r],
                                 (i + n_segments - 1) % n_segments,
                                 false);
            add_junction_stencil(j, r, rods[r], i % n_segments, true);
          }
      }
  }


  void
  DofLayout::add_junction_stencil(const unsigned int junction,
                                  const unsigned int rod_index,
                                  const Rod         &rod,
                                  const unsigned int segment,
                                  const bool         ghost_first)
  {
    const unsigned int n = rod.vertices.size();
    JunctionStencil    s;
    s.rod         = rod_index;
    s.junction    = junction;
    s.ghost_first = ghost_first;
    s.vertices    = {{rod.vertices[segment], rod.vertices[(segment + 1) % n]}};
    s.segment     = rod.segments[segment];
    for (unsigned int c = 0; c < 3; ++c)
      {
        s.dofs[c]     = vertex_dofs[s.vertices[0]][c];
        s.dofs[3 + c] = vertex_dofs[s.vertices[1]][c];
      }
    s.dofs[6] = twist_dofs[s.segment];
    // The quaternion's DoFs, s.dofs[7..10], come with its block.
    s.dofs[7] = s.dofs[8] = s.dofs[9] = s.dofs[10] =
      dealii::numbers::invalid_dof_index;
    junction_list.push_back(s);
  }


  global_dof_index
  DofLayout::add_block(const std::string &owner, std::vector<DeclaredDof> dofs)
  {
    DofBlock block{owner, n_dofs(), std::move(dofs)};
    number_rotations(block);
    n_declared_dofs += block.dofs.size();
    blocks.push_back(std::move(block));
    // The identities are stored over all DoFs (a closed AffineConstraints
    // answers only for indices in its set).
    dealii::AffineConstraints<double> grown(
      dealii::complete_index_set(n_dofs()));
    for (const auto &line : junction_identities.get_lines())
      {
        grown.add_line(line.index);
        grown.add_entries(line.index, line.entries);
      }
    grown.close();
    junction_identities.clear();
    junction_identities.copy_from(grown);
    return blocks.back().first;
  }


  void
  DofLayout::number_rotations(const DofBlock &block)
  {
    // Checked whole before anything is recorded: a refused block leaves
    // the layout as it was.
    std::vector<std::pair<unsigned int, global_dof_index>> firsts;
    for (unsigned int i = 0; i < block.dofs.size(); ++i)
      {
        const DeclaredDof &dof = block.dofs[i];
        if (dof.role != DofRole::rotation)
          continue;
        const auto junction = junction_of_vertex.find(dof.vertex);
        const bool taken =
          junction != junction_of_vertex.end() &&
          (has_rotation_dofs(junction->second) ||
           std::any_of(firsts.begin(), firsts.end(), [&](const auto &f) {
             return f.first == junction->second;
           }));
        if (junction == junction_of_vertex.end() || taken ||
            i + 4 > block.dofs.size())
          throw std::logic_error(block.owner + ": " + dof.label +
                                 " is not the first of four components of "
                                 "a junction's rotation not yet declared");
        firsts.emplace_back(junction->second, block.first + i);
        i += 3;
      }
    for (const auto &[j, first] : firsts)
      rotation_dofs[j] = first;
    for (JunctionStencil &s : junction_list)
      if (has_rotation_dofs(s.junction))
        for (unsigned int c = 0; c < 4; ++c)
          s.dofs[7 + c] = rotation_dof(s.junction, c);
  }
} // namespace rodnet
