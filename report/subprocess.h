// Running the external tools the report layer drives (gnuplot, ffmpeg) without a shell, so
// paths need no quoting and a missing tool is reported, not guessed from a shell's exit code.
#pragma once

#include <sys/types.h>

#include <span>
#include <string>
#include <vector>

namespace multicpg::report {

struct ProcessResult {
  int exit_code = -1;  // -1 when the process did not exit normally (signal)
  int signal = 0;      // the signal that ended it, 0 when it exited
  std::string output;  // everything it wrote to standard output and standard error
};

// Runs argv[0] (looked up in PATH) with standard input closed, waits for it and captures what
// it printed. Throws RuntimeFailure when the program cannot be started; Interrupted (after
// killing it) when SIGINT or SIGTERM asks this process to stop meanwhile (common/interrupt.h).
ProcessResult run_process(const std::vector<std::string>& argv);

// A child process fed through its standard input (ffmpeg reading raw frames). Writing never
// raises SIGPIPE: a child that died makes write() return false instead.
class ChildWithInput {
 public:
  explicit ChildWithInput(const std::vector<std::string>& argv);
  ChildWithInput(const ChildWithInput&) = delete;
  ChildWithInput& operator=(const ChildWithInput&) = delete;
  // Without finish(): the work is abandoned, the child killed and reaped (none outlives us).
  ~ChildWithInput();

  // Sends all bytes; false when the child stopped reading.
  bool write(std::span<const unsigned char> bytes);
  // Closes the input, waits for the child and returns how it ended (Interrupted as
  // run_process).
  ProcessResult finish();

 private:
  pid_t pid_ = -1;
  int input_fd_ = -1;
  int output_fd_ = -1;
};

// How a tool ended and the last line it printed (gnuplot and ffmpeg end with the error that
// stopped them), for one-line error messages: "exit status 1: line 3: undefined variable: x",
// "killed by signal 9 (Killed)", "exit status 0, printed nothing".
std::string tool_error(const ProcessResult& result);

}  // namespace multicpg::report
