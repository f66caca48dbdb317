// Results you can trust: output files never replace special files or symlinks, an
// output directory has one owner, saved runs carry a checksum, strays of killed runs are removed,
// and failures (exploding physics, unwritable stdout, absurd step counts) are reported as such.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/atomic_file.h"
#include "common/checksum.h"
#include "common/dir_lock.h"
#include "common/errors.h"
#include "experiments/runner.h"
#include "tests/cli_runner.h"

namespace multicpg {
namespace {

namespace fs = std::filesystem;
using experiments::RunnerOptions;
using experiments::Task;
using testing::count_lines;
using testing::expect_bad_input;
using testing::make_temp_dir;
using testing::read_file;
using testing::run_cli;
using testing::run_shell;

// A short walk: enough for a CSV header and a few rows.
const std::string kShortWalk = "walk --steps 3 --window 2 ";

class TempDir {
 public:
  TempDir() : path_(make_temp_dir("integrity-")) {}
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The pid of a process that has ended (a child that exited at once and was reaped).
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

std::vector<Task> tasks() {
  std::vector<Task> out;
  for (int run = 0; run < 3; ++run) {
    const std::string key = experiments::run_key("R1", run);
    out.push_back({key, "R1", run, experiments::derive_seed(1, key), {{"beta", 0.5}}});
  }
  return out;
}

nlohmann::json result_of(const Task& task) {
  return {{"trials", task.run + 1}, {"final_deviation_deg", 1.25 * task.run}};
}

RunnerOptions runner_options(const fs::path& out) {
  RunnerOptions o;
  o.out_dir = out;
  o.jobs = 1;
  o.arguments = {{"seed", 1}};
  o.progress = false;
  return o;
}

TEST(AtomicFile, DevNullStaysADevice) {
  const auto r = run_cli(kShortWalk + "--csv /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null was replaced";
}

TEST(AtomicFile, SymlinkStaysAndItsTargetIsWritten) {
  TempDir dir;
  const fs::path real = dir.path() / "real.csv";
  const fs::path link = dir.path() / "link.csv";
  fs::create_symlink("real.csv", link);  // relative, and dangling until written
  const auto r = run_cli(kShortWalk + "--csv " + link.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(count_lines(read_file(real)), 1 + 3 + 1);  // header, start row, one per step
  EXPECT_EQ(fs::read_symlink(link), "real.csv");
}

TEST(AtomicFile, FifoWithoutReaderIsRefused) {
  TempDir dir;
  const fs::path fifo = dir.path() / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_bad_input(kShortWalk + "--csv " + fifo.string(), "FIFO has no reader");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(AtomicFile, FifoWithReaderIsWrittenThrough) {
  TempDir dir;
  const fs::path fifo = dir.path() / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Our own reader, open before the writer starts; the few rows fit in the pipe's buffer.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const auto r = run_cli(kShortWalk + "--csv " + fifo.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string text(1 << 16, '\0');
  const ssize_t n = ::read(reader, text.data(), text.size());
  ::close(reader);
  ASSERT_GT(n, 0);
  text.resize(static_cast<std::size_t>(n));
  EXPECT_EQ(count_lines(text), 1 + 3 + 1);
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(AtomicFile, FailedCommitLeavesTheOldFile) {
  TempDir dir;
  const fs::path path = dir.path() / "out.txt";
  write_file_atomic(path, "old\n");
  {
    AtomicFile file(path);
    file.stream() << "new\n";
    EXPECT_THROW(file.commit([](const fs::path&) { throw RuntimeFailure("refused"); }),
                 RuntimeFailure);
  }
  EXPECT_EQ(read_file(path), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1)
      << "the temporary file was left behind";
}

TEST(DirLock, SecondClaimIsRefused) {
  TempDir dir;
  const DirLock first(dir.path());
  try {
    const DirLock second(dir.path());
    ADD_FAILURE() << "a second lock was granted";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("in use by another multicpg process (pid " +
                                         std::to_string(::getpid()) + ")"),
              std::string::npos)
        << e.what();
  }
}

TEST(DirLock, ExperimentOnALockedDirectoryIsRefused) {
  TempDir dir;
  const DirLock held(dir.path());
  expect_bad_input("experiment table --robot quadruped --runs 1 --out " + dir.path().string(),
                   "in use by another multicpg process");
  EXPECT_FALSE(fs::exists(dir.path() / "experiment.json"));
}

TEST(Checksum, Fnv1a64KnownValues) {
  // Published FNV-1a 64 test vectors (http://www.isthe.com/chongo/src/fnv/test_fnv.c).
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
  EXPECT_EQ(checksum_text("a"), "fnv1a64:af63dc4c8601ec8c");
}

TEST(RunFiles, EditedRunIsNamedOnResume) {
  TempDir dir;
  const std::vector<Task> list = tasks();
  experiments::run_tasks(list, result_of, runner_options(dir.path()));
  const fs::path run = dir.path() / "runs" / (list[1].key + ".json");
  std::string text = read_file(run);
  const std::size_t at = text.find("\"trials\": 2");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, 11, "\"trials\": 3");
  std::ofstream(run) << text;
  try {
    experiments::run_tasks(list, result_of, runner_options(dir.path()));
    ADD_FAILURE() << "an edited run was loaded";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find(run.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("checksum does not match"), std::string::npos);
  }
}

TEST(RunFiles, TruncatedAndUncheckedFilesAreDamaged) {
  const std::string sealed =
      read_file(std::string(MULTICPG_SOURCE_DIR) + "/fuzz/corpus/parsers/run_file.json");
  ASSERT_FALSE(sealed.empty());
  EXPECT_NO_THROW(experiments::parse_sealed(sealed, "run.json"));
  for (const std::string& bad :
       {sealed.substr(0, sealed.size() / 2), std::string("[1, 2]"), std::string("{\"a\": 1}")}) {
    EXPECT_THROW(experiments::parse_sealed(bad, "run.json"), BadInput) << bad;
  }
}

TEST(RunFiles, DamagedExperimentRecordIsNamedWithExit2) {
  TempDir dir;
  std::ofstream(dir.path() / "experiment.json") << "{\"arguments\": {\"seed\": ";
  expect_bad_input("experiment table --robot quadruped --runs 1 --out " + dir.path().string(),
                   (dir.path() / "experiment.json").string() + "' is damaged");
}

TEST(RunFiles, StrayTemporaryFilesOfKilledRunsAreRemoved) {
  TempDir dir;
  fs::create_directories(dir.path() / "runs");
  const std::string dead = std::to_string(dead_pid());
  const fs::path stray_run = dir.path() / "runs" / ("R1_run000.json.tmp" + dead);
  const fs::path stray_table = dir.path() / ("table.csv.tmp" + dead);
  const fs::path live = dir.path() / "table.csv.tmp1";  // pid 1 runs: not a stray
  for (const fs::path& p : {stray_run, stray_table, live}) std::ofstream(p) << "half";
  experiments::run_tasks(tasks(), result_of, runner_options(dir.path()));
  EXPECT_FALSE(fs::exists(stray_run));
  EXPECT_FALSE(fs::exists(stray_table));
  EXPECT_TRUE(fs::exists(live));
}

TEST(Failures, ExplodingPhysicsFailsNamingTheStep) {
  const auto r = run_cli("tunnel --disable R1 --control-dt 0.2 --physics-dt 0.05");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("unstable at step "), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(Failures, AbsurdStepCountsAreBadInput) {
  expect_bad_input(kShortWalk + "--control-dt 1000000 --physics-dt 1e-9", "--control-dt");
  expect_bad_input("walk --settle 9223372036854775000", "--settle: must be in 0..100000000");
  expect_bad_input("walk --warmup 9223372036854775000", "--warmup: must be in 0..100000000");
}

TEST(Failures, UnwritableStdoutExits1) {
  const auto r = run_shell(std::string(MULTICPG_EXE) + " " + kShortWalk + "--json > /dev/full");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "multicpg: cannot write standard output\n");
}

}  // namespace
}  // namespace multicpg
