// `mpirun -np N multicpg experiment table`: the runs shared among N processes give the same run
// files, tables and output as one thread, a killed MPI job resumes to the same result, and a
// failing job ends with one line. Real mpirun, as root only in the tests' environment.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

// Small: 8 learning runs of at most 2 trials.
const std::string kExperiment =
    "experiment table --robot quadruped --runs 2 --max-trials 2 --seed 3 ";

#ifdef MULTICPG_MPI
// mpirun with the root permission (CI runs as root) and its help banners off (-q), as
// docs/experiments.md tells users; extra processes share the 2 cores (--oversubscribe).
std::string mpirun(int processes, const std::string& program = MULTICPG_EXE) {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MULTICPG_MPIEXEC
         " -q --oversubscribe -np " +
         std::to_string(processes) + " " + program + " ";
}
#endif

// Every file of an experiment directory that the results consist of, name -> contents.
std::map<std::string, std::string> result_files(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const char* name : {"experiment.json", "table.csv", "table.md", "summary.json"}) {
    out[name] = read_file((dir / name).string());
  }
  if (!fs::exists(dir / "runs")) return out;
  for (const auto& e : fs::directory_iterator(dir / "runs")) {
    out["runs/" + e.path().filename().string()] = read_file(e.path().string());
  }
  return out;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
  return text;
}

class Mpi : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef MULTICPG_MPI
    GTEST_SKIP() << "built without MPI (-DMULTICPG_MPI=OFF)";
#endif
    dir_ = make_temp_dir("mpi-");
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // The reference: the experiment on one thread of one process, run once for all tests.
  static const std::map<std::string, std::string>& one_thread() {
    static const std::map<std::string, std::string> files = [] {
      const std::string dir = make_temp_dir("mpi-ref-");
      const CliResult r = run_cli(kExperiment + "--jobs 1 --out " + dir + "/out");
      EXPECT_EQ(r.exit_code, 0) << r.err;
      auto f = result_files(fs::path(dir) / "out");
      f["stdout"] = replace_all(r.out, dir + "/out", "OUT");
      fs::remove_all(dir);
      return f;
    }();
    return files;
  }

  // Runs the experiment under `mpirun -np processes` into dir_/name; expects its files and
  // standard output to be those of one thread.
  void expect_same_as_one_thread([[maybe_unused]] int processes,
                                 [[maybe_unused]] const std::string& jobs) {
#ifdef MULTICPG_MPI
    const std::string out = dir_ + "/np" + std::to_string(processes);
    const CliResult r = run_shell(mpirun(processes) + kExperiment + jobs + " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto files = result_files(out);
    files["stdout"] = replace_all(r.out, out, "OUT");
    const auto& expected = one_thread();
    ASSERT_EQ(files.size(), expected.size());
    for (const auto& [name, text] : expected) {
      EXPECT_EQ(files[name], text) << name << " differs with " << processes << " processes";
    }
#endif
  }

  std::string dir_;
};

TEST_F(Mpi, OneProcessGivesTheFilesOfOneThread) {
  expect_same_as_one_thread(1, "--jobs 1");
}

TEST_F(Mpi, TwoProcessesGiveTheFilesOfOneThread) {
  expect_same_as_one_thread(2, "--jobs 1");
}

TEST_F(Mpi, ThreeProcessesOnTwoCoresGiveTheFilesOfOneThread) {
  expect_same_as_one_thread(3, "--jobs 1");
}

TEST_F(Mpi, ThreadsInsideProcessesGiveTheFilesOfOneThread) {
  expect_same_as_one_thread(2, "--jobs 2");
}

// `run FILE.toml` goes through the same runner: an experiment file under two processes gives the
// files of one thread, its tidy CSVs included. A sweep as small as kExperiment (two grid points of
// β, two scenarios, two runs of at most 2 trials), so that the runner, not the learning, is tested.
TEST_F(Mpi, AnExperimentFileUnderTwoProcessesGivesTheFilesOfOneThread) {
#ifdef MULTICPG_MPI
  const std::string file = dir_ + "/sweep.toml";
  std::ofstream(file)
      << "robot = \"quadruped\"\nscenarios = [\"R1\", \"L2\"]\nruns = 2\nseed = 3\n"
         "[learning]\nmode = \"paper\"\nsteering = \"off\"\n"
         "[learning.annealing]\nbeta = [0.5, 10]\nmax_trials = 2\n[record]\ntrace = true\n";
  ASSERT_EQ(run_cli("run " + file + " --jobs 1 --out " + dir_ + "/one").exit_code, 0);
  const CliResult r = run_shell(mpirun(2) + "run " + file + " --jobs 1 --out " + dir_ + "/two");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto one = result_files(dir_ + "/one");
  auto two = result_files(dir_ + "/two");
  for (const char* name : {"runs.csv", "trials.csv"}) {
    one[name] = read_file(dir_ + "/one/" + name);
    two[name] = read_file(dir_ + "/two/" + name);
  }
  EXPECT_EQ(one.size(), 14u);  // 8 runs, experiment.json, 3 tables, 2 CSVs
  for (const auto& [name, text] : one) {
    EXPECT_FALSE(text.empty()) << name;
    EXPECT_EQ(two[name], text) << name << " differs with 2 processes";
  }
#endif
}

#ifdef MULTICPG_MPI
// Whether some process still holds OUT's lock (a process of the killed job not yet ended).
bool locked(const fs::path& out) {
  const int fd = ::open((out / ".multicpg.lock").c_str(), O_RDONLY);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0;
  ::close(fd);
  return held;
}
#endif

TEST_F(Mpi, AKilledJobResumesToTheSameResult) {
#ifdef MULTICPG_MPI
  const fs::path out = fs::path(dir_) / "killed";
  run_shell("cd " + dir_ + " && (" + mpirun(2) + kExperiment +
            "--jobs 1 --out killed >/dev/null 2>&1 & echo $! > pid)");
  const std::string pid = read_file(dir_ + "/pid");
  const auto saved_runs = [&] {
    std::map<std::string, std::string> runs;
    for (const auto& [name, text] : result_files(out)) {
      if (name.rfind("runs/", 0) == 0) runs[name] = text;
    }
    return runs;
  };
  constexpr int kMaxPolls = 6000;  // bounds on the waits, not timing assertions
  constexpr auto kPoll = std::chrono::milliseconds(50);
  for (int i = 0; i < kMaxPolls && saved_runs().size() < 2; ++i) std::this_thread::sleep_for(kPoll);
  // mpirun and its processes (its children) at once, as a scheduler's cancel kills a job: killed
  // alone, mpirun leaves them running, and they can finish every run over shared memory (seen
  // once: all 8 runs saved after the kill).
  run_shell("kill -9 $(pgrep -P " + pid + ") " + pid);
  for (int i = 0; i < kMaxPolls && locked(out); ++i) std::this_thread::sleep_for(kPoll);
  ASSERT_FALSE(locked(out)) << "a process of the killed job still runs";
  const auto before = saved_runs();
  ASSERT_GE(before.size(), 2u);
  ASSERT_LT(before.size(), 8u) << "the experiment finished before it could be killed";

  const CliResult resumed = run_shell(mpirun(3) + kExperiment + "--jobs 1 --out " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  auto files = result_files(out);
  files["stdout"] = replace_all(resumed.out, out.string(), "OUT");
  for (const auto& [name, text] : one_thread()) EXPECT_EQ(files[name], text) << name;
  for (const auto& [name, text] : before) EXPECT_EQ(files[name], text) << name << " was redone";
#endif
}

TEST_F(Mpi, AFailingJobEndsWithOneLine) {
#ifdef MULTICPG_MPI
  // Bad input every process sees.
  CliResult r = run_shell(mpirun(3) + kExperiment + "--jobs 0 --out " + dir_ + "/bad");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--jobs: must be in 1..4096"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;

  // Bad input only the primary sees (OUT holds another experiment): the others are told.
  const std::string other = dir_ + "/other";
  ASSERT_EQ(run_cli("experiment table --robot quadruped --runs 1 --max-trials 1 --out " + other)
                .exit_code,
            0);
  r = run_shell(mpirun(3) + kExperiment + "--out " + other);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("holds an experiment made with other arguments"), std::string::npos)
      << r.err;

  // A run that fails on another process than the primary: the primary is told, stops handing
  // out runs, and the job ends with that run's error.
  r = run_shell(mpirun(3, MULTICPG_FAILING_JOB) + dir_ + "/in-run in-run");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("failed on process"), std::string::npos) << r.err;

  // A process that fails before it reaches the runner: the others, waiting there, end too.
  r = run_shell(mpirun(3, MULTICPG_FAILING_JOB) + dir_ + "/before-run before-run");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("process 1 cannot start"), std::string::npos) << r.err;

  // Commands that cannot share their work among processes say so, before any work.
  r = run_shell(mpirun(2) + "reproduce --quick --out " + dir_ + "/reproduce");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("'reproduce' runs in one process"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ + "/reproduce"));
  r = run_shell(mpirun(2) + "walk --steps 10");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'walk' runs in one process"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
#endif
}

}  // namespace
