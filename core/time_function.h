#ifndef RODNET_CORE_TIME_FUNCTION_H
#define RODNET_CORE_TIME_FUNCTION_H

#include <functional>
#include <memory>
#include <string>

namespace rodnet
{
  /**
   * What scales a prescribed displacement or rotation (doc/dynamics.md,
   * "Moving supports"): the load factor (empty, the default), or a function
   * f(t) of its own in time stepping ("in time <f(t)>" of a scene), the
   * support then at its stated value times f(t). The expression names the
   * function in messages and tells two apart.
   */
  struct TimeFunction
  {
    /// The expression as written ("sin(2*pi*t)"); empty: the load factor.
    std::string expression;
    /// f(t), which throws naming its entry and the time where it is not
    /// finite; null: the load factor.
    std::shared_ptr<const std::function<double(double)>> of_time;

    /// Whether a function of time drives it.
    bool
    given() const
    {
      return of_time != nullptr;
    }

    /// Its factor at @p load_factor and @p time (s).
    double
    factor(const double load_factor, const double time) const
    {
      return given() ? (*of_time)(time) : load_factor;
    }

    /// Whether both scale by the same: the load factor, or the same
    /// expression of t.
    bool
    operator==(const TimeFunction &other) const
    {
      return given() == other.given() && expression == other.expression;
    }

    bool
    operator!=(const TimeFunction &other) const
    {
      return !(*this == other);
    }

    /// "the load factor" or "the function of time <expression>".
    std::string
    describe() const
    {
      return given() ? "the function of time " + expression : "the load factor";
    }
  };
} // namespace rodnet

#endif
