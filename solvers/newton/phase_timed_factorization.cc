#include <base/phase_times.h>
#include <solvers/newton/phase_timed_factorization.h>

namespace rodnet
{
  namespace
  {
    using phase_times::Phase;

    /// A factorization that times the one it holds, phase by phase.
    class PhaseTimedFactorization : public TangentFactorization
    {
    public:
      explicit PhaseTimedFactorization(
        std::unique_ptr<TangentFactorization> timed)
          : timed(std::move(timed))
      {
      }

      void
      factorize() override
      {
        const phase_times::Scope phase(Phase::numeric_factorization);
        timed->factorize();
      }

      void
      solve(const VectorType &b, VectorType &x) override
      {
        const phase_times::Scope phase(Phase::linear_solves);
        timed->solve(b, x);
      }

      void
      solve(const VectorType &b,
            VectorType       &x,
            const VectorType &c,
            VectorType       &y) override
      {
        const phase_times::Scope phase(Phase::linear_solves);
        timed->solve(b, x, c, y);
      }

      std::string
      name() const override
      {
        return timed->name();
      }

      double
      factor_entries() const override
      {
        return timed->factor_entries();
      }

      std::optional<unsigned int>
      negative_pivots() const override
      {
        return timed->negative_pivots();
      }

    private:
      std::unique_ptr<TangentFactorization> timed;
    };
  } // namespace


  std::unique_ptr<TangentFactorization>
  phase_timed(std::unique_ptr<TangentFactorization> factorization)
  {
    return std::make_unique<PhaseTimedFactorization>(std::move(factorization));
  }
} // namespace rodnet
