// The command line and main() of the benchmark programs. Every program reads
// its options as pairs "--name value" and runs the same main(): parse, start
// MPI with the requested number of threads, report an exception on stderr.
// Keeping that in one place keeps the command lines of doc/performance.md
// behaving alike in all of them.
#ifndef RODNET_BENCH_OPTIONS_H
#define RODNET_BENCH_OPTIONS_H

#include <base/mpi_session.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  namespace bench
  {
    /// One option "--name value" of a benchmark: its name and what reading
    /// its value does, usually storing it in a field of the program's
    /// Options.
    struct Option
    {
      std::string                                   name;
      std::function<void(const std::string &value)> read;
    };

    /// "--name n" for a whole number n, stored in @p value as
    /// max(n, @p minimum): a floor such as a minimum number of repeats
    /// keeps a median meaningful whatever the command line asks.
    inline Option
    number(const std::string &name,
           unsigned int      &value,
           const unsigned int minimum = 0)
    {
      return {name, [&value, minimum](const std::string &text) {
                value = std::max(minimum,
                                 static_cast<unsigned int>(std::stoul(text)));
              }};
    }

    /// "--name n" for a switch: @p value is n != 0.
    inline Option
    flag(const std::string &name, bool &value)
    {
      return {name, [&value](const std::string &text) {
                value = std::stoul(text) != 0;
              }};
    }

    /// "--name x" for a real number x, stored in @p value.
    inline Option
    real(const std::string &name, double &value)
    {
      return {name,
              [&value](const std::string &text) { value = std::stod(text); }};
    }

    /// "--name text", stored in @p value as given.
    inline Option
    text(const std::string &name, std::string &value)
    {
      return {name, [&value](const std::string &text) { value = text; }};
    }

    /// Reads the pairs "--name value" of @p argv with the matching entries of
    /// @p options. A last argument without a value is ignored. Throws
    /// std::invalid_argument for a name that is not among @p options, with
    /// the list of the known ones, so that a mistyped option stops the run
    /// instead of timing the defaults.
    inline void
    parse(const int argc, char **argv, const std::vector<Option> &options)
    {
      for (int i = 1; i + 1 < argc; i += 2)
        {
          const std::string name   = argv[i];
          const auto        option = std::find_if(options.begin(),
                                           options.end(),
                                           [&](const Option &candidate) {
                                             return candidate.name == name;
                                           });
          if (option == options.end())
            {
              std::string known;
              for (const Option &candidate : options)
                known += (known.empty() ? "" : ", ") + candidate.name;
              throw std::invalid_argument("unknown option " + name +
                                          "; known: " + known);
            }
          option->read(argv[i + 1]);
        }
    }

    /**
     * The main() of a benchmark program called @p program: reads the command
     * line into default Options with the options Options::command_line()
     * declares on its fields, starts MPI with Options::threads threads and
     * runs @p benchmark. An exception ends the program with "program:
     * message" on stderr and exit status 1.
     */
    template <class Options>
    int
    run_benchmark(const char *program,
                  int         argc,
                  char      **argv,
                  void (*benchmark)(const Options &))
    {
      try
        {
          Options options;
          parse(argc, argv, options.command_line());
          rodnet::MPISession mpi(argc, argv, options.threads);
          benchmark(options);
        }
      catch (const std::exception &e)
        {
          std::cerr << program << ": " << e.what() << std::endl;
          return 1;
        }
      return 0;
    }
  } // namespace bench
} // namespace rodnet

#endif
