#include <core/require_positive.h>
#include <geometry/rod_generators.h>

#include <algorithm>
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

      /**
       * Vertices of the curve @p x(u), u in [0, 1], traversed at constant
       * speed, with @p velocity = dx/du at u = 0: n equal segments, or with
       * the midpoint clamp the layout of the header (the arc length is
       * proportional to u, so l = L / (n - 1/2) is du = 1 / (n - 1/2)).
       */
      template <class Curve>
      std::vector<Vector3>
      sample(const Curve       &x,
             const Vector3     &velocity,
             const unsigned int n,
             const bool         clamp_at_start_midpoint)
      {
        std::vector<Vector3> points;
        if (!clamp_at_start_midpoint)
          {
            for (unsigned int i = 0; i <= n; ++i)
              points.push_back(x(double(i) / n));
            return points;
          }
        const double du = 1.0 / (n - 0.5);
        points.push_back(x(0) - 0.5 * du * velocity);
        points.push_back(x(0) + 0.5 * du * velocity);
        for (unsigned int i = 2; i <= n; ++i)
          points.push_back(x((i - 0.5) * du));
        return points;
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
      const Vector3 chord = end - start;
      return sample([&](const double u) { return Vector3(start + u * chord); },
                    chord,
                    n_segments,
                    clamp_at_start_midpoint);
    }

    std::vector<Vector3>
    arc(const Vector3     &center,
        const double       radius,
        const Vector3     &e1,
        const Vector3     &e2,
        const double       angle0,
        const double       angle1,
        const unsigned int n_segments,
        const bool         clamp_at_start_midpoint)
    {
      require_segments(n_segments, "arc");
      require_positive(radius, "arc radius");
      require_positive(std::abs(angle1 - angle0), "arc opening angle");
      const double opening = angle1 - angle0;
      const auto   x       = [&](const double u) {
        const double a = angle0 + opening * u;
        return Vector3(center + radius * (std::cos(a) * e1 + std::sin(a) * e2));
      };
      return sample(x,
                    radius * opening *
                      (-std::sin(angle0) * e1 + std::cos(angle0) * e2),
                    n_segments,
                    clamp_at_start_midpoint);
    }

    std::vector<Vector3>
    ring(const Vector3     &center,
         const double       radius,
         const Vector3     &e1,
         const Vector3     &e2,
         const unsigned int n_segments,
         const unsigned int turns)
    {
      if (n_segments < 3)
        throw std::invalid_argument(
          "ring: the number of segments must be >= 3");
      if (turns < 1)
        throw std::invalid_argument(
          "ring: the number of turns must be a whole number >= 1");
      std::vector<Vector3> points =
        arc(center, radius, e1, e2, 0, 2 * M_PI * turns, n_segments);
      points.pop_back();
      return points;
    }

    std::vector<Vector3>
    helix(const double       radius,
          const double       pitch_over_2pi,
          const double       turns,
          const unsigned int n_segments,
          const bool         clamp_at_start_midpoint)
    {
      require_segments(n_segments, "helix");
      require_positive(radius, "helix radius");
      require_positive(turns, "helix number of turns");
      const double angle = 2 * M_PI * turns;
      const auto   x     = [&](const double u) {
        const double t = angle * u;
        return Vector3(radius * std::cos(t),
                       radius * std::sin(t),
                       pitch_over_2pi * t);
      };
      return sample(x,
                    angle * Vector3(0, radius, pitch_over_2pi),
                    n_segments,
                    clamp_at_start_midpoint);
    }

    std::vector<Vector3>
    polyline(const std::vector<Vector3> &corners,
             const unsigned int          segments_per_piece,
             const bool                  clamp_at_start_midpoint)
    {
      require_segments(segments_per_piece, "polyline");
      if (corners.size() < 2)
        throw std::invalid_argument("polyline: needs at least 2 points");
      std::vector<Vector3> points{corners[0]};
      for (unsigned int k = 0; k + 1 < corners.size(); ++k)
        for (unsigned int i = 1; i <= segments_per_piece; ++i)
          points.push_back(corners[k] + (corners[k + 1] - corners[k]) *
                                          (double(i) / segments_per_piece));
      if (!clamp_at_start_midpoint)
        return points;
      if (!((corners[1] - corners[0]).norm() > 0))
        throw std::invalid_argument("polyline: the first two points "
                                    "coincide; the midpoint clamp needs the "
                                    "direction of the first piece");
      // The first piece is straight: lay it out as a straight rod.
      std::vector<Vector3> first =
        straight(corners[0], corners[1], segments_per_piece, true);
      first.back() = corners[1];
      std::copy(first.begin(), first.end(), points.begin());
      return points;
    }

    std::vector<Vector3>
    center_first_segment_on_start(const std::vector<Vector3> &chain)
    {
      if (chain.size() < 2)
        throw std::invalid_argument(
          "midpoint clamp: the chain needs at least 2 points");
      const Vector3        half = 0.5 * (chain[1] - chain[0]);
      std::vector<Vector3> points{chain[0] - half, chain[0] + half};
      points.insert(points.end(), chain.begin() + 1, chain.end());
      return points;
    }
  } // namespace generators
} // namespace rodnet
