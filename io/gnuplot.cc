#include <base/mpi_session.h>
#include <io/gnuplot.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace rodnet
{
  std::string
  gnuplot_quote(const std::string &text)
  {
    std::string quoted = "'";
    for (const char c : text)
      quoted += (c == '\'') ? std::string("''") : std::string(1, c);
    return quoted + "'";
  }

  namespace
  {
    /// The last line of @p messages that is not blank, trimmed at its end.
    std::string
    last_line(const std::string &messages)
    {
      const std::size_t end = messages.find_last_not_of(" \t\r\n");
      if (end == std::string::npos)
        return "";
      const std::size_t newline = messages.rfind('\n', end);
      const std::size_t begin =
        (newline == std::string::npos) ? 0 : newline + 1;
      return messages.substr(begin, end + 1 - begin);
    }
  } // namespace

  // posix_spawnp rather than std::system: no shell sees the path.
  std::string
  run_gnuplot(const std::string &script_path)
  {
    std::array<int, 2> pipe_ends;
    // Close-on-exec: no other program started meanwhile by another
    // thread inherits the pipe (dup2 clears the flag on the child's
    // stderr).
    if (pipe2(pipe_ends.data(), O_CLOEXEC) != 0)
      return std::string("cannot create a pipe: ") + std::strerror(errno);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions,
                                     STDOUT_FILENO,
                                     "/dev/null",
                                     O_WRONLY,
                                     0);

    std::string program  = "gnuplot";
    std::string argument = script_path;
    char *const argv[]   = {program.data(), argument.data(), nullptr};
    pid_t       pid;
    const int   spawn_error =
      posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipe_ends[1]);
    if (spawn_error != 0)
      {
        close(pipe_ends[0]);
        return std::string("cannot run gnuplot: ") + std::strerror(spawn_error);
      }

    // Drain stderr before waiting, so that a chatty gnuplot cannot block
    // on a full pipe.
    std::string            messages;
    std::array<char, 4096> buffer;
    ssize_t                n;
    while ((n = read(pipe_ends[0], buffer.data(), buffer.size())) > 0 ||
           (n < 0 && errno == EINTR))
      if (n > 0)
        messages.append(buffer.data(), n);
    close(pipe_ends[0]);

    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
      if (errno != EINTR)
        return std::string("waiting for gnuplot failed: ") +
               std::strerror(errno);

    if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
      return "";
    // gnuplot ends its report of a script error with the message itself,
    // after the offending line and a caret.
    const std::string last = last_line(messages);
    const std::string exit_text =
      WIFEXITED(status) ?
        "gnuplot exited with code " + std::to_string(WEXITSTATUS(status)) :
        "gnuplot was killed";
    return last.empty() ? exit_text : exit_text + ": " + last;
  }

  std::string
  draw_with_gnuplot(const std::string &script, const std::string &image_path)
  {
    if (!writes_outputs())
      return "";
    const std::string script_path = image_path + ".gp";
    {
      std::ofstream file(script_path);
      file << script;
      if (!file)
        return "cannot write the script \"" + script_path + "\"";
    }
    return run_gnuplot(script_path);
  }
} // namespace rodnet
