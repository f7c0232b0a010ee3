#ifndef RODNET_TESTS_RUN_DRIVER_H
#define RODNET_TESTS_RUN_DRIVER_H

#include <array>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>

namespace rodnet::testing
{
  /// What a run of rodnet-run returned.
  struct DriverOutcome
  {
    int         exit_code;
    std::string output; ///< stdout and stderr
  };

  /// Writes @p scene to `<name>.prm` and runs rodnet-run on it, with the
  /// output directory `out_<name>`.
  inline DriverOutcome
  run_driver(const std::string &name, const std::string &scene)
  {
    const std::string path = name + ".prm";
    std::ofstream(path) << scene;
    const std::string command = std::string(RODNET_BINARY_DIR) +
                                "/rodnet-run " + path + " --output out_" +
                                name + " 2>&1";
    FILE *pipe = popen(command.c_str(), "r");
    EXPECT_NE(pipe, nullptr);
    std::string           output;
    std::array<char, 512> buffer;
    while (fgets(buffer.data(), buffer.size(), pipe) != nullptr)
      output += buffer.data();
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
  }
} // namespace rodnet::testing

#endif
