// ModelState and StateGuard: a trial that throws leaves the model's state
// (reference configuration, committed internal variables, time step) equal,
// value by value, to the state before it; in particular a time step whose
// commit of internal variables throws halfway leaves the model at the end
// of the previous step, not with half its variables advanced.
#include <common/family_named.h>
#include <common/held_bar.h>
#include <core/rod_model.h>
#include <materials/standard_linear_solid.h>
#include <solvers/state_guard.h>
#include <solvers/time/time_integrator.h>

#include <gtest/gtest.h>
#include <optional>
#include <stdexcept>

namespace
{
  using namespace rodnet;
  using rodnet::testing::held_bar;

  /// A standard linear solid whose commit (segment_increment with an
  /// output) throws at its third segment once armed: a failure in the
  /// middle of commit_internal_variables().
  class FailingCommit : public StandardLinearSolid
  {
  public:
    using StandardLinearSolid::StandardLinearSolid;

    MaterialResponse<1>
    segment_increment(const double  strain,
                      const double  rest_length,
                      const double *previous,
                      const double  time_step,
                      double       *updated) const override
    {
      if (armed && updated != nullptr && ++commits == 3)
        throw std::runtime_error("commit failed");
      return StandardLinearSolid::segment_increment(strain,
                                                    rest_length,
                                                    previous,
                                                    time_step,
                                                    updated);
    }

    bool                 armed   = false;
    mutable unsigned int commits = 0;
  };

  /// Number of segments of the bars below.
  constexpr unsigned int n_segments = 4;

  /// Expects @p a and @p b to hold the same values: the reference data
  /// (the director frames it gives at @p u, the hinge references, the rest
  /// lengths), every internal variable and the time step.
  void
  expect_same_state(const RodModel   &model,
                    const ModelState &a,
                    const ModelState &b,
                    const VectorType &u)
  {
    EXPECT_EQ(a.time_step, b.time_step);
    const DofLayout &layout = model.layout();
    for (const SegmentStencil &s : layout.segments())
      {
        EXPECT_EQ(a.configuration.rest_length(s.cell),
                  b.configuration.rest_length(s.cell));
        EXPECT_EQ(a.configuration.director_frame(u, s.cell).coeffs(),
                  b.configuration.director_frame(u, s.cell).coeffs())
          << "segment " << s.cell;
      }
    for (unsigned int h = 0; h < layout.hinges().size(); ++h)
      {
        const HingeReference &ra = a.configuration.hinge_reference(h);
        const HingeReference &rb = b.configuration.hinge_reference(h);
        EXPECT_EQ(ra.frame_prev.coeffs(), rb.frame_prev.coeffs());
        EXPECT_EQ(ra.frame_next.coeffs(), rb.frame_next.coeffs());
        EXPECT_EQ(ra.twist, rb.twist) << "hinge " << h;
      }
    const auto expect_same_blocks = [&](const ElementFamily &owner,
                                        const unsigned       n) {
      for (unsigned int i = 0; i < n; ++i)
        {
          ASSERT_EQ(a.committed.size(owner, i), b.committed.size(owner, i));
          for (unsigned int k = 0; k < a.committed.size(owner, i); ++k)
            EXPECT_EQ(a.committed.block(owner, i)[k],
                      b.committed.block(owner, i)[k])
              << "block " << i << ", variable " << k;
        }
    };
    expect_same_blocks(rodnet::testing::family_named(model, "hinges"),
                       layout.hinges().size());
    expect_same_blocks(rodnet::testing::family_named(model, "segments"),
                       layout.segments().size());
  }

  // A guarded trial that resets the reference to a bent state and sets a
  // time step, then throws: the model's state is the one before, and the
  // trial did change it (so that the comparison can fail).
  TEST(ModelState, GuardRestoresStateOnThrow)
  {
    auto model = held_bar(
      std::make_shared<StandardLinearSolid>(RodStiffness{1, 1, 1, 1}, 0.3, 1.0),
      n_segments,
      Vector3(0, 0.5, 0));
    VectorType bent = model->create_vector();
    model->apply_boundary_values(bent, 1.0);
    const ModelState          before = model->state();
    std::optional<ModelState> during;
    try
      {
        const StateGuard guard(*model);
        model->reset_reference(bent);
        model->set_time_step(0.25);
        during = model->state();
        throw std::runtime_error("trial failed");
      }
    catch (const std::runtime_error &)
      {
      }
    ASSERT_TRUE(during.has_value());
    EXPECT_EQ(during->time_step, 0.25);
    EXPECT_NE(
      during->configuration.hinge_reference(n_segments - 2).frame_next.coeffs(),
      before.configuration.hinge_reference(n_segments - 2).frame_next.coeffs());
    expect_same_state(*model, model->state(), before, bent);
  }

  // Quasi-static relaxation of a viscoelastic bar pulled as t: the second
  // step's commit throws after two of its four segments. The run throws,
  // and the model's state and u are those at the end of the first step,
  // as the observer saw them; before StateGuard the time step stayed at h
  // and the hinges and two segments held the second step's variables.
  TEST(ModelState, ThrowingCommitLeavesPreviousStep)
  {
    auto material =
      std::make_shared<FailingCommit>(RodStiffness{1, 1, 1, 1}, 0.3, 1.0);
    auto model = held_bar(material, n_segments, Vector3(0.01, 0.02, 0));
    TimeIntegrator::Parameters p;
    p.integrator  = "quasi-static";
    p.time_step   = 0.1;
    p.end_time    = 0.3;
    p.load_factor = [](const double t) { return t; };
    TimeIntegrator            integrator(*model, {}, p);
    VectorType                u = model->create_vector();
    VectorType                v = model->create_vector();
    std::optional<ModelState> after_first;
    VectorType                u_first;
    EXPECT_THROW(integrator.run(u,
                                v,
                                [&](const TimeIntegrator::StepInfo &,
                                    const VectorType &x,
                                    const VectorType &) {
                                  after_first     = model->state();
                                  u_first         = x;
                                  material->armed = true;
                                }),
                 std::runtime_error);
    ASSERT_TRUE(after_first.has_value());
    EXPECT_EQ(material->commits, 3u);
    // The first step committed nonzero variables: the comparison can fail.
    EXPECT_NE(after_first->committed.block(
                rodnet::testing::family_named(*model, "segments"),
                n_segments - 1)[0],
              0.0);
    expect_same_state(*model, model->state(), *after_first, u);
    VectorType change = u;
    change -= u_first;
    EXPECT_EQ(change.linfty_norm(), 0.0);
  }
} // namespace
