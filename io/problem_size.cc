#include <io/problem_size.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  double
  ProblemSize::dofs() const
  {
    return 3 * vertices + segments + 4 * junctions + constraint_dofs;
  }

  double
  ProblemSize::factor_entries() const
  {
    return 32 * dofs() + 53 * std::pow(junctions, 1.35);
  }

  double
  ProblemSize::memory() const
  {
    return 200e6 + bytes_per_dof * dofs() +
           bytes_per_factor_entry * factor_entries();
  }

  double
  memory_per_dof(const bool static_checks,
                 const bool time_stepping,
                 const bool vtu)
  {
    const double solver = static_checks ? 1300 : time_stepping ? 900 : 250;
    return solver + (vtu ? 150 : 0);
  }

  double
  memory_per_factor_entry(const bool static_checks, const bool time_stepping)
  {
    return static_checks ? 16 : time_stepping ? 28 : 0;
  }

  ProblemSize
  rods_size(const double n_rods, const double n_segments, const double n_closed)
  {
    ProblemSize size;
    size.rods     = n_rods;
    size.segments = n_segments;
    // An open rod has one vertex more than segments.
    size.vertices = n_segments + n_rods - n_closed;
    return size;
  }

  ProblemSize
  network_size(const double n_beams,
               const double n_junctions,
               const double segments_per_beam)
  {
    ProblemSize size = rods_size(n_beams, n_beams * segments_per_beam);
    size.junctions   = n_junctions;
    return size;
  }

  double
  available_memory()
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   key, unit;
    double        value = 0;
    while (meminfo >> key >> value >> unit)
      if (key == "MemAvailable:")
        return value * 1024;
    return 0;
  }

  std::string
  format_bytes(const double bytes)
  {
    const bool         giga  = bytes >= 1e9;
    const double       value = bytes / (giga ? 1e9 : 1e6);
    std::ostringstream text;
    text << std::fixed << std::setprecision(value < 10 ? 1 : 0) << value
         << (giga ? " GB" : " MB");
    return text.str();
  }

  void
  check_memory(const ProblemSize &size,
               const double       available,
               const std::string &entry)
  {
    if (available <= 0 || size.memory() <= available)
      return;
    std::ostringstream message;
    message << std::fixed << std::setprecision(0) << "entry \"" << entry
            << "\": the model would have " << size.segments << " segments and "
            << size.dofs() << " DoFs and need about "
            << format_bytes(size.memory()) << " of memory, more than the "
            << format_bytes(available)
            << " available (MemAvailable); use fewer segments or cells";
    throw std::invalid_argument(message.str());
  }
} // namespace rodnet
