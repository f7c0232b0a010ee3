#ifndef RODNET_CORE_REQUIRE_POSITIVE_H
#define RODNET_CORE_REQUIRE_POSITIVE_H

#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  /// Throws std::invalid_argument "<what> must be positive and finite, got
  /// <value>" unless @p value is positive and finite; @p what names the
  /// quantity and where it comes from ("DrModel: rod 2: EA").
  inline void
  require_positive(const double value, const std::string &what)
  {
    if (!(value > 0) || !std::isfinite(value))
      throw std::invalid_argument(what + " must be positive and finite, got " +
                                  std::to_string(value));
  }
} // namespace rodnet

#endif
