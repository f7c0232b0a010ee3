#ifndef RODNET_FUZZ_FUZZ_INPUT_H
#define RODNET_FUZZ_FUZZ_INPUT_H

/**
 * @file What the fuzz targets share. Each target defines libFuzzer's entry
 * point LLVMFuzzerTestOneInput(); built with -fsanitize=fuzzer it is a
 * fuzzer, linked with replay_main.cc it replays a corpus
 * (doc/sanitizers_and_fuzzing.md).
 *
 * An input passes when the reader accepts it or refuses it the documented
 * way: std::invalid_argument with a message of one non-empty line. Anything
 * else (another exception, a message of several lines or none, a crash, a
 * sanitizer report, a hang) is a finding: the target aborts, which libFuzzer
 * reports with the input that did it.
 */

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace rodnet::fuzz
{
  /// Reports a finding and aborts.
  [[noreturn]] inline void
  finding(const std::string &what)
  {
    std::fprintf(stderr, "rodnet fuzz finding: %s\n", what.c_str());
    std::abort();
  }

  /// Aborts unless @p message is one non-empty line, without the source
  /// location and stack trace of a deal.II exception's what().
  inline void
  expect_one_line(const std::string &message)
  {
    if (message.empty())
      finding("an input was refused with an empty message");
    if (message.find('\n') != std::string::npos)
      finding("an input was refused with a message of several lines:\n" +
              message);
    if (message.find("An error occurred in line <") != std::string::npos)
      finding("an input was refused with deal.II's source location and "
              "stack trace: " +
              message);
  }

  /**
   * Runs @p read, which either returns (the input was accepted) or throws
   * std::invalid_argument (refused); aborts for anything else. The message
   * of a refusal goes through @p to_text (the driver prints
   * rodnet::error_message() of it).
   */
  template <class Read, class ToText>
  void
  expect_accepted_or_refused(const Read &read, const ToText &to_text)
  {
    try
      {
        read();
      }
    catch (const std::invalid_argument &e)
      {
        expect_one_line(to_text(e));
      }
    catch (const std::exception &e)
      {
        finding(std::string("an input was refused with an exception other "
                            "than std::invalid_argument: ") +
                e.what());
      }
  }

  /// As above, the message being what() (as the readers' own).
  template <class Read>
  void
  expect_accepted_or_refused(const Read &read)
  {
    expect_accepted_or_refused(read, [](const std::exception &e) {
      return std::string(e.what());
    });
  }

  /// The fuzzer's bytes as a file, for readers that take a path; removed
  /// at destruction.
  class InputFile
  {
  public:
    /// Writes @p size bytes at @p data to a file of this process ending in
    /// @p extension (".net", ".msh") in the temporary directory.
    InputFile(const std::uint8_t *data,
              const std::size_t   size,
              const std::string  &extension)
        : path_((std::filesystem::temp_directory_path() /
                 ("rodnet_fuzz_" + std::to_string(::getpid()) + extension))
                  .string())
    {
      std::ofstream out(path_, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char *>(data), size);
      if (!out)
        finding("cannot write the input file " + path_);
    }

    ~InputFile()
    {
      std::remove(path_.c_str());
    }

    InputFile(const InputFile &) = delete;
    InputFile &
    operator=(const InputFile &) = delete;

    const std::string &
    path() const
    {
      return path_;
    }

  private:
    const std::string path_;
  };
} // namespace rodnet::fuzz

#endif
