// Error kinds the CLI maps to exit codes: BadInput -> 2, RuntimeFailure -> 1, GoalNotReached ->
// 3, Interrupted -> 128 + the signal (130 for SIGINT, 143 for SIGTERM; docs/cli.md "Exit codes and
// signals"). Every message is made printable (common/user_text.h): text the user typed that holds a
// NUL, newline or escape sequence is shown escaped, on one line, whole.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "common/user_text.h"

namespace multicpg {

// The user gave something the program cannot accept (flag, file, leg name, period, path).
class BadInput : public std::runtime_error {
 public:
  explicit BadInput(const std::string& what) : std::runtime_error(printable(what)) {}
};

// A bad value of one option, named by its key: the dotted path of the option in its JSON record
// ("annealing.beta"). The CLI names the flag bound to the key, an experiment file the file, line
// and key; what() is the message without either ("must be at least 0, got -1"). key() is as
// given (it finds the key's line in a file): print it through printable().
class OptionError : public BadInput {
 public:
  OptionError(std::string key, const std::string& what) : BadInput(what), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Valid input, but the run itself failed (physics blow-up, I/O failure mid-run, ...).
class RuntimeFailure : public std::runtime_error {
 public:
  explicit RuntimeFailure(const std::string& what) : std::runtime_error(printable(what)) {}
};

// The run went to its end and wrote every output, but did not reach what it was run for: learning
// that did not converge. Its output has said so; the exit code says it to a script (docs/cli.md
// "Exit codes and signals").
class GoalNotReached : public std::runtime_error {
 public:
  explicit GoalNotReached(const std::string& what) : std::runtime_error(printable(what)) {}
  static constexpr int kExitCode = 3;
};

// The user stopped the run (SIGINT or SIGTERM, common/interrupt.h). Thrown where the work checks
// for it and unwinds like any error, so temporary files are removed by their owners.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal) : std::runtime_error(message(signal)), signal_(signal) {}
  int signal() const { return signal_; }
  int exit_code() const { return kSignalExitBase + signal_; }
  // The shell's convention for a process ended by a signal.
  static constexpr int kSignalExitBase = 128;

 private:
  static std::string message(int signal) {
    constexpr int kSigint = 2;  // POSIX fixes both numbers
    constexpr int kSigterm = 15;
    return signal == kSigint    ? "interrupted by SIGINT"
           : signal == kSigterm ? "interrupted by SIGTERM"
                                : "interrupted by signal " + std::to_string(signal);
  }

  int signal_;
};

}  // namespace multicpg
