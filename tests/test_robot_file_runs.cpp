// Robot files beyond one run, through the real CLI (docs/robots.md "Your robot: robot files"):
// experiment files (`robot = "R.toml"`, relative to the experiment file), `experiment table` and
// `landscape` take them and record them; a resumed experiment whose robot file changed is
// refused; `tunnel --scale-tunnel` records the tunnel it scaled.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_runner.h"

namespace {

using namespace multicpg::testing;
using nlohmann::json;

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

json read_json(const std::string& path) {
  return json::parse(read_file(path));
}

// Two learning runs of two trials on the quadruped (in experiment files, its robot line first).
const std::string kExperiment =
    "scenarios = [\"R1\", \"L2\"]\nruns = 1\n[learning]\nmode = \"paper\"\n"
    "annealing.max_trials = 2\n";

class RobotFileRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("robot-file-runs-");
    const CliResult r = run_cli("model --robot quadruped --out " + dir_ + "/robots");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    robot_ = dir_ + "/robots/quadruped.toml";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // `command` exits 0.
  static void ok(const std::string& command) {
    const CliResult r = run_cli(command);
    ASSERT_EQ(r.exit_code, 0) << command << ": " << r.err;
  }

  std::string dir_;
  std::string robot_;
};

TEST_F(RobotFileRuns, AnExperimentFileNamesItRelativeToItselfAndRecordsIt) {
  write(dir_ + "/builtin.toml", "robot = \"quadruped\"\n" + kExperiment);
  write(dir_ + "/file.toml", "robot = \"robots/quadruped.toml\"\n" + kExperiment);
  ok("run " + dir_ + "/builtin.toml --jobs 1 --out " + dir_ + "/builtin");
  ok("run " + dir_ + "/file.toml --jobs 1 --out " + dir_ + "/file");
  for (const char* name : {"runs.csv", "trials.csv", "table.csv", "table.md"}) {
    EXPECT_EQ(read_file(dir_ + "/builtin/" + name), read_file(dir_ + "/file/" + name)) << name;
  }
  const json summary = read_json(dir_ + "/file/summary.json");
  const json record = summary.at("robot_file");
  EXPECT_EQ(summary.at("robot"), "quadruped");
  EXPECT_EQ(record.at("path"), std::filesystem::absolute(robot_).lexically_normal().string());
  EXPECT_EQ(record.at("name"), "quadruped");
  EXPECT_EQ(summary.at("arguments").at("robot_file"), record);
  EXPECT_EQ(read_json(dir_ + "/builtin/summary.json").count("robot_file"), 0U);
  const json run = read_json(dir_ + "/file/runs/R1_run000.json");
  EXPECT_EQ(run.at("params").at("robot_file"), record);

  // Its run files rerun from the record, and a walk's record replays; a changed robot file is
  // refused, resumed, rerun or replayed, by the one reader of the record (run_robot.h).
  const CliResult rerun = run_cli("rerun " + dir_ + "/file R1_run000");
  EXPECT_EQ(rerun.exit_code, 0) << rerun.err;
  const CliResult walked = run_cli("walk --json --steps 40 --window 20 --robot " + robot_);
  ASSERT_EQ(walked.exit_code, 0) << walked.err;
  write(dir_ + "/walk.json", walked.out);
  const std::string replay = "replay " + dir_ + "/walk.json --out " + dir_ + "/walk.html";
  ok(replay);
  std::ofstream(robot_, std::ios::app) << "# edited\n";
  for (const std::string& command : {"run " + dir_ + "/file.toml --jobs 1 --out " + dir_ + "/file",
                                     "rerun " + dir_ + "/file R1_run000", replay}) {
    const CliResult r = run_cli(command);
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("robot_file.checksum_toml"), std::string::npos) << r.err;
  }
}

TEST_F(RobotFileRuns, ABadRobotFileInAnExperimentNamesBothFilesAndTheKey) {
  write(dir_ + "/missing.toml", "robot = \"robots/nosuch.toml\"\n" + kExperiment);
  expect_bad_input("run --check " + dir_ + "/missing.toml", "missing.toml:1: robot");
  expect_bad_input("run --check " + dir_ + "/missing.toml",
                   "nosuch.toml: cannot read (No such file");
  std::string toml = read_file(robot_);
  toml.replace(toml.find("trunk = \"trunk\""), 15, "trunk = \"torso\"");
  write(dir_ + "/robots/torso.toml", toml);
  write(dir_ + "/torso.toml", "robot = \"robots/torso.toml\"\n" + kExperiment);
  expect_bad_input("run --check " + dir_ + "/torso.toml", "torso.toml: trunk");
  const std::string torso = dir_ + "/robots/torso.toml";
  expect_bad_input("experiment table --runs 1 --out " + dir_ + "/t --robot " + torso,
                   "torso.toml: trunk");
  expect_bad_input("landscape --disable L2 --out " + dir_ + "/l --robot " + torso,
                   "torso.toml: trunk");
  expect_bad_input("tunnel --disable R1 --scale-tunnel --robot " + torso, "torso.toml: trunk");
  // Its body is its model: the experiment's [sim.body] may not change it.
  write(dir_ + "/heavy.toml",
        "robot = \"robots/quadruped.toml\"\n" + kExperiment + "[sim.body]\ntrunk_mass = 2.0\n");
  expect_bad_input("run --check " + dir_ + "/heavy.toml", "sim.body.trunk_mass");
}

TEST_F(RobotFileRuns, ExperimentTableRunsEveryOneAndTwoLegLossOfItsLayout) {
  ok("experiment table --robot " + robot_ + " --runs 1 --max-trials 1 --jobs 1 --out " + dir_ +
     "/table");
  const json summary = read_json(dir_ + "/table/summary.json");
  EXPECT_EQ(summary.at("robot"), "quadruped");
  EXPECT_EQ(summary.at("robot_file").at("name"), "quadruped");
  // R1, R2, L1, L2, then the pairs that leave each side a leg.
  const json expected = {"R1", "R2", "L1", "L2", "R1+L1", "R1+L2", "R2+L1", "R2+L2"};
  json scenarios = json::array();
  for (const json& s : summary.at("arguments").at("scenarios")) scenarios.push_back(s);
  EXPECT_EQ(scenarios, expected);
  EXPECT_EQ(summary.at("rows").size(), expected.size());
}

TEST_F(RobotFileRuns, LandscapeWalksItAsTheBuiltInRobot) {
  const std::string args = " --disable L2 --periods-set 4,5 --windows 1 --jobs 1 --out ";
  ok("landscape --robot quadruped" + args + dir_ + "/builtin");
  ok("landscape --robot " + robot_ + args + dir_ + "/file");
  EXPECT_EQ(read_file(dir_ + "/builtin/landscape.csv"), read_file(dir_ + "/file/landscape.csv"));
  json summary = read_json(dir_ + "/file/summary.json");
  EXPECT_EQ(summary.at("robot_file").at("name"), "quadruped");
  summary.erase("robot_file");
  EXPECT_EQ(summary, read_json(dir_ + "/builtin/summary.json"));
  // Resumed with a changed robot file: refused.
  std::ofstream(robot_, std::ios::app) << "# edited\n";
  expect_bad_input("landscape --robot " + robot_ + args + dir_ + "/file",
                   "robot_file.checksum_toml");
}

// A dataset of every loss walked by a robot file names it, as each of its landscapes does
// (docs/learning.md "The landscape dataset"). One period: each loss is one combination, the
// smallest such dataset, and each map is drawn for its one combination.
TEST_F(RobotFileRuns, ADatasetOfEveryLossNamesTheRobotFileThatWalkedIt) {
  ok("landscape --robot " + robot_ + " --every-loss --periods-set 4 --windows 1 --out " + dir_ +
     "/set");
  const json manifest = read_json(dir_ + "/set/landscapes.json");
  EXPECT_EQ(manifest.at("robot_file"), read_json(dir_ + "/set/R1/summary.json").at("robot_file"));
  EXPECT_EQ(manifest.at("robot_file").at("name"), "quadruped");
  EXPECT_EQ(manifest.at("scenarios").size(), 14U);
  EXPECT_GT(std::filesystem::file_size(dir_ + "/set/R1+R2/landscape-map.png"), 0U);
}

TEST_F(RobotFileRuns, TheTunnelScaledToTheRobotIsRecorded) {
  const std::string walk = "tunnel --disable R1 --max-steps 300 --json --robot " + robot_;
  const CliResult plain = run_cli(walk);
  const CliResult scaled = run_cli(walk + " --scale-tunnel");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(scaled.exit_code, 0) << scaled.err;
  json j = json::parse(scaled.out);
  EXPECT_EQ(json::parse(plain.out).count("tunnel"), 0U);
  // The built-in quadruped's own file is as wide as the quadruped: the paper's tunnel.
  const json& scale = j.at("tunnel").at("scale");
  EXPECT_EQ(scale.at("factor"), 1.0);
  EXPECT_GT(scale.at("robot_width_m").get<double>(), 0.1);
  EXPECT_EQ(scale.at("robot_width_m"), scale.at("layout_width_m"));
  EXPECT_EQ(j.at("tunnel").at("length_m"), 3.0);
  EXPECT_EQ(j.at("tunnel").at("width_m"), 1.2);
  j.erase("tunnel");
  EXPECT_EQ(plain.out, j.dump(2) + "\n");

  // Its legs set 8 cm further out on each side: its feet span 16 cm more, the tunnel grows.
  std::string xml = read_file(dir_ + "/robots/quadruped.xml");
  for (const std::string side : {" -0.08 0.0325\">", " 0.08 0.0325\">"}) {
    const std::string wider = side.substr(0, side.find("08")) + "16 0.0325\">";
    for (std::size_t at = xml.find(side); at != std::string::npos; at = xml.find(side, at)) {
      xml.replace(at, side.size(), wider);
    }
  }
  write(dir_ + "/robots/wide.xml", xml);
  std::string toml = read_file(robot_);
  toml.replace(toml.find("quadruped.xml"), 13, "wide.xml");
  write(dir_ + "/robots/wide.toml", toml);
  const CliResult wide =
      run_cli("tunnel --disable R1 --max-steps 300 --json --scale-tunnel --robot " + dir_ +
              "/robots/wide.toml");
  ASSERT_EQ(wide.exit_code, 0) << wide.err;
  const json tunnel = json::parse(wide.out).at("tunnel");
  const double robot = tunnel.at("scale").at("robot_width_m").get<double>();
  const double layout = tunnel.at("scale").at("layout_width_m").get<double>();
  EXPECT_NEAR(robot - layout, 0.16, 1e-9);
  EXPECT_EQ(tunnel.at("scale").at("factor").get<double>(), robot / layout);
  EXPECT_DOUBLE_EQ(tunnel.at("length_m").get<double>(), 3.0 * robot / layout);
  EXPECT_DOUBLE_EQ(tunnel.at("width_m").get<double>(), 1.2 * robot / layout);
}

}  // namespace
