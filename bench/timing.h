// Wall-clock statistics shared by the benchmark programs: every figure they
// print is the median of repeated runs with the range (min-max), as the
// peer figures of BENCHMARKS.md are quoted.
#ifndef RODNET_BENCH_TIMING_H
#define RODNET_BENCH_TIMING_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <mpi.h>
#include <string>
#include <vector>

namespace rodnet
{
  namespace bench
  {
    /// Median, minimum and maximum of a set of samples.
    struct Statistics
    {
      double median = 0;
      double min    = 0;
      double max    = 0;
    };

    inline Statistics
    statistics(std::vector<double> samples)
    {
      std::sort(samples.begin(), samples.end());
      const std::size_t n = samples.size();
      Statistics        s;
      s.min    = samples.front();
      s.max    = samples.back();
      s.median = n % 2 == 1 ? samples[n / 2] :
                              0.5 * (samples[n / 2 - 1] + samples[n / 2]);
      return s;
    }

    /// Seconds since an arbitrary origin, monotonic.
    inline double
    now()
    {
      return std::chrono::duration<double>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
    }

    /// Seconds that @p work took on this process, all processes of
    /// MPI_COMM_WORLD starting it together (a barrier before).
    inline double
    timed_together(const std::function<void()> &work)
    {
      MPI_Barrier(MPI_COMM_WORLD);
      const double start = now();
      work();
      return now() - start;
    }

    /// Wall times in seconds of @p repeats calls of @p work, after one
    /// untimed warm-up call (first-touch page faults, lazy allocations).
    inline std::vector<double>
    time_repeats(const unsigned int repeats, const std::function<void()> &work)
    {
      work();
      std::vector<double> samples;
      for (unsigned int r = 0; r < repeats; ++r)
        {
          const double start = now();
          work();
          samples.push_back(now() - start);
        }
      return samples;
    }

    /// "1.23e+05 (1.20e+05-1.25e+05)" for a rate: the median of the rates
    /// @p count / time and its range.
    inline std::string
    format_rate(const double count, const Statistics &time)
    {
      char text[80];
      std::snprintf(text,
                    sizeof(text),
                    "%.3g (%.3g-%.3g)",
                    count / time.median,
                    count / time.max,
                    count / time.min);
      return text;
    }

    /// @p x as "1.234e-05", for tables and CSV.
    inline std::string
    scientific(const double x)
    {
      char text[32];
      std::snprintf(text, sizeof(text), "%.3e", x);
      return text;
    }

    /// "1.23e-03 (1.20e-03-1.25e-03)" for a time in seconds.
    inline std::string
    format_time(const Statistics &time)
    {
      char text[80];
      std::snprintf(text,
                    sizeof(text),
                    "%.3g (%.3g-%.3g)",
                    time.median,
                    time.min,
                    time.max);
      return text;
    }

    /// Prints "what   median (min-max) s" of the times @p samples.
    inline void
    print_time(const std::string &what, const std::vector<double> &samples)
    {
      std::printf("%-28s %s s\n",
                  what.c_str(),
                  format_time(statistics(samples)).c_str());
    }
  } // namespace bench
} // namespace rodnet

#endif
