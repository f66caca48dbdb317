// A multicpg process started by a test without a shell, so the test knows its pid: it can send
// it signals, read its memory from /proc while it runs, and wait for it with a hang guard.
// Standard output and error go to files of a scratch folder.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace multicpg::testing {

class CliProcess {
 public:
  // Starts MULTICPG_EXE with `args` in the folder `cwd` (the test's when empty).
  explicit CliProcess(const std::vector<std::string>& args, const std::filesystem::path& cwd = {});
  CliProcess(const CliProcess&) = delete;
  CliProcess& operator=(const CliProcess&) = delete;
  ~CliProcess();  // kills it if it still runs

  pid_t pid() const { return pid_; }
  void signal(int sig) const;
  // A "kB" field of /proc/PID/status (VmHWM: peak resident memory, VmRSS: now); -1 once gone.
  long status_kb(const std::string& field) const;

  // Waits at most `limit` (a hang guard, not a timing claim); false, after killing it, if it did
  // not end by then.
  bool wait(std::chrono::seconds limit);
  bool running() const { return !ended_; }

  // Once ended: the exit code (-signal when a signal killed it) and its peak memory (wait4).
  int exit_code() const { return exit_code_; }
  long max_rss_kb() const { return max_rss_kb_; }
  std::string out() const;
  std::string err() const;

 private:
  pid_t pid_ = -1;
  std::filesystem::path scratch_;
  bool ended_ = false;
  int exit_code_ = -1;
  long max_rss_kb_ = -1;
};

// Looks at `done` every few milliseconds until it is true or `limit` passed; returns it.
bool wait_until(const std::function<bool()>& done, std::chrono::seconds limit);

}  // namespace multicpg::testing
