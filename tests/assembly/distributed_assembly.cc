// Assembly on several processes (RodModel::finalize on a communicator of
// P processes, assemble_distributed): each process evaluates the stencils
// that couple its DoFs and adds its own rows. The energy, the residual and
// the tangent, rows of fixed DoFs included, equal those of the same model
// on one process (MPI_COMM_SELF) up to the order of the additions
// (1e-12 relative), on a welded square lattice with a clamped junction, a
// pinned vertex and a point force, in a random state. Runs on 1, 2 and 3
// processes (tests/CMakeLists.txt, RODNET_MPI_TESTS); 3 split it unevenly.
#include <deal.II/base/mpi.h>

#include <common/square_lattice_model.h>
#include <core/rod_model.h>
#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>
#include <materials/linear_elastic_rod.h>

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace
{
  using namespace rodnet;

  /// A 3 x 2 welded square lattice of 4 segments per beam on
  /// @p communicator, clamped at its first junction, pinned at its last
  /// vertex, pulled at vertex 7.
  std::unique_ptr<RodModel>
  welded_test_lattice(const MPI_Comm communicator)
  {
    auto model =
      rodnet::testing::square_lattice_model(3,
                                            2,
                                            4,
                                            RodStiffness{100, 2, 3, 1.5},
                                            communicator);
    const unsigned int n_vertices = model->network().n_vertices();
    model->clamp_junction("corner", 0);
    model->fix_components("pin", n_vertices - 1, {true, true, true});
    model->add_point_force(7, Vector3(0.1, -0.2, 0.3));
    model->finalize();
    return model;
  }

  /// The same random state on every process, in @p model's vector.
  VectorType
  random_lattice_state(const RodModel &model)
  {
    VectorType                             u = model.create_vector();
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> small(-0.05, 0.05);
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const double value = small(random);
        if (model.locally_owned_dofs().is_element(i))
          u[i] = value;
      }
    u.compress(dealii::VectorOperation::insert);
    return u;
  }

  struct AssembledOnProcesses
  {
    AssembledOnProcesses(const RodModel &model)
        : u(random_lattice_state(model))
        , residual(model.create_vector())
    {
      model.initialize_matrix(tangent);
      energy         = model.assemble(u, 0.7, &residual, &tangent);
      elastic_energy = model.elastic_energy(u, 0.7);
    }
    VectorType u, residual;
    MatrixType tangent;
    double     energy, elastic_energy;
  };

  TEST(DistributedAssembly, EveryProcessHasTheRowsOfOneProcess)
  {
    const auto serial_model      = welded_test_lattice(MPI_COMM_SELF);
    const auto distributed_model = welded_test_lattice(MPI_COMM_WORLD);
    const AssembledOnProcesses serial(*serial_model),
      distributed(*distributed_model);
    EXPECT_GT(distributed_model->locally_owned_dofs().n_elements(), 0u);
    EXPECT_NEAR(distributed.energy,
                serial.energy,
                1e-12 * std::abs(serial.energy));
    EXPECT_NEAR(distributed.elastic_energy,
                serial.elastic_energy,
                1e-12 * std::abs(serial.elastic_energy));
    const double r_scale = serial.residual.linfty_norm();
    const double k_scale = serial.tangent.linfty_norm();
    ASSERT_GT(r_scale, 0);
    for (const global_dof_index i : distributed_model->locally_owned_dofs())
      {
        EXPECT_NEAR(distributed.residual[i],
                    serial.residual[i],
                    1e-12 * r_scale)
          << "row " << i;
        EXPECT_EQ(distributed.tangent.row_length(i),
                  serial.tangent.row_length(i))
          << "row " << i;
        for (auto entry = serial.tangent.begin(i);
             entry != serial.tangent.end(i);
             ++entry)
          EXPECT_NEAR(distributed.tangent.el(i, entry->column()),
                      entry->value(),
                      1e-12 * k_scale)
            << "entry (" << i << ", " << entry->column() << ")";
      }
  }

  TEST(DistributedAssembly, SupportsSetTheValuesOfOneProcess)
  {
    // The supports write DoFs that other processes own and read the frames
    // of segments anywhere (RodModel::replica()).
    std::unique_ptr<RodModel> models[2];
    const MPI_Comm communicators[2] = {MPI_COMM_SELF, MPI_COMM_WORLD};
    VectorType     states[2];
    for (unsigned int k = 0; k < 2; ++k)
      {
        models[k] =
          rodnet::testing::square_lattice_model(3,
                                                2,
                                                4,
                                                RodStiffness{100, 2, 3, 1.5},
                                                communicators[k]);
        const unsigned int n_vertices = models[k]->network().n_vertices();
        models[k]->clamp_junction("turned", 0);
        models[k]->prescribe_rotation(0, Vector3::UnitZ(), 0.4);
        models[k]->fix_components("moved",
                                  n_vertices - 1,
                                  {true, false, true},
                                  Vector3(0.2, 0, -0.1));
        models[k]->finalize();
        states[k] = random_lattice_state(*models[k]);
        models[k]->apply_boundary_values(states[k], 0.5);
      }
    for (const global_dof_index i : models[1]->locally_owned_dofs())
      EXPECT_NEAR(states[1][i], states[0][i], 1e-15) << "DoF " << i;
    EXPECT_GT(states[0].linfty_norm(), 0.05);
  }

  TEST(DistributedAssembly, APartitionThatIsNotOneIsRefusedOnEveryProcess)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
      GTEST_SKIP() << "one process: every contiguous range is its share";
    auto network =
      std::move(build_rod_network(network_generators::square_lattice(2, 2, 1.0),
                                  3,
                                  "simple")
                  .network);
    const unsigned int n_rods = network->rods().size();
    RodModel           model(std::move(network),
                   std::vector<std::shared_ptr<const RodMaterial>>(
                     n_rods,
                     std::make_shared<LinearElasticRod>(
                       RodStiffness{100, 2, 3, 1.5})));
    // Every process claims the first half: they overlap.
    dealii::IndexSet overlapping(model.layout().n_dofs());
    overlapping.add_range(0, model.layout().n_dofs() / 2);
    try
      {
        model.finalize(overlapping);
        FAIL() << "an overlapping partition was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("not a partition"),
                  std::string::npos)
          << e.what();
      }
  }
} // namespace
