// Results that a change of structure must not change: outputs recorded by the CLI before the runs
// were described by experiments::RunSpec (tests/data/golden), compared byte for byte (the CLI's
// JSON and CSVs) or value for value (a run file's result). A change of the physics or of the
// learning changes them on purpose; record them anew then, and say why in the commit.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;

std::string golden(const std::string& name) {
  const fs::path path = fs::path(MULTICPG_SOURCE_DIR) / "tests/data/golden" / name;
  const std::string text = read_file(path.string());
  EXPECT_FALSE(text.empty()) << path;
  return text;
}

// The repository's path in an output stands as "<repository>" in its golden file (a prior's
// dataset, learned_from): a checkout anywhere gives the same file.
std::string with_repository_placeholder(std::string text) {
  const std::string source = MULTICPG_SOURCE_DIR;
  for (std::size_t at = text.find(source); at != std::string::npos; at = text.find(source, at)) {
    text.replace(at, source.size(), "<repository>");
  }
  return text;
}

void expect_output(const std::string& args, const std::string& file) {
  const CliResult r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  EXPECT_EQ(with_repository_placeholder(r.out), golden(file)) << "multicpg " << args;
}

TEST(Golden, LearnTunnelAndWalkPrintWhatTheyPrinted) {
  // Robust mode with the annealing, its learner before the prior became the default where a
  // dataset is (docs/learning.md "Which learner a run uses"), and the default run itself.
  expect_output("learn --robot hexapod --disable R1,R3,L2 --learner annealing --seed 1 --json",
                "learn-robust-R1+R3+L2.json");
  expect_output("learn --robot hexapod --disable R1,R3,L2 --seed 1 --json",
                "learn-robust-prior-R1+R3+L2.json");
  expect_output("learn --mode paper --disable R1 --seed 1 --json", "learn-paper-R1.json");
  expect_output("tunnel --disable R1,R3 --json", "tunnel-R1+R3.json");
  expect_output("walk --disable R1 --steps 800 --json", "walk-R1.json");
}

TEST(Golden, AnExperimentFileGivesTheSameTablesAndRuns) {
  const std::string dir = make_temp_dir("golden-quick-");
  const CliResult r = run_cli("run " + std::string(MULTICPG_SOURCE_DIR) +
                              "/examples/quick.toml --jobs 2 --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir + "/table.csv"), golden("quick-table.csv"));
  EXPECT_EQ(read_file(dir + "/runs.csv"), golden("quick-runs.csv"));
  const auto run = nlohmann::json::parse(read_file(dir + "/runs/beta10_R1+R3_run001.json"));
  EXPECT_EQ(run.at("result"), nlohmann::json::parse(golden("quick-run-result.json")));
  fs::remove_all(dir);
}

TEST(Golden, ALandscapeWalksTheSameCombinations) {
  const std::string dir = make_temp_dir("golden-land-");
  const CliResult r = run_cli(
      "landscape --robot quadruped --disable L2 --periods-set 4,5 --windows 1 --jobs 2 "
      "--out " +
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir + "/landscape.csv"), golden("landscape-quadruped-L2.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace multicpg::testing
