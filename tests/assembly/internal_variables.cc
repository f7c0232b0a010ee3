// History-dependent materials in the assembly: with committed viscous
// strains in every hinge, junction element and segment, the residual is the
// gradient of the condensed incremental energy and the tangent its
// Hessian (central finite differences); a commit stores the closed-form
// update alpha = (dt e + t_r alpha_prev) / (dt + t_r) of each hinge,
// junction element and segment (e: the strain less the natural strain of
// the helix, stress free as built); the energy does not change when the
// reference is reset; time steps are checked. A family of its own with
// history (a Maxwell element) is committed by the model like the rods'
// families, and its energy reads the committed value.
#include <common/family_named.h>
#include <core/rod_model.h>
#include <elements/stretch_kernel.h>
#include <geometry/network_generators.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <materials/standard_linear_solid.h>

#include <gtest/gtest.h>
#include <random>

namespace
{
  using namespace rodnet;
  using rodnet::testing::family_named;

  const double relaxation_time = 0.5;
  const double time_step       = 0.2;

  std::shared_ptr<const RodMaterial>
  viscoelastic()
  {
    return std::make_shared<StandardLinearSolid>(RodStiffness{100, 2, 3, 1.5},
                                                 0.4,
                                                 relaxation_time);
  }

  /// A helix, and a welded frame (junction elements) from the generator.
  std::unique_ptr<RodModel>
  viscoelastic_model(const bool network_model)
  {
    std::unique_ptr<RodNetwork> network;
    if (network_model)
      network = std::move(
        build_rod_network(network_generators::hexagonal_lattice(1, 1, 1.0),
                          2,
                          "simple")
          .network);
    else
      {
        network = std::make_unique<RodNetwork>();
        network->add_rod(generators::helix(0.5, 0.1, 0.5, 10),
                         false,
                         Vector3(0.3, 0.2, 1.0),
                         "simple");
        network->create_triangulation();
      }
    const unsigned int n_rods = network->rods().size();
    auto               model  = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>(n_rods, viscoelastic()));
    model->finalize();
    return model;
  }

  void
  perturb(VectorType &u, std::mt19937 &random, const double size)
  {
    std::uniform_real_distribution<double> small(-size, size);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] += small(random);
    u.compress(dealii::VectorOperation::add);
  }

  class InternalVariablesInAssembly : public ::testing::TestWithParam<bool>
  {
  };

  TEST_P(InternalVariablesInAssembly, DerivativesOfIncrementalEnergy)
  {
    const auto model = viscoelastic_model(GetParam());
    ASSERT_TRUE(model->has_internal_variables());
    model->set_time_step(time_step);
    std::mt19937 random(11);
    VectorType   u = model->create_vector();
    // Two committed steps leave non-zero, different viscous strains; a
    // reset moves the reference away from the undeformed state.
    for (unsigned int step = 0; step < 2; ++step)
      {
        perturb(u, random, 0.05);
        model->commit_internal_variables(u);
        model->reset_reference(u);
      }
    perturb(u, random, 0.05);

    VectorType r = model->create_vector();
    MatrixType k;
    model->initialize_matrix(k);
    model->assemble(u, 0.0, &r, &k, false);

    const double h     = 1e-6;
    double       max_r = 0, max_k = 0, err_r = 0, err_k = 0;
    VectorType   r_plus = model->create_vector(), r_minus = r_plus;
    for (unsigned int j = 0; j < u.size(); ++j)
      {
        VectorType up = u, um = u;
        up[j] += h;
        um[j] -= h;
        const double fd_r =
          (model->assemble(up, 0.0, &r_plus, nullptr, false) -
           model->assemble(um, 0.0, &r_minus, nullptr, false)) /
          (2 * h);
        max_r = std::max(max_r, std::abs(r[j]));
        err_r = std::max(err_r, std::abs(fd_r - r[j]));
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            max_k = std::max(max_k, std::abs(k.el(i, j)));
            err_k = std::max(err_k,
                             std::abs((r_plus[i] - r_minus[i]) / (2 * h) -
                                      k.el(i, j)));
          }
      }
    // Central differences: truncation h^2 |f'''| and rounding eps |f| / h.
    EXPECT_LT(err_r, 1e-6 * max_r);
    EXPECT_LT(err_k, 1e-6 * max_k);
    std::cout << "max relative FD error: residual " << err_r / max_r
              << ", tangent " << err_k / max_k << std::endl;
  }

  TEST_P(InternalVariablesInAssembly, CommitStoresClosedFormUpdate)
  {
    const auto model = viscoelastic_model(GetParam());
    model->set_time_step(time_step);
    std::mt19937 random(5);
    VectorType   u = model->create_vector();
    perturb(u, random, 0.05);
    model->commit_internal_variables(u);
    const VectorType u1 = u;
    perturb(u, random, 0.05);
    // Nothing but a commit changes the stored values.
    const double *first =
      model->internal_variables().block(family_named(*model, "segments"), 0);
    const double stored = first[0];
    model->assemble(u, 0.0, nullptr, nullptr);
    EXPECT_EQ(first[0], stored);
    model->commit_internal_variables(u);

    // Two backward-Euler steps of t_r alpha_dot = e - alpha from 0.
    const double         w = relaxation_time / (relaxation_time + time_step);
    const Configuration &c = model->configuration();
    StretchStrain        e1, e2;
    const auto          &segments = model->layout().segments();
    for (unsigned int s = 0; s < segments.size(); ++s)
      {
        const double l0 = c.rest_length(segments[s].cell);
        evaluate_stretch(c.segment_dofs(u1, segments[s]), l0, e1, false);
        evaluate_stretch(c.segment_dofs(u, segments[s]), l0, e2, false);
        const double alpha1 = (1 - w) * e1.strain;
        EXPECT_NEAR(model->internal_variables().block(family_named(*model,
                                                                   "segments"),
                                                      s)[0],
                    w * alpha1 + (1 - w) * e2.strain,
                    1e-14)
          << "segment " << s;
      }
    const auto &hinges = model->layout().hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      {
        const HingeKernel &kernel = model->hinge_kernel(hinges[h].rod);
        const double       l      = c.voronoi_length(h);
        // The helix is stress free as built: the viscous strains follow
        // kappa - kappa_bar.
        const Vector3 k1 =
          (kernel.strains(c.hinge_dofs(u1, hinges[h]), c.hinge_reference(h)) -
           c.natural_strains(h)) /
          l;
        const Vector3 k2 =
          (kernel.strains(c.hinge_dofs(u, hinges[h]), c.hinge_reference(h)) -
           c.natural_strains(h)) /
          l;
        for (unsigned int m = 0; m < 3; ++m)
          EXPECT_NEAR(model->internal_variables().block(family_named(*model,
                                                                     "hinges"),
                                                        h)[m],
                      w * (1 - w) * k1[m] + (1 - w) * k2[m],
                      1e-12)
            << "hinge " << h << " mode " << m;
      }
    const auto &junctions = model->layout().junctions();
    EXPECT_EQ(junctions.empty(), !GetParam());
    for (unsigned int e = 0; e < junctions.size(); ++e)
      {
        const JunctionKernel &kernel = model->junction_kernel(junctions[e].rod);
        const double          l      = c.junction_voronoi_length(e);
        const Vector3 k1 = kernel.strains(c.junction_dofs(u1, junctions[e]),
                                          c.junction_reference(e)) /
                           l;
        const Vector3 k2 = kernel.strains(c.junction_dofs(u, junctions[e]),
                                          c.junction_reference(e)) /
                           l;
        ASSERT_EQ(model->internal_variables()
                    .size(family_named(*model, "junction elements"), e),
                  3u);
        for (unsigned int m = 0; m < 3; ++m)
          EXPECT_NEAR(model->internal_variables()
                        .block(family_named(*model, "junction elements"), e)[m],
                      w * (1 - w) * k1[m] + (1 - w) * k2[m],
                      1e-12)
            << "junction element " << e << " mode " << m;
      }
  }

  TEST_P(InternalVariablesInAssembly, EnergyInvariantUnderReferenceReset)
  {
    const auto model = viscoelastic_model(GetParam());
    model->set_time_step(time_step);
    std::mt19937 random(3);
    VectorType   u = model->create_vector();
    perturb(u, random, 0.05);
    model->commit_internal_variables(u);
    perturb(u, random, 0.05);
    const double before = model->assemble(u, 0.0, nullptr, nullptr);
    model->reset_reference(u);
    const double after = model->assemble(u, 0.0, nullptr, nullptr);
    EXPECT_NEAR(after, before, 1e-12 * std::abs(before));
  }

  INSTANTIATE_TEST_SUITE_P(RodAndNetwork,
                           InternalVariablesInAssembly,
                           ::testing::Values(false, true));

  TEST(InternalVariablesInAssembly, TimeStepIsChecked)
  {
    const auto model = viscoelastic_model(false);
    for (const double bad : {-1.0, std::nan(""), HUGE_VAL})
      EXPECT_THROW(model->set_time_step(bad), std::invalid_argument);
    EXPECT_NO_THROW(model->set_time_step(1e-3));
    EXPECT_NO_THROW(model->set_time_step(0));
  }

  /// A family of its own with history: a Maxwell element on one DoF, a
  /// spring k in series with a dashpot of relaxation time t_r (that of the
  /// material above) whose slip a
  /// is the internal variable. W = k/2 (u - a)^2 at the committed a; the
  /// commit takes a backward-Euler step of t_r da/dt = u - a.
  class MaxwellAnchor : public ElementFamily
  {
  public:
    static constexpr double stiffness = 3;

    explicit MaxwellAnchor(const global_dof_index dof)
        : dof(dof)
    {
    }

    std::string
    name() const override
    {
      return "Maxwell anchor";
    }

    unsigned int
    n_stencils() const override
    {
      return 1;
    }

    void
    get_dofs(unsigned int, std::vector<global_dof_index> &dofs) const override
    {
      dofs = {dof};
    }

    void
    evaluate(const unsigned int  s,
             const StencilState &state,
             const Derivatives   derivatives,
             LocalContribution  &local) const override
    {
      const double spring = state.u[dof] - state.history.block(*this, s)[0];
      local.energy        = stiffness / 2 * spring * spring;
      Eigen::Matrix<double, 1, 1> gradient, hessian;
      gradient << stiffness * spring;
      hessian << stiffness;
      if (derivatives != Derivatives::energy)
        local.store(gradient,
                    derivatives == Derivatives::hessian ? &hessian : nullptr);
    }

    unsigned int
    n_internal_variables(unsigned int) const override
    {
      return 1;
    }

    void
    update_internal_variables(const unsigned int  s,
                              const StencilState &state,
                              double             *updated) const override
    {
      const double h = state.time_step;
      updated[0]     = (h * state.u[dof] +
                    relaxation_time * state.history.block(*this, s)[0]) /
                   (h + relaxation_time);
    }

  private:
    global_dof_index dof;
  };

  TEST(InternalVariablesOfAFamily, TheModelCommitsAFamilyOfItsOwn)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3::Zero(), Vector3::UnitX(), 4),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(
                     RodStiffness{1, 1, 1, 1})});
    EXPECT_FALSE(model.has_internal_variables());
    const global_dof_index dof    = model.layout().vertex_dof(0, 0);
    auto                   family = std::make_unique<MaxwellAnchor>(dof);
    const MaxwellAnchor   &anchor = *family;
    model.add_element_family(std::move(family));
    EXPECT_TRUE(model.has_internal_variables());
    model.finalize();
    model.set_time_step(time_step);

    // Two steps to u = 0.03, then 0.05, from a = 0, by hand; the energy of
    // the anchor (the rod's does not change at fixed u) follows a.
    const double k = MaxwellAnchor::stiffness, t_r = relaxation_time;
    double       slip = 0;
    VectorType   u    = model.create_vector();
    for (const double value : {0.03, 0.05})
      {
        u[dof] = value;
        u.compress(dealii::VectorOperation::insert);
        const double before = model.assemble(u, 0.0, nullptr, nullptr);
        model.commit_internal_variables(u);
        const double committed =
          (time_step * value + t_r * slip) / (time_step + t_r);
        EXPECT_NEAR(model.internal_variables().block(anchor, 0)[0],
                    committed,
                    1e-15);
        EXPECT_NEAR(
          model.assemble(u, 0.0, nullptr, nullptr) - before,
          k / 2 * (std::pow(value - committed, 2) - std::pow(value - slip, 2)),
          1e-12);
        slip = committed;
      }
  }
} // namespace
