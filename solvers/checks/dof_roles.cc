#include <solvers/checks/dof_roles.h>

namespace rodnet
{
  namespace
  {
    /// Per cell of @p network: whether a hinge or junction element of
    /// @p layout sees its twist.
    std::vector<bool>
    twists_seen(const RodNetwork &network, const DofLayout &layout)
    {
      std::vector<bool> seen(network.n_segments(), false);
      for (const HingeStencil &h : layout.hinges())
        seen[h.segment_prev] = seen[h.segment_next] = true;
      for (const JunctionStencil &e : layout.junctions())
        seen[e.segment] = true;
      return seen;
    }

    /// The kind of a DoF that a family declares as @p role; the components
    /// of a rotation are marked by junction afterwards.
    DofRoles::Kind
    kind_of(const DofRole role)
    {
      switch (role)
        {
          case DofRole::shape:
            return DofRoles::Kind::shape;
          case DofRole::multiplier:
            return DofRoles::Kind::multiplier;
          default:
            return DofRoles::Kind::inert;
        }
    }

    /// (rod, place along it) of each vertex and each cell of @p network.
    void
    set_rod_places(
      const RodNetwork                                   &network,
      std::vector<std::pair<unsigned int, unsigned int>> &vertex_places,
      std::vector<std::pair<unsigned int, unsigned int>> &cell_places)
    {
      vertex_places.resize(network.n_vertices());
      cell_places.resize(network.n_segments());
      for (unsigned int r = 0; r < network.rods().size(); ++r)
        {
          const Rod &rod = network.rods()[r];
          for (unsigned int k = 0; k < rod.vertices.size(); ++k)
            vertex_places[rod.vertices[k]] = {r, k};
          for (unsigned int k = 0; k < rod.segments.size(); ++k)
            cell_places[rod.segments[k]] = {r, k};
        }
    }
  } // namespace

  DofRoles::DofRoles(const SolvableModel &model)
      : model(model)
  {
    const DofLayout  &layout  = model.layout();
    const RodNetwork &network = model.network();
    kinds.assign(layout.n_dofs(), Kind::inert);
    owners.assign(layout.n_dofs(), 0);
    components.assign(layout.n_dofs(), 0);
    declared.assign(layout.n_dofs(), nullptr);
    for (unsigned int v = 0; v < network.n_vertices(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const global_dof_index d = layout.vertex_dof(v, c);
          kinds[d]                 = Kind::position;
          owners[d]                = v;
          components[d]            = c;
        }
    for (const auto &copy : layout.junction_constraints().get_lines())
      kinds[copy.index] = Kind::inert;

    // A twist that no hinge or junction element sees carries nothing.
    const unsigned int      n_cells = network.n_segments();
    const std::vector<bool> seen    = twists_seen(network, layout);
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      {
        owners[layout.twist_dof(cell)] = cell;
        if (seen[cell])
          kinds[layout.twist_dof(cell)] = Kind::twist;
      }
    mark_declared_dofs(layout);
    // A quaternion's vector part turns the junction; its real part is the
    // gauge of the unit norm.
    for (unsigned int j = 0; j < network.junctions().size(); ++j)
      if (layout.has_rotation_dofs(j))
        for (unsigned int c = 1; c < 4; ++c)
          {
            const global_dof_index d = layout.rotation_dof(j, c);
            kinds[d]                 = Kind::quaternion;
            owners[d]                = j;
            components[d]            = c;
          }

    set_rod_places(network, vertex_places, cell_places);
  }

  void
  DofRoles::mark_declared_dofs(const DofLayout &layout)
  {
    // The families' own blocks say what their DoFs are.
    for (const DofBlock &block : layout.declared_blocks())
      for (unsigned int i = 0; i < block.dofs.size(); ++i)
        {
          const global_dof_index d = block.first + i;
          kinds[d]                 = kind_of(block.dofs[i].role);
          owners[d]                = block.dofs[i].vertex;
          declared[d]              = &block.dofs[i];
        }
  }

  std::string
  DofRoles::vertex_name(const unsigned int v) const
  {
    const auto [r, k]     = vertex_places[v];
    const Rod        &rod = model.network().rods()[r];
    const std::string where =
      k == 0 ?
        "start" :
        (k + 1 == rod.vertices.size() && !rod.closed ? "end" :
                                                       std::to_string(k));
    return std::to_string(r) + ":" + where;
  }

  std::string
  DofRoles::describe(const global_dof_index dof) const
  {
    const RodNetwork &network = model.network();
    if (declared[dof] != nullptr)
      return declared[dof]->label;
    switch (kinds[dof])
      {
        case Kind::quaternion:
          return "junction \"" + network.junctions()[owners[dof]].name + "\"";
        case Kind::position:
          {
            const auto [r, k]          = vertex_places[owners[dof]];
            const Rod         &rod     = network.rods()[r];
            const unsigned int n       = rod.segments.size();
            unsigned int       segment = k < n ? k : n - 1;
            if ((k > 0 || rod.closed) && k < n)
              {
                const unsigned int before = (k + n - 1) % n;
                if (model.configuration().rest_length(rod.segments[before]) <
                    model.configuration().rest_length(rod.segments[k]))
                  segment = before;
              }
            return "rod " + std::to_string(r) + " segment " +
                   std::to_string(segment) + " (vertex " + std::to_string(k) +
                   ")";
          }
        default:
          {
            const auto [r, s] = cell_places[owners[dof]];
            return "rod " + std::to_string(r) + " segment " +
                   std::to_string(s) + " (its twist)";
          }
      }
  }
} // namespace rodnet
