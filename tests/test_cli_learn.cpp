// The real multicpg binary: learn and experiment commands (issue 4).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

TEST(CliLearn, PrintsTheTraceAndTheFinalCombination) {
  const auto r = run_cli("learn --robot hexapod --disable R1 --seed 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("trial  R1  R2  R3  L1  L2  L3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4x"), std::string::npos) << "disabled legs are marked";
  EXPECT_NE(r.out.find("converged after"), std::string::npos) << r.out;
}

TEST(CliLearn, JsonHasTheDocumentedFields) {
  const auto r = run_cli("learn --disable R1 --seed 2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("converged").is_boolean());
  EXPECT_TRUE(j.at("trials").is_number_integer());
  EXPECT_TRUE(j.at("final_deviation_deg").is_number());
  EXPECT_EQ(j.at("periods").size(), 6u);
  EXPECT_EQ(j.at("periods").at("R1"), 4);
  ASSERT_EQ(j.at("trace").size(), j.at("trials").get<std::size_t>());
  for (const auto& t : j.at("trace")) {
    EXPECT_EQ(t.at("periods").size(), 6u);
    EXPECT_TRUE(t.at("deviation_deg").is_number());
    EXPECT_TRUE(t.at("accepted").is_boolean());
  }
  // Same seed, same run.
  EXPECT_EQ(run_cli("learn --disable R1 --seed 2 --json").out, r.out);
}

TEST(CliLearn, OutKeepsTraceAndPerStepRecord) {
  const std::string dir = make_temp_dir("learn-");
  const auto r = run_cli("learn --robot quadruped --disable L2 --seed 1 --out " + dir + "/run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(read_file(fs::path(dir) / "run/learning.json"));
  const std::string trace = read_file(fs::path(dir) / "run/trace.csv");
  EXPECT_EQ(trace.substr(0, trace.find('\n')),
            "trial,R1,R2,L1,L2,deviation_deg,accepted,acceptance_probability");
  EXPECT_EQ(count_lines(trace), j.at("trials").get<int>() + 1);
  const std::string steps = read_file(fs::path(dir) / "run/steps.csv");
  EXPECT_EQ(steps.rfind("step,time_s,x_m,y_m,z_m,yaw_deg,R1_TC_command,", 0), 0u);
  EXPECT_EQ(count_lines(steps), j.at("steps_walked").get<int>() + 2);  // header + row 0
  fs::remove_all(dir);
}

TEST(CliLearn, BadInput) {
  expect_bad_input("learn --disable R1 --beta -1", "beta");
  expect_bad_input("learn --disable R1 --threshold 0", "threshold");
  expect_bad_input("learn --disable R1 --window 0", "window");
  expect_bad_input("learn --disable R1 --max-trials 0", "max trials");
  expect_bad_input("learn --disable R1,R2,R3,L1,L2,L3", "every leg");
  expect_bad_input("learn --disable R9", "R9");
  expect_bad_input("learn --robot quadruped --disable R3", "R3");
  expect_bad_input("learn --robot spider --disable R1", "spider");
  expect_bad_input("learn", "--disable");
  expect_bad_input("learn --disable R1 --out /proc/multicpg-out", "/proc/multicpg-out");
  expect_bad_input("learn --disable R1 --disable-at -3", "--disable-at");
}

TEST(CliExperiment, BadInput) {
  const std::string dir = make_temp_dir("exp-");
  expect_bad_input("experiment table --runs 0 --out " + dir, "--runs");
  expect_bad_input("experiment table --jobs 0 --out " + dir, "--jobs");
  expect_bad_input("experiment table --robot octopod --out " + dir, "octopod");
  expect_bad_input("experiment table --out /proc/multicpg-out", "/proc/multicpg-out");
  expect_bad_input("experiment beta --runs 0 --out " + dir, "--runs");
  expect_bad_input("experiment beta --threshold -2 --out " + dir, "threshold");
  expect_bad_input("experiment results --out " + dir + "/r.md", "--hexapod");
  expect_bad_input("experiment results --hexapod " + dir + "/none --out " + dir + "/r.md",
                   "summary.json");
  fs::remove_all(dir);
}

// Saved runs of an experiment directory, file name -> contents.
std::map<std::string, std::string> saved_runs(const fs::path& dir) {
  std::map<std::string, std::string> out;
  if (!fs::exists(dir / "runs")) return out;
  for (const auto& e : fs::directory_iterator(dir / "runs")) {
    if (e.path().extension() == ".json") out[e.path().filename()] = read_file(e.path());
  }
  return out;
}

TEST(CliExperiment, JobsDoNotChangeTheTableAndAKilledRunResumes) {
  const std::string dir = make_temp_dir("exp-");
  const std::string args = "experiment table --robot quadruped --runs 1 --seed 7 ";
  ASSERT_EQ(run_cli(args + "--jobs 1 --out " + dir + "/one").exit_code, 0);
  ASSERT_EQ(run_cli(args + "--jobs 2 --out " + dir + "/two").exit_code, 0);
  const std::string table = read_file(fs::path(dir) / "one/table.csv");
  EXPECT_EQ(count_lines(table), 5);  // header + R1, R2, L1, L2
  EXPECT_EQ(read_file(fs::path(dir) / "two/table.csv"), table);

  // Start, kill hard once two runs are saved, start again: same table, saved runs untouched.
  const fs::path killed = fs::path(dir) / "killed";
  run_shell("cd " + dir + " && (" + std::string(MULTICPG_EXE) + " " + args +
            "--jobs 1 --out killed >/dev/null 2>&1 & echo $! > pid)");
  const std::string pid = read_file(fs::path(dir) / "pid");
  constexpr int kMaxPolls = 6000;  // a bound on the wait, not a timing assertion
  for (int i = 0; i < kMaxPolls && saved_runs(killed).size() < 2; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  run_shell("kill -9 " + pid);
  const auto before = saved_runs(killed);
  ASSERT_GE(before.size(), 2u);
  ASSERT_LT(before.size(), 4u) << "the experiment finished before it could be killed";
  const auto resumed = run_cli(args + "--jobs 1 --out " + killed.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_file(killed / "table.csv"), table);
  const auto after = saved_runs(killed);
  for (const auto& [name, text] : before) EXPECT_EQ(after.at(name), text) << name;

  // Resuming with other arguments is refused.
  const auto other =
      run_cli("experiment table --robot quadruped --runs 1 --seed 8 --out " + killed.string());
  EXPECT_EQ(other.exit_code, 2);
  fs::remove_all(dir);
}

TEST(CliExperiment, ResultsPageSetsOursBesideThePaper) {
  const std::string dir = make_temp_dir("exp-");
  ASSERT_EQ(run_cli("experiment table --robot quadruped --runs 1 --out " + dir + "/q").exit_code,
            0);
  const auto r = run_cli("experiment results --quadruped " + dir + "/q --out " + dir + "/r.md");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_file(fs::path(dir) / "r.md");
  EXPECT_NE(page.find("## Quadruped: learning per scenario (paper Fig. 13)"), std::string::npos);
  EXPECT_NE(page.find("| The paper states | Ours |"), std::string::npos);
  EXPECT_NE(page.find("| R1 | 1 |"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
