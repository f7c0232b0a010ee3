// What the fuzzers found (doc/sanitizers_and_fuzzing.md): each input that
// crashed, hung or was refused without a clear message, kept in
// tests/input/fuzz/findings/, is now refused with one line that names the
// file and the problem.
#include <io/gmsh_rods.h>

#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  const std::string findings = RODNET_SOURCE_DIR "/tests/input/fuzz/findings/";

  /// The message with which @p read refuses its input; fails the test if
  /// it accepts it or throws anything but std::invalid_argument.
  std::string
  refusal(const std::function<void()> &read)
  {
    try
      {
        read();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    ADD_FAILURE() << "the input was accepted";
    return "";
  }

  /// Expects @p message to be one line holding every one of @p parts.
  void
  expect_clear(const std::string              &message,
               const std::vector<std::string> &parts)
  {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string &part : parts)
      EXPECT_NE(message.find(part), std::string::npos)
        << "\"" << message << "\" does not mention \"" << part << "\"";
  }

  TEST(FuzzFindings, GmshRodsEmptyFile)
  {
    // Was deal.II's GridIn exception: source location and stack trace.
    const std::string path = findings + "gmsh_rods_empty.msh";
    expect_clear(refusal([&] { read_gmsh_rods(path); }),
                 {path, "no line elements"});
  }

  TEST(FuzzFindings, GmshRodsTruncatedSection)
  {
    // $PhysicalNames announces 5 names and loses its $End line: GridIn
    // read on forever.
    const std::string path = findings + "gmsh_rods_truncated_section.msh";
    expect_clear(refusal([&] { read_gmsh_rods(path); }),
                 {path + ":9:", "expected at least 3 fields"});
  }
} // namespace
