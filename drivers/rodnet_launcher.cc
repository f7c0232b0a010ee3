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

#include <cstring>
#include <iostream>

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
  // RTLD_GLOBAL: deal.II's and Trilinos's plugins (Open MPI's components)
  // resolve symbols of the libraries the driver brings.
  void *driver = dlopen("librodnet-run-driver.so", RTLD_NOW | RTLD_GLOBAL);
  if (driver == nullptr)
    {
      std::cerr << "rodnet-run: cannot load its driver: " << dlerror()
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
