// The direct scatter (RodModel::assemble on one process) adds each local
// entry at the place in the compressed rows that ScatterPositions found
// once per sparsity pattern, or, for a family with rows too long for them,
// searches the row. Both must give what deal.II's
// AffineConstraints::distribute_local_to_global gives (assemble_into, the
// independent path), for every pattern and set of supports it is used with.

#include <common/rod_models.h>
#include <core/scatter_positions.h>

#include <cmath>
#include <gtest/gtest.h>

using namespace rodnet;

namespace
{
  constexpr unsigned int n_hub_segments = 3;

  /// @p n_rods rods of length 1 from a hub at the origin, welded there, in
  /// directions spread over a cone; clamped at the far end of rod 0, with
  /// a force at the far end of rod 1, at a state off equilibrium. A hub of
  /// 60 rods couples its rotation's DoFs with more than 255 others.
  std::unique_ptr<RodModel>
  hub_of_rods(const unsigned int n_rods)
  {
    auto                network = std::make_unique<RodNetwork>();
    std::vector<RodEnd> ends;
    for (unsigned int r = 0; r < n_rods; ++r)
      {
        const double  angle = 2 * M_PI * r / n_rods;
        const Vector3 end =
          Vector3(std::cos(angle), std::sin(angle), 0.3).normalized();
        network->add_rod(generators::straight(Vector3::Zero(),
                                              end,
                                              n_hub_segments),
                         false,
                         end.cross(Vector3::UnitZ()).normalized(),
                         "simple");
        ends.push_back({r, true});
      }
    network->add_junction("hub", JunctionKind::welded, ends);
    auto model =
      rodnet::testing::elastic_model(std::move(network), {1e3, 1.0, 1.0, 0.8});
    model->clamp_end("clamp", 0, false);
    model->add_point_force(model->network().rods()[1].vertices.back(),
                           Vector3(0, 0, 0.2));
    model->finalize();
    return model;
  }

  /// A state with every DoF moved a little, deterministically.
  VectorType
  perturbed_state(const RodModel &model)
  {
    VectorType u = model.create_vector();
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = 1e-2 * std::sin(1.7 * i + 0.3);
    u.compress(dealii::VectorOperation::insert);
    return u;
  }

  /// Expects @p direct (RodModel::assemble into a matrix with the model's
  /// pattern) to equal the deal.II path at @p u, entry by entry.
  void
  expect_as_deal_ii(const RodModel   &model,
                    const VectorType &u,
                    const bool        apply_constraints,
                    MatrixType       &direct)
  {
    VectorType r_direct = model.create_vector();
    model.assemble(u, 1.0, &r_direct, &direct, apply_constraints);

    MatrixType mapped;
    model.initialize_matrix(mapped);
    VectorType r_mapped = model.create_vector();
    model.assemble_into(u,
                        1.0,
                        SystemBlock::at_offset(model.layout().n_dofs(), 0),
                        &r_mapped,
                        &mapped,
                        apply_constraints);

    const double scale = mapped.frobenius_norm();
    ASSERT_GT(scale, 1.0);
    unsigned int compared = 0;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        if (apply_constraints && model.constraints().is_constrained(i))
          continue; // each path puts its own scale on the diagonal
        EXPECT_NEAR(r_direct[i], r_mapped[i], 1e-12 * r_mapped.l2_norm())
          << "DoF " << i;
        for (auto entry = mapped.begin(i); entry != mapped.end(i); ++entry)
          {
            const unsigned int j = entry->column();
            if (apply_constraints && model.constraints().is_constrained(j))
              continue;
            EXPECT_NEAR(direct.el(i, j), entry->value(), 1e-13 * scale)
              << "entry (" << i << ", " << j << ")";
            ++compared;
          }
      }
    EXPECT_GT(compared, 100u);
  }
} // namespace

TEST(DirectScatter, AddsWhatDealIIAddsWithAndWithoutTheSupports)
{
  const auto model = hub_of_rods(3);
  const auto u     = perturbed_state(*model);
  MatrixType matrix;
  model->initialize_matrix(matrix);
  // One matrix, its supports on, off and on again: each change of the
  // fixed DoFs needs other positions.
  expect_as_deal_ii(*model, u, true, matrix);
  expect_as_deal_ii(*model, u, false, matrix);
  expect_as_deal_ii(*model, u, true, matrix);
}

TEST(DirectScatter, SearchesTheRowsOfAHubOfManyRods)
{
  const auto model = hub_of_rods(60);
  const auto u     = perturbed_state(*model);
  MatrixType matrix;
  model->initialize_matrix(matrix);
  // The hub's rotation couples with more DoFs than positions can hold.
  const auto &m       = matrix.trilinos_matrix();
  int         longest = 0;
  for (int row = 0; row < m.NumMyRows(); ++row)
    longest = std::max(longest, m.NumMyEntries(row));
  ASSERT_GT(longest, int(ScatterPositions::skip()));
  expect_as_deal_ii(*model, u, true, matrix);
}

TEST(DirectScatter, FindsPositionsAgainForANewMatrix)
{
  const auto model = hub_of_rods(4);
  const auto u     = perturbed_state(*model);
  for (unsigned int k = 0; k < 3; ++k)
    {
      MatrixType matrix; // a new object each time, perhaps at the same place
      model->initialize_matrix(matrix);
      expect_as_deal_ii(*model, u, true, matrix);
    }
}

TEST(ScatterPositions, FingerprintChangesWithThePatternAndTheSupports)
{
  int                     offsets[] = {0, 2, 4};
  int                     columns[] = {0, 1, 0, 1};
  const CsrArrays         csr{offsets, columns, nullptr, 2};
  const std::vector<bool> none = {false, false}, first = {true, false};
  const auto              base = ScatterPositions::fingerprint(csr, &none);
  EXPECT_EQ(base, ScatterPositions::fingerprint(csr, &none));
  EXPECT_NE(base, ScatterPositions::fingerprint(csr, &first));
  EXPECT_NE(base, ScatterPositions::fingerprint(csr, nullptr));
  columns[3] = 0; // another pattern of the same size
  EXPECT_NE(base, ScatterPositions::fingerprint(csr, &none));
}
