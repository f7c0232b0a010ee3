#include <core/rod_generators.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace generators
  {
    namespace
    {
      void
      require_segments(const unsigned int n, const char *what)
      {
        if (n < 1)
          throw std::invalid_argument(std::string(what) +
                                      ": the number of segments must be >= 1");
      }

      void
      require_positive(const double value, const char *what)
      {
        if (!(value > 0) || !std::isfinite(value))
          throw std::invalid_argument(std::string(what) +
                                      " must be positive and finite, got " +
                                      std::to_string(value));
      }
    } // namespace

    std::vector<Vector3>
    straight(const Vector3     &start,
             const Vector3     &end,
             const unsigned int n_segments,
             const bool         clamp_at_start_midpoint)
    {
      require_segments(n_segments, "straight rod");
      require_positive((end - start).norm(), "straight rod length");
      // With the midpoint clamp the n segments span [start - l/2, end], so
      // l = L / (n - 1/2).
      const double         shift = clamp_at_start_midpoint ? 0.5 : 0.0;
      const Vector3        step  = (end - start) / (n_segments - shift);
      std::vector<Vector3> points;
      for (unsigned int i = 0; i <= n_segments; ++i)
        points.push_back(start + (i - shift) * step);
      return points;
    }

    std::vector<Vector3>
    arc(const Vector3     &center,
        const double       radius,
        const Vector3     &e1,
        const Vector3     &e2,
        const double       angle0,
        const double       angle1,
        const unsigned int n_segments)
    {
      require_segments(n_segments, "arc");
      require_positive(radius, "arc radius");
      require_positive(std::abs(angle1 - angle0), "arc opening angle");
      std::vector<Vector3> points;
      for (unsigned int i = 0; i <= n_segments; ++i)
        {
          const double a = angle0 + (angle1 - angle0) * i / n_segments;
          points.push_back(center +
                           radius * (std::cos(a) * e1 + std::sin(a) * e2));
        }
      return points;
    }

    std::vector<Vector3>
    ring(const Vector3     &center,
         const double       radius,
         const Vector3     &e1,
         const Vector3     &e2,
         const unsigned int n_segments)
    {
      if (n_segments < 3)
        throw std::invalid_argument(
          "ring: the number of segments must be >= 3");
      std::vector<Vector3> points =
        arc(center, radius, e1, e2, 0, 2 * M_PI, n_segments);
      points.pop_back();
      return points;
    }

    std::vector<Vector3>
    helix(const double       radius,
          const double       pitch_over_2pi,
          const double       turns,
          const unsigned int n_segments)
    {
      require_segments(n_segments, "helix");
      require_positive(radius, "helix radius");
      require_positive(turns, "helix number of turns");
      std::vector<Vector3> points;
      for (unsigned int i = 0; i <= n_segments; ++i)
        {
          const double t = 2 * M_PI * turns * i / n_segments;
          points.emplace_back(radius * std::cos(t),
                              radius * std::sin(t),
                              pitch_over_2pi * t);
        }
      return points;
    }

    std::vector<Vector3>
    polyline(const std::vector<Vector3> &corners,
             const unsigned int          segments_per_piece)
    {
      require_segments(segments_per_piece, "polyline");
      if (corners.size() < 2)
        throw std::invalid_argument("polyline: needs at least 2 points");
      std::vector<Vector3> points{corners[0]};
      for (unsigned int k = 0; k + 1 < corners.size(); ++k)
        for (unsigned int i = 1; i <= segments_per_piece; ++i)
          points.push_back(corners[k] + (corners[k + 1] - corners[k]) *
                                          (double(i) / segments_per_piece));
      return points;
    }
  } // namespace generators
} // namespace rodnet
