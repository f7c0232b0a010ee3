// rodnet-run as a process: its progress reaches a redirected stdout at
// once, SIGINT and SIGTERM stop it between two steps with every output
// complete and exit code 128 + signal, and "outputs in DIR: ..." lists the
// files written and no others.
#include <common/run_driver.h>
#include <common/scene_text.h>
#include <io/csv_table.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace
{
  namespace fs = std::filesystem;
  using rodnet::testing::read_file;

  std::vector<std::string>
  lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }

  /// A cantilever swinging for 1e5 time steps (about 10 s on one core):
  /// long enough to be stopped on the way.
  const std::string long_swing = "subsection Geometry\n"
                                 "  set End = 0.2, 0, 0\n"
                                 "  set Segments = 10\n"
                                 "  set Director d1 = 0, 0, 1\n"
                                 "end\n"
                                 "subsection Material\n"
                                 "  set Density = 1000\n"
                                 "  subsection linear elastic\n"
                                 "    set Young's modulus = 1e6\n"
                                 "    set Radius = 0.01\n"
                                 "  end\n"
                                 "end\n"
                                 "subsection Supports\n"
                                 "  set Clamped ends = start\n"
                                 "end\n"
                                 "subsection Loads\n"
                                 "  set Point forces = end: 0, -0.01, 0\n"
                                 "end\n"
                                 "subsection Solver\n"
                                 "  set Method = time stepping\n"
                                 "  subsection Time stepping\n"
                                 "    set Time step = 0.0005\n"
                                 "    set End time = 50\n"
                                 "    set Progress interval = 10\n"
                                 "  end\n"
                                 "end\n"
                                 "subsection Output\n"
                                 "  set VTU interval = 20\n"
                                 "  set Plot = false\n"
                                 "  set Probes = tip_y: position end y\n"
                                 "end\n";

  /// Waits up to 60 s for @p done while the process @p pid runs; false if
  /// it never came.
  template <class Condition>
  bool
  wait_for(const pid_t pid, const Condition &done)
  {
    for (int i = 0; i < 6000; ++i)
      {
        if (done())
          return true;
        int status = 0;
        if (waitpid(pid, &status, WNOHANG | WNOWAIT) == pid)
          return done();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    return false;
  }

  /// Starts rodnet-run on @p scene with stdout and stderr redirected to
  /// files, waits for its first progress line and 20 rows of probes.csv,
  /// sends @p signal and checks how it stops.
  void
  expect_clean_stop(const int signal, const std::string &name)
  {
    const std::string scene = name + ".prm", out = "out_" + name;
    std::ofstream(scene) << long_swing;
    fs::remove_all(out);
    const std::string stdout_path = name + ".stdout",
                      stderr_path = name + ".stderr";
    const std::string program = std::string(RODNET_BINARY_DIR) + "/rodnet-run";
    const pid_t       pid     = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0)
      {
        // A file, not a terminal: the stream is block-buffered by default.
        const int o =
          open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e =
          open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(o, STDOUT_FILENO);
        dup2(e, STDERR_FILENO);
        execl(program.c_str(),
              program.c_str(),
              scene.c_str(),
              "--output",
              out.c_str(),
              static_cast<char *>(nullptr));
        _exit(127);
      }
    // The progress line is in the file while the run goes on: flushed.
    const bool progress = wait_for(pid, [&] {
      return read_file(stdout_path).find("t = ") != std::string::npos;
    });
    const bool rows     = wait_for(pid, [&] {
      return lines_of(read_file(out + "/probes.csv")).size() > 50;
    });
    kill(pid, signal);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(progress) << read_file(stdout_path) << read_file(stderr_path);
    ASSERT_TRUE(rows) << read_file(stderr_path);

    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal) << read_file(stderr_path);
    // Every row complete, from step 0 on, and the message names the last.
    const std::vector<std::string> csv =
      lines_of(read_file(out + "/probes.csv"));
    EXPECT_EQ(csv.front(), "step,time,tip_y,in_range");
    unsigned int last = 0;
    for (std::size_t r = 1; r < csv.size(); ++r)
      {
        std::istringstream row(csv[r]);
        std::string        step, time, tip, in_range;
        ASSERT_TRUE(std::getline(row, step, ',') &&
                    std::getline(row, time, ',') &&
                    std::getline(row, tip, ',') && !tip.empty() &&
                    std::getline(row, in_range) && !in_range.empty())
          << csv[r];
        EXPECT_EQ(std::stoul(step), r - 1);
        last = std::stoul(step);
      }
    const std::string message = read_file(stderr_path);
    EXPECT_NE(message.find("rodnet-run: interrupted at step " +
                           std::to_string(last) + ": outputs of steps 0.." +
                           std::to_string(last) + " kept"),
              std::string::npos)
      << message;
    // The PVD is closed and lists exactly the VTU files written.
    const std::string pvd = read_file(out + "/solution.pvd");
    EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos) << pvd;
    unsigned int n_vtu = 0;
    for (unsigned int step = 0; step <= last; step += 20)
      {
        char file[32];
        std::snprintf(file, sizeof(file), "solution-%05u.vtu", step);
        EXPECT_NE(pvd.find(file), std::string::npos) << file;
        EXPECT_TRUE(fs::exists(out + "/" + file)) << file;
        ++n_vtu;
      }
    unsigned int listed = 0;
    for (auto at = pvd.find("<DataSet"); at != std::string::npos;
         at      = pvd.find("<DataSet", at + 1))
      ++listed;
    EXPECT_EQ(listed, n_vtu);
  }

  TEST(Driver, InterruptKeepsCompleteOutputs)
  {
    expect_clean_stop(SIGINT, "sigint");
  }

  TEST(Driver, TerminateKeepsCompleteOutputs)
  {
    expect_clean_stop(SIGTERM, "sigterm");
  }

  /// The files named on the "outputs in DIR/: ..." line of @p output.
  std::vector<std::string>
  listed_outputs(const std::string &output)
  {
    const auto at = output.find("/: ");
    EXPECT_NE(at, std::string::npos) << output;
    std::vector<std::string> names;
    std::istringstream       list(
      output.substr(at + 3, output.find('\n', at) - at - 3));
    for (std::string name; std::getline(list, name, ',');)
      names.push_back(name.substr(name.find_first_not_of(' ')));
    return names;
  }

  const std::string short_cantilever =
    "subsection Geometry\n  set Segments = 10\nend\n" +
    rodnet::testing::direct_material() +
    "subsection Supports\n  set Clamped ends = start\nend\n"
    "subsection Loads\n"
    "  set Steps = 2\n"
    "  set Point forces = end: 0, 0.1, 0\n"
    "end\n";

  /// Runs @p name with @p output_entries and checks that the files listed
  /// are @p expected and exist, and that the other outputs do not.
  void
  expect_outputs(const std::string              &name,
                 const std::string              &output_entries,
                 const std::vector<std::string> &expected)
  {
    fs::remove_all("out_" + name);
    const rodnet::testing::DriverOutcome o =
      rodnet::testing::run_driver(name,
                                  short_cantilever + "subsection Output\n" +
                                    output_entries + "end\n");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    EXPECT_EQ(listed_outputs(o.output), expected) << o.output;
    for (const char *file :
         {"probes.csv", "probes.png", "solution.pvd", "picture.png"})
      EXPECT_EQ(fs::exists("out_" + name + "/" + file),
                std::find(expected.begin(), expected.end(), file) !=
                  expected.end())
        << file;
  }

  TEST(Driver, ListsOnlyTheOutputsWritten)
  {
    const bool gnuplot =
      std::system("command -v gnuplot > /dev/null 2>&1") == 0;
    // No probes: no plot; the picture where gnuplot can draw it.
    expect_outputs("no_probes",
                   "",
                   gnuplot ?
                     std::vector<std::string>{"probes.csv",
                                              "solution.pvd",
                                              "picture.png"} :
                     std::vector<std::string>{"probes.csv", "solution.pvd"});
    // No VTU.
    expect_outputs("no_vtu",
                   "  set Write VTU = false\n  set Plot = false\n"
                   "  set Probes = tip: position end y\n",
                   {"probes.csv"});
    // Everything, where gnuplot can draw the plot.
    if (gnuplot)
      expect_outputs(
        "every_output",
        "  set Probes = tip: position end y\n",
        {"probes.csv", "probes.png", "solution.pvd", "picture.png"});
  }
  /// The probes of out_@p name/probes.csv, row by row.
  std::vector<std::vector<double>>
  probe_rows(const std::string &name)
  {
    const rodnet::CsvTable table =
      rodnet::read_csv_table("out_" + name + "/probes.csv");
    std::vector<std::vector<double>> rows;
    for (std::size_t r = 0; r < table.rows.size(); ++r)
      {
        rows.emplace_back();
        for (std::size_t c = 0; c < table.names.size(); ++c)
          rows.back().push_back(table.number(r, c));
      }
    return rows;
  }

  TEST(Driver, TwoThreadsGiveTheProbesOfOne)
  {
    // A welded lattice, whose stencils the threads take color by color:
    // the additions come in another order, the equilibria agree to the
    // Newton tolerance (far below 1e-8 of the deflection).
    const std::string lattice =
      "subsection Geometry\n  set Generator = square lattice\n"
      "  set Cells = 4, 4\n  set Beam length = 0.1\n  set Segments = 6\nend\n"
      "subsection Material\n  subsection linear elastic\n"
      "    set Stiffness input = direct\n    set EA = 1e5\n"
      "    set EI1 = 4\n    set EI2 = 1\n    set GJ = 0.67\n  end\nend\n"
      "subsection Supports\n  set Pinned vertices = @n_0_0, @n_4_0, @n_0_4, "
      "@n_4_4\nend\nsubsection Loads\n  set Steps = 2\n"
      "  set Gravity = 0, 0, -9.81\n  set Mass per length = 0.05\nend\n"
      "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
      "  set Probes = middle: position @n_2_2 z; side: position @n_2_0 z\n"
      "end\n";
    std::ofstream("threads.prm") << lattice;
    const rodnet::testing::DriverOutcome one =
      rodnet::testing::run_driver_with("threads.prm --output out_one_thread");
    const rodnet::testing::DriverOutcome two = rodnet::testing::run_driver_with(
      "threads.prm --output out_two_threads --threads 2");
    ASSERT_EQ(one.exit_code, 0) << one.output;
    ASSERT_EQ(two.exit_code, 0) << two.output;
    EXPECT_NE(two.output.find("assembling on 2 threads"), std::string::npos)
      << two.output;
    const auto rows_one = probe_rows("one_thread");
    const auto rows_two = probe_rows("two_threads");
    ASSERT_EQ(rows_two.size(), rows_one.size());
    ASSERT_EQ(rows_one.size(), 3u) << "the start and two steps";
    const double deflection = std::abs(rows_one.back()[2]);
    EXPECT_GT(deflection, 1e-4);
    for (std::size_t r = 0; r < rows_one.size(); ++r)
      for (std::size_t c = 0; c < rows_one[r].size(); ++c)
        if (std::isnan(rows_one[r][c])) // a field without a value at the start
          EXPECT_TRUE(std::isnan(rows_two[r][c]))
            << "row " << r << ", column " << c;
        else
          EXPECT_NEAR(rows_two[r][c], rows_one[r][c], 1e-8 * deflection)
            << "row " << r << ", column " << c;
  }

  // --timings: a table of the phases that took time, each the least and
  // the most over the processes (one here: the same), the rest as "other",
  // adding up to the run's time; the assembly and the factorizations of a
  // Newton solve are among them.
  TEST(Driver, TimingsAddUpToTheRun)
  {
    std::ofstream("timings.prm")
      << "subsection Geometry\n  set Generator = square lattice\n"
         "  set Cells = 10, 10\n  set Beam length = 0.1\n  set Segments = 10\n"
         "end\nsubsection Supports\n  set Pinned vertices = @n_0_0, "
         "@n_10_0, @n_0_10, @n_10_10\nend\nsubsection Material\n"
         "  subsection linear elastic\n    set Stiffness input = direct\n"
         "    set EA = 1e5\n    set EI1 = 4\n    set EI2 = 1\n"
         "    set GJ = 0.67\n  end\nend\nsubsection Loads\n  set Steps = 2\n"
         "  set Gravity = 0, 0, -9.81\n  set Mass per length = 0.05\nend\n"
         "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
         "end\n";
    const rodnet::testing::DriverOutcome o = rodnet::testing::run_driver_with(
      "timings.prm --output out_timings --timings");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    const std::size_t table = o.output.find("where the time went");
    ASSERT_NE(table, std::string::npos) << o.output;
    const std::regex total_pattern(R"(of ([0-9.e+-]+) s\):)");
    std::smatch      total;
    ASSERT_TRUE(std::regex_search(o.output, total, total_pattern)) << o.output;
    const std::regex row(
      R"(\n  ([A-Za-z ]+[a-z]) +([0-9.]+) +([0-9.]+) +[0-9.]+ %)");
    std::map<std::string, double> seconds;
    double                        sum = 0;
    for (auto it =
           std::sregex_iterator(o.output.begin() + table, o.output.end(), row);
         it != std::sregex_iterator();
         ++it)
      {
        EXPECT_EQ((*it)[2], (*it)[3]) << "one process: least = most";
        seconds[(*it)[1]] = std::stod((*it)[3]);
        sum += std::stod((*it)[3]);
      }
    for (const char *phase : {"model build",
                              "Hessian assembly",
                              "numeric factorization",
                              "linear solves",
                              "other"})
      EXPECT_EQ(seconds.count(phase), 1u) << phase << "\n" << o.output;
    // The rows and the total are rounded to 1 ms each.
    EXPECT_NEAR(sum, std::stod(total[1]), 1e-3 * (seconds.size() + 1))
      << o.output;
  }

  TEST(Driver, ThreadCountsThatAreNotOneToManyAreRefused)
  {
    for (const char *count : {"0", "two", "-1", "100000"})
      {
        const rodnet::testing::DriverOutcome o =
          rodnet::testing::run_driver_with(std::string("x.prm --threads ") +
                                           count);
        EXPECT_EQ(o.exit_code, 1) << o.output;
        EXPECT_NE(o.output.find("--threads needs a whole number"),
                  std::string::npos)
          << count << ": " << o.output;
      }
  }

  // More processes than DoFs (a clamped rod of two segments, 11 DoFs, on
  // 12): one message naming the counts, printed once, and no output
  // directory left behind.
  TEST(Driver, MoreProcessesThanDofsAreRefusedOnce)
  {
    if (std::system("command -v mpirun > /dev/null 2>&1") != 0)
      GTEST_SKIP() << "no mpirun";
    const std::string output = "out_twelve_processes";
    fs::remove_all(output);
    std::ofstream("twelve_processes.prm")
      << "subsection Geometry\n  set Segments = 2\nend\n"
         "subsection Supports\n  set Clamped ends = start\nend\n"
         "subsection Loads\n  set Point forces = end: 0, 0, 1e-3\nend\n" +
           rodnet::testing::direct_material();
    // This test program is an MPI process itself: its Open MPI variables
    // would make mpirun's processes join it instead of starting their own.
    const rodnet::testing::DriverOutcome o = rodnet::testing::run_command(
      "for v in $(env | grep -o '^\\(OMPI\\|PMIX\\)[A-Za-z0-9_]*'); do "
      "unset $v; done; ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" "
      "mpirun --allow-run-as-root --oversubscribe -np 12 " +
      std::string(RODNET_BINARY_DIR) +
      "/rodnet-run twelve_processes.prm --output " + output);
    EXPECT_EQ(o.exit_code, 1) << o.output;
    const std::string message =
      "the network has 11 DoFs for 12 processes, too few for each to own "
      "one";
    const auto first = o.output.find(message);
    ASSERT_NE(first, std::string::npos) << o.output;
    EXPECT_EQ(o.output.find(message, first + 1), std::string::npos)
      << "printed by more than one process:\n"
      << o.output;
    EXPECT_FALSE(fs::exists(output));
  }
} // namespace
