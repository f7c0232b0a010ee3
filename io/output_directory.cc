#include <io/output_directory.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace rodnet
{
  bool
  prepare_output_directory(const std::string &directory)
  {
    std::error_code error;
    const bool created = std::filesystem::create_directories(directory, error);
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
    return created;
  }


  void
  remove_if_empty(const std::string &directory)
  {
    // Several processes may try at once: whoever is late finds it gone.
    std::error_code error;
    if (std::filesystem::is_empty(directory, error) && !error)
      std::filesystem::remove(directory, error);
  }
} // namespace rodnet
