/**
 * @file rodnet-run, the program: a launcher that answers `--version` itself
 * and hands every other command line to the driver, the module
 * librodnet-run-driver.so (drivers/rodnet_run.cc), which it loads with
 * dlopen. The launcher links neither deal.II nor Trilinos: loading and
 * relocating their ~200 shared libraries takes 0.5 s, which `--version`
 * (and a script asking it) need not wait for (doc/performance.md,
 * "Start-up").
 */
#include <dlfcn.h>
#include <unistd.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  /// Whether the command line asks for the version before anything that
  /// the driver answers (--help), skipping the values of options.
  bool
  asks_version(const int argc, char **argv)
  {
    for (int i = 1; i < argc; ++i)
      {
        if (std::strcmp(argv[i], "--help") == 0 ||
            std::strcmp(argv[i], "-h") == 0)
          return false;
        if (std::strcmp(argv[i], "--version") == 0)
          return true;
        if (std::strcmp(argv[i], "--output") == 0 ||
            std::strcmp(argv[i], "--sweep") == 0)
          ++i;
      }
    return false;
  }

  /// The folder of this program's file, from /proc/self/exe (empty if the
  /// link cannot be read).
  std::string
  program_folder()
  {
    std::vector<char> path(4096);
    const ssize_t n = readlink("/proc/self/exe", path.data(), path.size());
    if (n <= 0 || static_cast<std::size_t>(n) >= path.size())
      return "";
    const std::string file(path.data(), static_cast<std::size_t>(n));
    return file.substr(0, file.rfind('/'));
  }

  /// Loads the driver by absolute path, next to this program (build tree)
  /// or in the library folder beside it (installed), then by name. A
  /// RUNPATH is not enough: under AddressSanitizer dlopen is called from
  /// the sanitizer's runtime, whose search path does not hold ours.
  void *
  load_driver(std::string &errors)
  {
    const std::string name = "librodnet-run-driver.so";
    const std::string folder = program_folder();
    std::vector<std::string> candidates;
    if (!folder.empty())
      {
        candidates.push_back(folder + "/" + name);
        candidates.push_back(folder + "/" + RODNET_DRIVER_FROM_PROGRAM + "/" +
                             name);
      }
    candidates.push_back(name);
    // RTLD_GLOBAL: deal.II's and Trilinos's plugins (Open MPI's components)
    // resolve symbols of the libraries the driver brings. RTLD_LAZY: the
    // ~100000 function relocations of deal.II (not linked with -z now) are
    // bound at first call, not all at load (doc/performance.md, "Start-up").
    for (const std::string &candidate : candidates)
      {
        if (candidate != name && access(candidate.c_str(), F_OK) != 0)
          continue;
        if (void *driver = dlopen(candidate.c_str(), RTLD_LAZY | RTLD_GLOBAL))
          return driver;
        errors += std::string("\n  ") + dlerror();
      }
    return nullptr;
  }
} // namespace

int
main(int argc, char **argv)
{
  if (asks_version(argc, argv))
    {
      // The versions the driver was built against, from CMake.
      std::cout << "rodnet " << RODNET_VERSION << " (deal.II "
                << RODNET_DEAL_II_VERSION << ", Trilinos "
                << RODNET_TRILINOS_VERSION << ")" << std::endl;
      return 0;
    }
  std::string errors;
  void *driver = load_driver(errors);
  if (driver == nullptr)
    {
      std::cerr << "rodnet-run: cannot load its driver:" << errors
                << std::endl;
      return 1;
    }
  using Main = int (*)(int, char **);
  const auto run = reinterpret_cast<Main>(dlsym(driver, "rodnet_run_main"));
  if (run == nullptr)
    {
      std::cerr << "rodnet-run: the driver has no entry point: " << dlerror()
                << std::endl;
      return 1;
    }
  return run(argc, argv);
}
