// SIGINT and SIGTERM during long commands, through the real CLI (docs/cli.md "Exit codes and
// signals"): the command stops with 130 or 143 and one line, leaves no file under its final name
// that is incomplete (and no temporary file behind), and an experiment started again resumes from
// the runs it saved. The waits are hang guards of several seconds, not timing claims.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli_process.h"
#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;

// How long a command may take to get going, and to stop once signalled: hang guards.
constexpr std::chrono::seconds kStartGuard{60};
constexpr std::chrono::seconds kStopGuard{20};

struct Signal {
  int number;
  int exit_code;
  std::string name;
};
const std::vector<Signal> kSignals{{SIGTERM, 143, "SIGTERM"}, {SIGINT, 130, "SIGINT"}};

// Files under `dir` (recursively) whose name has `part`.
std::vector<fs::path> files_with(const fs::path& dir, const std::string& part) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().filename().string().find(part) != std::string::npos) out.push_back(e.path());
  }
  return out;
}

// A temporary file (common/atomic_file.h: "*.tmp<pid>") of `path` with something in it.
bool streaming(const fs::path& path, pid_t pid) {
  const fs::path tmp = path.string() + ".tmp" + std::to_string(pid);
  std::error_code ec;
  return fs::exists(tmp, ec) && fs::file_size(tmp, ec) > 0;
}

// Signals `cli` and checks it stopped as a signalled command must: the exit code, one line.
void expect_stopped(CliProcess& cli, const Signal& s) {
  cli.signal(s.number);
  ASSERT_TRUE(cli.wait(kStopGuard)) << "did not stop after " << s.name;
  EXPECT_EQ(cli.exit_code(), s.exit_code) << cli.err();
  EXPECT_EQ(cli.err(), "multicpg: interrupted by " + s.name + "\n");
}

TEST(Signals, WalkWithCsvStopsAndLeavesNoCsv) {
  for (const Signal& s : kSignals) {
    SCOPED_TRACE(s.name);
    const std::string dir = make_temp_dir("multicpg-sig-walk-");
    const fs::path csv = fs::path(dir) / "walk.csv";
    CliProcess cli({"walk", "--steps", "100000000", "--csv", csv.string()});
    ASSERT_TRUE(wait_until([&] { return streaming(csv, cli.pid()); }, kStartGuard)) << cli.err();
    expect_stopped(cli, s);
    EXPECT_FALSE(fs::exists(csv));
    EXPECT_TRUE(files_with(dir, ".tmp").empty());
    EXPECT_EQ(cli.out(), "");
    fs::remove_all(dir);
  }
}

TEST(Signals, LearnWithOutStopsAndLeavesNoFiles) {
  for (const Signal& s : kSignals) {
    SCOPED_TRACE(s.name);
    const std::string dir = make_temp_dir("multicpg-sig-learn-");
    // A threshold no window meets: learning goes on until stopped.
    CliProcess cli({"learn", "--disable", "R1", "--mode", "paper", "--threshold", "0.001",
                    "--max-trials", "100000", "--out", dir});
    ASSERT_TRUE(
        wait_until([&] { return streaming(fs::path(dir) / "steps.csv", cli.pid()); }, kStartGuard))
        << cli.err();
    expect_stopped(cli, s);
    for (const char* name : {"steps.csv", "learning.json", "trace.csv"}) {
      EXPECT_FALSE(fs::exists(fs::path(dir) / name)) << name;
    }
    EXPECT_TRUE(files_with(dir, ".tmp").empty());
    fs::remove_all(dir);
  }
}

// Six short runs on two threads: interrupted after the first is saved, then resumed.
const std::string kSixRuns = R"(scenarios = ["R1"]
runs = 6
seed = 4
[learning]
mode = "paper"
[learning.annealing]
max_trials = 3
)";

TEST(Signals, RunStopsKeepsItsSavedRunsAndResumes) {
  const std::string dir = make_temp_dir("multicpg-sig-run-");
  const fs::path file = fs::path(dir) / "six.toml";
  std::ofstream(file) << kSixRuns;
  const fs::path out = fs::path(dir) / "out";
  const auto saved = [&] {
    std::error_code ec;
    return fs::exists(out / "runs", ec) ? files_with(out / "runs", ".json").size() : 0;
  };
  {
    CliProcess cli({"run", file.string(), "--jobs", "2", "--out", out.string()});
    ASSERT_TRUE(wait_until([&] { return saved() >= 1; }, kStartGuard)) << cli.err();
    cli.signal(SIGINT);
    ASSERT_TRUE(cli.wait(kStopGuard));
    EXPECT_EQ(cli.exit_code(), 130) << cli.err();
    // The progress lines go to stderr too; the last line says why it stopped.
    const std::string err = cli.err();
    EXPECT_NE(err.rfind("multicpg: interrupted by SIGINT\n"), std::string::npos) << err;
  }
  const std::size_t kept = saved();
  EXPECT_GE(kept, 1u);
  EXPECT_TRUE(files_with(out, ".tmp").empty());
  EXPECT_FALSE(fs::exists(out / "runs.csv")) << "tables of an unfinished experiment";
  for (const fs::path& run : files_with(out / "runs", ".json")) {
    EXPECT_TRUE(nlohmann::json::parse(read_file(run.string()), nullptr, false).is_object()) << run;
  }
  if (kept < 6) {
    CliProcess again({"run", file.string(), "--jobs", "2", "--out", out.string()});
    ASSERT_TRUE(again.wait(kStartGuard));
    EXPECT_EQ(again.exit_code(), 0) << again.err();
    EXPECT_NE(again.err().find("resuming: " + std::to_string(kept) + " of 6 runs already done"),
              std::string::npos)
        << again.err();
  }
  EXPECT_EQ(saved(), 6u);
  // The same results as a run never interrupted.
  const fs::path whole = fs::path(dir) / "whole";
  ASSERT_EQ(run_cli("run " + file.string() + " --jobs 2 --out " + whole.string()).exit_code, 0);
  for (const char* name : {"runs.csv", "trials.csv", "table.csv"}) {
    EXPECT_EQ(read_file((out / name).string()), read_file((whole / name).string())) << name;
  }
  fs::remove_all(dir);
}

// The threads of a running process (/proc/PID/status), 0 once it is gone.
int thread_count(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(line.find(':') + 1));
  }
  return 0;
}

// The learner benchmark replays for as long as it is let: stopped by either signal while its two
// threads replay, with no result written.
TEST(Signals, LearnerBenchmarkStopsAndWritesNoResult) {
  for (const Signal& s : kSignals) {
    SCOPED_TRACE(s.name);
    const std::string dir = make_temp_dir("multicpg-sig-bench-");
    CliProcess cli({"learner-benchmark", "--steering", "off", "--seeds", "100000", "--jobs", "2",
                    "--out", dir});
    ASSERT_TRUE(wait_until([&] { return thread_count(cli.pid()) >= 3; }, kStartGuard)) << cli.err();
    expect_stopped(cli, s);
    EXPECT_TRUE(fs::is_empty(dir));
    EXPECT_EQ(cli.out(), "");
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace multicpg::testing
