// The model on deal.II's own structures: each cell's material_id is its
// rod; a junction is the identity constraint x_end = x_junction of
// deal.II's AffineConstraints, so that FEValues on the model's DoFHandler
// see one continuous displacement through it; the model's vectors live on
// the communicator and the DoFs its caller gives it.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <common/ribbon_dofs.h>
#include <common/rod_models.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace rodnet;

namespace
{
  constexpr unsigned int n_layout_segments = 4;

  /// Three rods of length 1 from a hub at the origin, welded there (or
  /// tied as @p kind says), in the plane z = 0 (d1 = e_z).
  std::unique_ptr<RodNetwork>
  star(const JunctionKind kind = JunctionKind::welded)
  {
    auto network = std::make_unique<RodNetwork>();
    for (const Vector3 &end :
         {Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(-1, -1, 0).normalized()})
      network->add_rod(generators::straight(Vector3::Zero(),
                                            end,
                                            n_layout_segments),
                       false,
                       Vector3::UnitZ(),
                       "simple");
    network->add_junction("hub", kind, {{0, true}, {1, true}, {2, true}});
    return network;
  }

  /// The star clamped at the far end of rod 0, with an out-of-plane force
  /// at the far ends of rods 1 and 2, solved.
  struct SolvedStar
  {
    std::unique_ptr<RodModel> model;
    VectorType                u;

    SolvedStar()
    {
      model = rodnet::testing::elastic_model(star(), {1e3, 1.0, 1.0, 0.8});
      model->clamp_end("clamp", 0, false);
      model->add_point_force(model->network().rods()[1].vertices.back(),
                             Vector3(0, 0, 0.2));
      model->add_point_force(model->network().rods()[2].vertices.back(),
                             Vector3(0, 0, -0.1));
      model->finalize();
      u = model->create_vector();
      StaticSolver::Parameters parameters;
      parameters.n_steps = 2;
      StaticSolver(*model, parameters).run(u, [](const auto &, const auto &) {
      });
    }
  };
} // namespace

TEST(DealIILayout, EveryCellsMaterialIdIsItsRod)
{
  const auto  network = star();
  RodNetwork &n       = *network;
  n.create_triangulation();
  for (unsigned int r = 0; r < n.rods().size(); ++r)
    for (const unsigned int cell : n.rods()[r].segments)
      {
        using Cell = dealii::TriaActiveIterator<dealii::CellAccessor<1, 3>>;
        EXPECT_EQ(Cell(&n.triangulation(), 0, cell)->material_id(), r);
      }
}

TEST(DealIILayout, LinksTieTheOpenRodsIntoOnePieceAndCarryNoDofs)
{
  // The star's three rods, a ring and a separate rod: links from rod 0's
  // end to rod 1's start, 1 to 2 and 2 to 4; the ring (rod 3) stays apart.
  auto network = star();
  network->add_rod(generators::ring(Vector3(5, 0, 0),
                                    1.0,
                                    Vector3::UnitX(),
                                    Vector3::UnitY(),
                                    6),
                   true,
                   Vector3::UnitZ(),
                   "simple");
  network->add_rod(generators::straight(Vector3(0, 0, 3),
                                        Vector3(1, 0, 3),
                                        n_layout_segments),
                   false,
                   Vector3::UnitZ(),
                   "simple");
  const auto model =
    rodnet::testing::elastic_model(std::move(network), {1e3, 1.0, 1.0, 0.8});
  const RodNetwork  &n     = model->network();
  const auto        &rods  = n.rods();
  const unsigned int n_seg = 4 * n_layout_segments + 6;
  ASSERT_EQ(n.n_segments(), n_seg);
  ASSERT_EQ(n.triangulation().n_active_cells(), n_seg + 3);

  const std::vector<std::pair<unsigned int, unsigned int>> linked = {{0, 1},
                                                                     {1, 2},
                                                                     {2, 4}};
  using Cell = dealii::TriaActiveIterator<dealii::CellAccessor<1, 3>>;
  for (unsigned int k = 0; k < linked.size(); ++k)
    {
      const Cell link(&n.triangulation(), 0, n_seg + k);
      EXPECT_FALSE(RodNetwork::is_segment(*link));
      EXPECT_EQ(link->material_id(), RodNetwork::link_material_id);
      EXPECT_EQ(link->vertex_index(0), rods[linked[k].first].vertices.back());
      EXPECT_EQ(link->vertex_index(1), rods[linked[k].second].vertices.front());
    }

  // deal.II sees the open rods as one piece: a walk over face neighbours
  // from cell 0 reaches every cell but the ring's six.
  std::vector<bool> reached(n.triangulation().n_active_cells(), false);
  std::vector<Cell> front = {Cell(&n.triangulation(), 0, 0)};
  reached[0]              = true;
  while (!front.empty())
    {
      const Cell cell = front.back();
      front.pop_back();
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f) && !reached[cell->neighbor(f)->index()])
          {
            reached[cell->neighbor(f)->index()] = true;
            front.push_back(cell->neighbor(f));
          }
    }
  EXPECT_EQ(std::count(reached.begin(), reached.end(), true), n_seg + 3 - 6);

  // No DoFs on links: three per vertex and one twist per segment, and
  // segment_cells() walks the segments in their order.
  const DofLayout &layout = model->layout();
  EXPECT_EQ(layout.n_field_dofs(), 3 * n.n_vertices() + n_seg);
  unsigned int expected_index = 0;
  for (const auto &cell : layout.segment_cells())
    {
      EXPECT_EQ(cell->active_cell_index(), expected_index++);
      EXPECT_EQ(cell->get_fe().n_dofs_per_cell(), 7u);
    }
  EXPECT_EQ(expected_index, n_seg);
  using DofCell = dealii::DoFHandler<1, 3>::active_cell_iterator;
  for (unsigned int k = 0; k < linked.size(); ++k)
    {
      const DofCell link(&n.triangulation(),
                         0,
                         n_seg + k,
                         &layout.dof_handler());
      EXPECT_EQ(link->get_fe().n_dofs_per_cell(), 0u);
    }
}

TEST(DealIILayout, AJunctionIsAnIdentityConstraintOfTheOtherEnds)
{
  const SolvedStar   star;
  const RodModel    &model   = *star.model;
  const DofLayout   &layout  = model.layout();
  const RodNetwork  &network = model.network();
  const unsigned int hub     = network.junctions()[0].vertex;

  // Two of the three ends have their own vertex, tied component by
  // component to the hub's DoF.
  const auto &identities = layout.junction_constraints();
  EXPECT_EQ(identities.n_constraints(), 2u * 3u);
  for (unsigned int r = 0; r < 3; ++r)
    {
      const unsigned int v = network.rods()[r].vertices.front();
      if (v == hub)
        continue;
      for (unsigned int c = 0; c < 3; ++c)
        {
          dealii::types::global_dof_index own =
            dealii::numbers::invalid_dof_index;
          for (const auto &cell : layout.segment_cells())
            if (cell->material_id() == r && cell->vertex_index(0) == v)
              own = cell->vertex_dof_index(0, c);
          ASSERT_TRUE(identities.is_constrained(own));
          const auto &entries = *identities.get_constraint_entries(own);
          ASSERT_EQ(entries.size(), 1u);
          EXPECT_EQ(entries[0].first, layout.vertex_dof(hub, c));
          EXPECT_EQ(entries[0].second, 1.0);
          // The converged state carries the hub's value there.
          EXPECT_EQ(star.u[own], star.u[layout.vertex_dof(hub, c)]);
        }
    }

  // FEValues on the model's DoFHandler see the hub's displacement at the
  // hub end of every rod: one continuous field through the junction.
  const Vector3 hub_displacement =
    model.position(star.u, hub) - network.vertex(hub);
  ASSERT_GT(hub_displacement.norm(), 1e-3);
  const dealii::Vector<double>        values = model.field_values(star.u);
  dealii::FEValues<1, 3>              fe_values(layout.segment_fe(),
                                   dealii::QTrapezoid<1>(),
                                   dealii::update_values);
  std::vector<dealii::Vector<double>> at_points(2, dealii::Vector<double>(4));
  unsigned int                        n_hub_ends = 0;
  for (const auto &cell : layout.segment_cells())
    for (unsigned int k = 0; k < 2; ++k)
      if (network.vertex(cell->vertex_index(k)).isApprox(network.vertex(hub)))
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(values, at_points);
          for (unsigned int c = 0; c < 3; ++c)
            EXPECT_NEAR(at_points[k][c], hub_displacement[c], 1e-14)
              << "rod " << cell->material_id() << ", component " << c;
          ++n_hub_ends;
        }
  EXPECT_EQ(n_hub_ends, 3u);
}

TEST(DealIILayout, TheModelLivesOnItsCallersCommunicator)
{
  auto on_self = std::make_unique<RodModel>(
    star(),
    std::vector<std::shared_ptr<const RodMaterial>>(
      3,
      std::make_shared<LinearElasticRod>(RodStiffness{1e3, 1.0, 1.0, 0.8})),
    GhostSpin::exact,
    MPI_COMM_SELF);
  auto on_world = rodnet::testing::elastic_model(star(), {1e3, 1.0, 1.0, 0.8});
  for (RodModel *model : {on_self.get(), on_world.get()})
    {
      model->clamp_end("clamp", 0, false);
      model->add_point_force(1, Vector3(0, 0, 0.2));
    }
  on_world->finalize();
  on_self->finalize(dealii::complete_index_set(on_self->layout().n_dofs()));

  int comparison;
  MPI_Comm_compare(on_self->create_vector().get_mpi_communicator(),
                   MPI_COMM_SELF,
                   &comparison);
  EXPECT_TRUE(comparison == MPI_IDENT || comparison == MPI_CONGRUENT);
  EXPECT_EQ(on_self->locally_owned_dofs().n_elements(),
            on_self->layout().n_dofs());

  // The same residual on either communicator.
  VectorType u = on_world->create_vector();
  for (unsigned int i = 0; i < u.size(); ++i)
    u[i] = 1e-3 * std::sin(1.0 + i);
  u.compress(dealii::VectorOperation::insert);
  VectorType u_self = on_self->create_vector();
  for (unsigned int i = 0; i < u.size(); ++i)
    u_self[i] = u[i];
  u_self.compress(dealii::VectorOperation::insert);
  VectorType r_world = on_world->create_vector();
  VectorType r_self  = on_self->create_vector();
  on_world->assemble(u, 1.0, &r_world, nullptr);
  on_self->assemble(u_self, 1.0, &r_self, nullptr);
  ASSERT_GT(r_world.linfty_norm(), 0.0);
  for (unsigned int i = 0; i < u.size(); ++i)
    EXPECT_EQ(r_self[i], r_world[i]) << "DoF " << i;
}

TEST(DealIILayout, FinalizeRefusesDofsThatAreNotAllTheModels)
{
  auto model = rodnet::testing::elastic_model(star(), {1e3, 1.0, 1.0, 0.8});
  const auto       n = model->layout().n_dofs();
  dealii::IndexSet half(n);
  half.add_range(0, n / 2);
  try
    {
      model->finalize(half);
      FAIL() << "a partial set of DoFs on one process was accepted";
    }
  catch (const std::invalid_argument &error)
    {
      EXPECT_NE(std::string(error.what()).find("locally owned DoFs"),
                std::string::npos)
        << error.what();
    }
  EXPECT_THROW(model->finalize(dealii::complete_index_set(n + 1)),
               std::invalid_argument);
}

namespace
{
  TEST(DealIILayout, VectorsMadeBeforeFinalizeHoldEveryDof)
  {
    // A clamp reads its reference frame from such a vector before the
    // model is finalized (the Debug library refused the empty vector this
    // once was; the Release one read past its end).
    auto model = rodnet::testing::elastic_model(star(), {1e3, 1.0, 1.0, 0.8});
    const VectorType u = model->create_vector();
    EXPECT_EQ(u.size(), model->layout().n_dofs());
    EXPECT_EQ(u.locally_owned_elements().n_elements(),
              model->layout().n_dofs());
  }
} // namespace

TEST(DealIILayout, TheJunctionFamilyDeclaresTheQuaternions)
{
  // Two rotations: the welded hub, and a handle inside rod 1.
  auto network = star();
  network->create_triangulation();
  network->add_rotation_handle("knob", network->rods()[1].vertices[2]);
  auto model =
    rodnet::testing::elastic_model(std::move(network), {1e3, 1.0, 1.0, 0.8});
  model->clamp_end("clamp", 0, false);
  model->finalize();
  const DofLayout  &layout = model->layout();
  const RodNetwork &net    = model->network();
  const DofBlock   &block =
    rodnet::testing::declared_block(*model, "junction elements");

  // Right after the DoFHandler's: 3 rods of 5 own vertices (3 DoFs each)
  // and 12 segment twists.
  EXPECT_EQ(layout.n_field_dofs(), 3u * 5u * 3u + 12u);
  EXPECT_EQ(block.first, layout.n_field_dofs());
  ASSERT_EQ(block.dofs.size(), 8u);

  const DofRoles roles(*model);
  for (unsigned int j = 0; j < 2; ++j)
    for (unsigned int c = 0; c < 4; ++c)
      {
        const global_dof_index d   = block.first + 4 * j + c;
        const DeclaredDof     &dof = block.dofs[4 * j + c];
        EXPECT_EQ(layout.rotation_dof(j, c), d);
        EXPECT_EQ(dof.role, DofRole::rotation);
        EXPECT_EQ(dof.vertex, net.junctions()[j].vertex);
        EXPECT_EQ(roles.describe(d),
                  "junction \"" + net.junctions()[j].name + "\"");
        // The real part is the gauge of the unit norm, held at zero.
        EXPECT_EQ(roles.kind(d),
                  c == 0 ? DofRoles::Kind::inert : DofRoles::Kind::quaternion);
        EXPECT_EQ(model->constraints().is_constrained(d), c == 0);
        if (c > 0)
          {
            EXPECT_EQ(roles.owner(d), j);
            EXPECT_EQ(roles.component(d), c);
          }
      }

  // Three elements at the hub, two at the handle, each reading its
  // junction's quaternion.
  ASSERT_EQ(layout.junctions().size(), 5u);
  for (const JunctionStencil &element : layout.junctions())
    for (unsigned int c = 0; c < 4; ++c)
      EXPECT_EQ(element.dofs[7 + c], layout.rotation_dof(element.junction, c));
}

TEST(DealIILayout, APinnedJunctionHasNoQuaternion)
{
  auto model = rodnet::testing::elastic_model(star(JunctionKind::pinned),
                                              {1e3, 1.0, 1.0, 0.8});
  EXPECT_FALSE(model->layout().has_rotation_dofs(0));
  EXPECT_TRUE(model->layout().junctions().empty());
  EXPECT_EQ(model->layout().n_dofs(), model->layout().n_field_dofs());
  EXPECT_THROW(rodnet::testing::declared_block(*model, "junction elements"),
               std::logic_error);
}

namespace
{
  /// A family that declares a rotation at a vertex of its choice and has no
  /// stencils.
  class StrayRotation : public ElementFamily
  {
  public:
    explicit StrayRotation(const unsigned int vertex)
        : vertex(vertex)
    {
    }

    std::string
    name() const override
    {
      return "stray rotation";
    }

    unsigned int
    n_stencils() const override
    {
      return 0;
    }

    void
    get_dofs(unsigned int, std::vector<global_dof_index> &) const override
    {
    }

    void
    evaluate(unsigned int,
             const StencilState &,
             Derivatives,
             LocalContribution &) const override
    {
    }

    std::vector<DeclaredDof>
    own_dofs() const override
    {
      std::vector<DeclaredDof> q(4);
      for (DeclaredDof &component : q)
        {
          component.role   = DofRole::rotation;
          component.vertex = vertex;
          component.label  = "stray";
        }
      return q;
    }

  private:
    unsigned int vertex;
  };
} // namespace

TEST(DealIILayout, ARotationOffAJunctionOrDeclaredTwiceIsRefused)
{
  auto model = rodnet::testing::elastic_model(star(), {1e3, 1.0, 1.0, 0.8});
  const unsigned int inside = model->network().rods()[0].vertices[2];
  EXPECT_THROW(model->add_element_family(
                 std::make_unique<StrayRotation>(inside)),
               std::logic_error);
  // The hub's rotation is the junction family's already.
  EXPECT_THROW(model->add_element_family(std::make_unique<StrayRotation>(
                 model->network().junctions()[0].vertex)),
               std::logic_error);
}
