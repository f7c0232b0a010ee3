#include <io/probe_plot.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

namespace rodnet
{
  void
  plot_probes(const std::string &csv_path,
              const std::string &png_path,
              const std::string &title)
  {
    auto warn = [&](const std::string &why) {
      std::cerr << "rodnet: no plot " << png_path << ": " << why << std::endl;
    };

    std::ifstream csv(csv_path);
    std::string   header, first_row;
    if (!std::getline(csv, header) || !std::getline(csv, first_row))
      return warn("the table " + csv_path + " has no rows");
    std::vector<std::string> columns;
    std::istringstream       names(header);
    for (std::string name; std::getline(names, name, ',');)
      columns.push_back(name);
    if (columns.size() < 3)
      return warn("the table has no probe column");
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
      return warn("gnuplot is not installed");

    // One panel per probe, stacked, sharing the load-factor axis. Probe
    // names are plain words (parse_probes forbids quotes and commas), so
    // they can stand in the script's strings as they are.
    const unsigned int n_panels = columns.size() - 2;
    const std::string  script   = png_path + ".gp";
    {
      std::ofstream gp(script);
      gp << "set terminal pngcairo size 800," << 220 * n_panels + 80 << "\n"
         << "set output '" << png_path << "'\n"
         << "set datafile separator ','\n"
         << "set key off\nset grid\n"
         << "set multiplot layout " << n_panels << ",1 title '" << title
         << "'\n";
      for (unsigned int i = 2; i < columns.size(); ++i)
        gp << "set xlabel 'load factor'\nset ylabel '" << columns[i] << "'\n"
           << "plot '" << csv_path << "' every ::1 using 2:" << i + 1
           << " with linespoints pt 7 ps 0.5\n";
      gp << "unset multiplot\n";
    }
    if (std::system(("gnuplot '" + script + "' > /dev/null 2>&1").c_str()) != 0)
      warn("gnuplot failed on " + script);
  }
} // namespace rodnet
