#include <io/output_directory.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace rodnet
{
  void
  prepare_output_directory(const std::string &directory)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory))
      throw std::invalid_argument(
        "cannot create the output directory \"" + directory +
        "\": " + (error ? error.message() : "a file of that name exists") +
        "; give another with --output DIR (or Output/Directory)");
    if (access(directory.c_str(), W_OK) != 0)
      throw std::invalid_argument("cannot write into the output directory \"" +
                                  directory + "\": " + std::strerror(errno) +
                                  "; give another with --output DIR (or "
                                  "Output/Directory)");
  }
} // namespace rodnet
