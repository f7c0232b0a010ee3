// `rodnet-run --help` is compact and complete, doc/scene_reference.txt is
// exactly it, and `--version` names the versions of rodnet and deal.II.
#include <deal.II/base/config.h>

#include <common/run_driver.h>
#include <io/scene_help.h>

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace
{
  using rodnet::testing::read_file;
  using rodnet::testing::run_driver_with;

  /// How often @p needle occurs in @p text.
  unsigned int
  count(const std::string &text, const std::string &needle)
  {
    unsigned int n = 0;
    for (auto at = text.find(needle); at != std::string::npos;
         at      = text.find(needle, at + 1))
      ++n;
    return n;
  }

  TEST(Help, EqualsSceneReference)
  {
    const rodnet::testing::DriverOutcome o = run_driver_with("--help");
    ASSERT_EQ(o.exit_code, 0);
    // Regenerate with: build/release/rodnet-run --help >
    // doc/scene_reference.txt
    EXPECT_EQ(o.output, read_file(RODNET_SOURCE_DIR "/doc/scene_reference.txt"))
      << "doc/scene_reference.txt is not the output of rodnet-run --help";
  }

  /// @p text with every run of blanks and newlines as one blank.
  std::string
  one_line(const std::string &text)
  {
    std::istringstream words(text);
    std::string        line, word;
    while (words >> word)
      line += (line.empty() ? "" : " ") + word;
    return line;
  }

  TEST(Help, CompactAndComplete)
  {
    const std::string help = run_driver_with("--help").output;
    const std::string text = one_line(help);
    // Each material model's entries once (the groups refer to them), the
    // values of selections and every probe kind.
    EXPECT_EQ(count(help, "subsection linear elastic"), 1u);
    EXPECT_EQ(count(help, "subsection standard linear solid"), 1u);
    EXPECT_EQ(count(help, "Every entry and subsection of \"Material\""), 1u);
    EXPECT_NE(text.find("(one of: newton | dynamic relaxation | time "
                        "stepping | continuation)"),
              std::string::npos);
    for (const char *kind : {"position <vertex>",
                             "reaction <vertex>",
                             "energy [J]",
                             "eigenvalue",
                             "rotation <junction> <ax>,<ay>,<az> [rad]",
                             "moment <junction> <x|y|z> [N m]"})
      EXPECT_NE(text.find(kind), std::string::npos) << kind;
    // 450 until the continuation method and its eight entries came; 480
    // until the ribbon models came; 540 until the Substrate came; 560 until
    // rod groups, activation fields, imperfections and pictures came (578);
    // 600 until the rotary inertia of issue 35 (602) and Loads/Rigid bodies
    // (3 lines) came; 606 until "Spectral radius at infinity" of the
    // generalized-alpha integrator (2 lines) came; 608 until the inertia
    // tensor of Loads/Rigid bodies (1 line) came; 609 until the bonding
    // constraints (7 lines) came; 616 until the line searches' help from
    // their registry (3 lines) came; 619 until MUMPS joined the linear
    // solvers (1 line); 620 until --threads (2 lines) and Solver/Max step
    // time (5 lines) came; 630 until --timings (4 lines) came.
    EXPECT_LT(count(help, "\n"), 640u);
    unsigned int       longest = 0;
    std::istringstream lines(help);
    for (std::string line; std::getline(lines, line);)
      longest = std::max<unsigned int>(longest, line.size());
    EXPECT_LE(longest, 79u);
  }

  TEST(Help, Version)
  {
    const rodnet::testing::DriverOutcome o = run_driver_with("--version");
    EXPECT_EQ(o.exit_code, 0);
    EXPECT_EQ(o.output,
              std::string("rodnet ") + RODNET_VERSION + " (deal.II " +
                DEAL_II_PACKAGE_VERSION + ", Trilinos " +
                std::to_string(DEAL_II_TRILINOS_VERSION_MAJOR) + "." +
                std::to_string(DEAL_II_TRILINOS_VERSION_MINOR) + ")\n");
  }

  TEST(Help, PatternsInWords)
  {
    using rodnet::describe_pattern;
    EXPECT_EQ(describe_pattern("[Integer range 1...2147483647 (inclusive)]"),
              "integer >= 1");
    EXPECT_EQ(describe_pattern("[Double -MAX_DOUBLE...MAX_DOUBLE (inclusive)]"),
              "number");
    EXPECT_EQ(describe_pattern("[Double 0...1 (inclusive)]"),
              "number from 0 to 1");
    EXPECT_EQ(describe_pattern("[Selection a|b c ]"), "one of: a | b c");
    EXPECT_EQ(describe_pattern("[List of <[Double -MAX_DOUBLE...MAX_DOUBLE "
                               "(inclusive)]> of length 3...3 (inclusive)]"),
              "3 numbers separated by ','");
    EXPECT_EQ(describe_pattern("[List of <[Integer range 1...2147483647 "
                               "(inclusive)]> of length 2...2 (inclusive) "
                               "separated by <;>]"),
              "2 integers >= 1 separated by ';'");
    EXPECT_EQ(describe_pattern("[Bool]"), "true | false");
    EXPECT_EQ(describe_pattern("[Anything]"), "text");
  }
} // namespace
