#include "report/subprocess.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>
#include <utility>

#include "common/errors.h"
#include "common/interrupt.h"

extern char** environ;

namespace multicpg::report {
namespace {

// Output goes to an anonymous temporary file rather than a pipe, so a chatty child can never
// block on a full pipe while we are busy writing its input or waiting for it.
int make_output_file() {
  const auto dir = std::filesystem::temp_directory_path();
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) {
    throw RuntimeFailure("cannot create a temporary file in " + dir.string() + ": " +
                         std::strerror(errno));
  }
  return fd;
}

std::string read_all(int fd) {
  std::string text;
  if (::lseek(fd, 0, SEEK_SET) < 0) return text;
  char buf[4096];
  ssize_t n = 0;
  while ((n = ::read(fd, buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(n));
  return text;
}

std::vector<char*> c_argv(const std::vector<std::string>& argv) {
  std::vector<char*> out;
  for (const auto& a : argv) out.push_back(const_cast<char*>(a.c_str()));
  out.push_back(nullptr);
  return out;
}

// Spawns argv with the given stdin source (a file descriptor, or -1 for /dev/null) and both
// output streams into out_fd.
pid_t spawn(const std::vector<std::string>& argv, int stdin_fd, int out_fd) {
  if (argv.empty()) throw RuntimeFailure("no program to run");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdin_fd >= 0) {
    posix_spawn_file_actions_adddup2(&actions, stdin_fd, STDIN_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  }
  posix_spawn_file_actions_adddup2(&actions, out_fd, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out_fd, STDERR_FILENO);
  pid_t pid = -1;
  auto args = c_argv(argv);
  const int rc = ::posix_spawnp(&pid, argv[0].c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw RuntimeFailure("cannot run " + argv[0] + ": " + std::strerror(rc));
  return pid;
}

// Fills in how the child ended from its wait status.
void set_ending(ProcessResult& result, int status) {
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

// Kills the child and reaps it: a tool whose work is abandoned must not outlive us.
void kill_and_reap(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

// How often a wait looks whether a signal asked this process to stop: well under the second
// within which SIGINT and SIGTERM must end a command (docs/cli.md "Exit codes and signals").
constexpr auto kWaitPoll = std::chrono::milliseconds(10);

// The child's wait status; when SIGINT or SIGTERM asks this process to stop while it waits, the
// child is killed and reaped and Interrupted thrown (common/interrupt.h).
int wait_status(pid_t pid) {
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return status;
    if (done < 0 && errno != EINTR) {
      throw RuntimeFailure("cannot wait for a child process: " + std::string(std::strerror(errno)));
    }
    if (const int signal = interrupt_signal(); signal != 0) {
      kill_and_reap(pid);
      throw Interrupted(signal);
    }
    std::this_thread::sleep_for(kWaitPoll);
  }
}

// Waits for the child `pid` to end and reads what it wrote to `output_fd`, which it closes.
ProcessResult collect(pid_t pid, int output_fd) {
  ProcessResult result;
  try {
    set_ending(result, wait_status(pid));
  } catch (...) {
    ::close(output_fd);
    throw;
  }
  result.output = read_all(output_fd);
  ::close(output_fd);
  return result;
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv) {
  const int output_fd = make_output_file();
  pid_t pid = -1;
  try {
    pid = spawn(argv, -1, output_fd);
  } catch (...) {
    ::close(output_fd);
    throw;
  }
  return collect(pid, output_fd);
}

ChildWithInput::ChildWithInput(const std::vector<std::string>& argv) {
  // A socket rather than a pipe: send(MSG_NOSIGNAL) reports a dead reader as EPIPE instead of
  // killing this process with SIGPIPE.
  int sv[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
    throw RuntimeFailure(std::string("socketpair failed: ") + std::strerror(errno));
  }
  output_fd_ = make_output_file();
  try {
    pid_ = spawn(argv, sv[1], output_fd_);
  } catch (...) {
    ::close(sv[0]);
    ::close(sv[1]);
    ::close(output_fd_);
    throw;
  }
  ::close(sv[1]);
  input_fd_ = sv[0];
}

ChildWithInput::~ChildWithInput() {
  if (pid_ <= 0) return;
  ::close(input_fd_);
  kill_and_reap(pid_);
  ::close(output_fd_);
}

bool ChildWithInput::write(std::span<const unsigned char> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::send(input_fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return true;
}

ProcessResult ChildWithInput::finish() {
  if (pid_ <= 0) return {};
  ::close(input_fd_);
  input_fd_ = -1;
  return collect(std::exchange(pid_, -1), std::exchange(output_fd_, -1));
}

std::string tool_error(const ProcessResult& result) {
  const std::string ending = result.signal != 0
                                 ? "killed by signal " + std::to_string(result.signal) + " (" +
                                       ::strsignal(result.signal) + ")"
                                 : "exit status " + std::to_string(result.exit_code);
  const std::string& text = result.output;
  const auto end = text.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return ending + ", printed nothing";
  const auto newline = text.find_last_of("\r\n", end);
  const auto start = newline == std::string::npos ? 0 : newline + 1;
  return ending + ": " + text.substr(start, end + 1 - start);
}

}  // namespace multicpg::report
