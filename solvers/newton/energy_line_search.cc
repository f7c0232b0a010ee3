#include <solvers/newton/energy_line_search.h>
#include <solvers/newton/nox_group.h>

#include <NOX_Solver_Generic.H>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rodnet
{
  namespace
  {
    /// The energy and its slope at one step length along the line.
    struct Sample
    {
      double step   = 0;
      double energy = 0;
      double slope  = 0;
    };

    /**
     * The potential along x_old + sign a d as a function of a: each call
     * moves the trial group there and assembles energy and residual. A
     * state where they cannot be computed (a flipped segment) counts as
     * infinite energy, so the search steps back from it.
     */
    class Line
    {
    public:
      Line(NoxGroup                    &trial,
           const NoxGroup              &start,
           const NOX::Abstract::Vector &direction)
          : trial(trial)
          , start(start)
          , direction(direction)
      {
        origin.energy = start.energy();
        origin.slope  = start.getF().innerProduct(direction);
        // Downhill: along -d where the Newton direction climbs.
        sign         = origin.slope > 0 ? -1.0 : 1.0;
        origin.slope = sign * origin.slope;
      }

      /// Puts the trial group at @p step with its energy and residual
      /// (not assembled again if it is there already).
      void
      move_to(const double step)
      {
        if (step != last_step || !trial.isF())
          at(step);
      }

      Sample
      at(const double step)
      {
        last_step = step;
        trial.computeX(start, direction, sign * step);
        Sample sample;
        sample.step = step;
        if (trial.computeF() != NOX::Abstract::Group::Ok)
          {
            trial.forget_failure();
            sample.energy = std::numeric_limits<double>::infinity();
            sample.slope  = std::numeric_limits<double>::quiet_NaN();
            return sample;
          }
        sample.energy = trial.energy();
        sample.slope  = sign * trial.getF().innerProduct(direction);
        return sample;
      }

      double
      signed_step(const double step) const
      {
        return sign * step;
      }

      Sample origin;

    private:
      NoxGroup                    &trial;
      const NoxGroup              &start;
      const NOX::Abstract::Vector &direction;
      double                       sign      = 1;
      double                       last_step = std::nan("");
    };

    /**
     * The minimizer of the cubic through the energies and slopes at @p a
     * and @p b (Nocedal & Wright eq. 3.59), kept at least a tenth of the
     * bracket away from its ends; the midpoint where the cubic has none
     * or an end is not finite.
     */
    double
    cubic_step(const Sample &a, const Sample &b)
    {
      const double low    = std::min(a.step, b.step);
      const double high   = std::max(a.step, b.step);
      const double margin = 0.1 * (high - low);
      const double d1 =
        a.slope + b.slope - 3 * (a.energy - b.energy) / (a.step - b.step);
      const double radicand = d1 * d1 - a.slope * b.slope;
      if (!(radicand >= 0) || !std::isfinite(b.energy))
        return 0.5 * (low + high);
      const double d2   = std::copysign(std::sqrt(radicand), b.step - a.step);
      const double step = b.step - (b.step - a.step) * (b.slope + d2 - d1) /
                                     (b.slope - a.slope + 2 * d2);
      if (!std::isfinite(step))
        return 0.5 * (low + high);
      return std::clamp(step, low + margin, high - margin);
    }
  } // namespace


  EnergyLineSearch::EnergyLineSearch()
      : EnergyLineSearch(Parameters())
  {
  }


  EnergyLineSearch::EnergyLineSearch(const Parameters &parameters)
      : parameters(parameters)
  {
  }


  namespace
  {
    /// What the conditions say of one sample.
    struct Conditions
    {
      const EnergyLineSearch::Parameters &parameters;
      const Sample                       &origin;

      bool
      sufficient_decrease(const Sample &s) const
      {
        const double allowed =
          parameters.relative_rounding * std::abs(origin.energy);
        return std::isfinite(s.energy) &&
               s.energy <=
                 origin.energy +
                   parameters.sufficient_decrease * s.step * origin.slope +
                   allowed;
      }

      bool
      curvature(const Sample &s) const
      {
        return std::abs(s.slope) <=
               parameters.curvature * std::abs(origin.slope);
      }
    };

    /**
     * Algorithm 3.6 of Nocedal & Wright: @p low satisfies sufficient
     * decrease and is the lower of the two, the minimizer lies between
     * @p low and @p high. Returns the accepted sample, or @p low with
     * @p found false after @p trials_left evaluations.
     */
    Sample
    zoom(Line             &line,
         const Conditions &conditions,
         Sample            low,
         Sample            high,
         unsigned int      trials_left,
         bool             &found)
    {
      found = false;
      for (; trials_left > 0; --trials_left)
        {
          const Sample s = line.at(cubic_step(low, high));
          if (!conditions.sufficient_decrease(s) || s.energy >= low.energy)
            high = s;
          else
            {
              if (conditions.curvature(s))
                {
                  found = true;
                  return s;
                }
              if (s.slope * (high.step - low.step) >= 0)
                high = low;
              low = s;
            }
        }
      return low;
    }
  } // namespace


  bool
  EnergyLineSearch::compute(NOX::Abstract::Group        &grp,
                            double                      &step,
                            const NOX::Abstract::Vector &dir,
                            const NOX::Solver::Generic  &solver)
  {
    auto       &trial = dynamic_cast<NoxGroup &>(grp);
    const auto &start =
      dynamic_cast<const NoxGroup &>(solver.getPreviousSolutionGroup());
    Line             line(trial, start, dir);
    const Conditions conditions{parameters, line.origin};
    if (!std::isfinite(line.origin.energy) || line.origin.slope == 0)
      return false;

    // Algorithm 3.5 of Nocedal & Wright from the full step.
    Sample       previous = line.origin;
    Sample       accepted = line.origin;
    bool         found    = false;
    double       length   = 1;
    unsigned int trials   = 0;
    while (trials < parameters.max_trials)
      {
        const Sample s = line.at(length);
        ++trials;
        const unsigned int left = parameters.max_trials - trials;
        if (!conditions.sufficient_decrease(s) ||
            (previous.step > 0 && s.energy >= previous.energy))
          {
            accepted = zoom(line, conditions, previous, s, left, found);
            break;
          }
        if (conditions.curvature(s))
          {
            accepted = s;
            found    = true;
            break;
          }
        if (s.slope >= 0)
          {
            accepted = zoom(line, conditions, s, previous, left, found);
            break;
          }
        previous = accepted = s;
        if (length >= parameters.max_step)
          {
            // Still steeply downhill at the longest step: take it.
            found = true;
            break;
          }
        length = std::min(2 * length, parameters.max_step);
      }
    // The group ends at the accepted point (or where the search began).
    // Sufficient decrease without the curvature condition is still
    // progress: only a search that found no lower energy fails.
    step = line.signed_step(accepted.step);
    line.move_to(accepted.step);
    return found || accepted.step > 0;
  }


  Teuchos::RCP<NOX::LineSearch::Generic>
  EnergyLineSearchFactory::buildLineSearch(
    const Teuchos::RCP<NOX::GlobalData> &,
    Teuchos::ParameterList &) const
  {
    return Teuchos::rcp(new EnergyLineSearch());
  }
} // namespace rodnet
