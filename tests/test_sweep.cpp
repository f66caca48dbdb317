// Experiment files through the real CLI: `run FILE.toml` (validation, grids, shards),
// `rerun` and `merge`, and the paper presets against their example files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;

const std::string kExamples = std::string(MULTICPG_SOURCE_DIR) + "/examples/";

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A result file as compared between directories: experiment.json without its provenance (the
// command line that made it, common/provenance.h) and checksum; any other file whole.
std::string comparable(const std::string& path) {
  const std::string text = read_file(path);
  if (fs::path(path).filename() != "experiment.json" || text.empty()) return text;
  nlohmann::json record = nlohmann::json::parse(text);
  record.erase("provenance");
  record.erase("checksum");
  return record.dump(2);
}

// A small sweep: two betas on R1, few trials, one run each (two short runs).
const std::string kSmall = R"(robot = "hexapod"
scenarios = ["R1"]
runs = 1
seed = 3

[learning]
mode = "paper"
steering = "off"

[learning.annealing]
beta = [0.5, 10]
max_trials = 4
)";

TEST(Sweep, EachExampleFileValidates) {
  const std::vector<std::pair<std::string, std::string>> files{
      {"quick.toml", "8 runs (2 grid points x 2 scenarios x 2 runs)"},
      {"paper-table-hexapod.toml", "240 runs (1 grid point x 24 scenarios x 10 runs)"},
      {"paper-table-quadruped.toml", "40 runs (1 grid point x 4 scenarios x 10 runs)"},
      {"paper-beta.toml", "350 runs (7 grid points x 1 scenario x 50 runs)"},
      {"landscape-r1.toml", "a landscape of 3125 combinations"},
      {"landscape-quadruped-l2.toml", "a landscape of 125 combinations"}};
  for (const auto& [file, count] : files) {
    const CliResult r = run_cli("run " + kExamples + file + " --check");
    EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.err;
    EXPECT_NE(r.out.find(count), std::string::npos) << file << "\n" << r.out;
  }
  // Every other experiment file of examples/ too (robot and hardware files are not experiments).
  int checked = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kExamples)) {
    const std::filesystem::path& path = entry.path();
    const std::string folder = path.parent_path().filename().string();
    if (path.extension() != ".toml" || folder == "robots" || folder == "hardware") continue;
    const CliResult r = run_cli("run " + path.string() + " --check");
    EXPECT_EQ(r.exit_code, 0) << path << "\n" << r.err;
    ++checked;
  }
  EXPECT_GT(checked, static_cast<int>(files.size()));
}

TEST(Sweep, ListsFormAGridOfEveryCombination) {
  const std::string dir = make_temp_dir("sweep-grid-");
  const std::string file = dir + "/grid.toml";
  write(file, R"(scenarios = ["R1", "R2+L3"]
runs = 3
[learning.annealing]
beta = [0, 1, 2]
threshold_deg = [5, 10]
[sim]
control_dt = [0.037, 0.074]
)");
  const CliResult r = run_cli("run " + file + " --check");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("72 runs (12 grid points x 2 scenarios x 3 runs)"), std::string::npos)
      << r.out;
  const CliResult shard = run_cli("run " + file + " --check --shard 4/5 --runs 1");
  EXPECT_NE(shard.out.find("24 runs (12 grid points x 2 scenarios x 1 run), 4 in shard 4/5"),
            std::string::npos)
      << shard.out;
  // "all": every set of 1-3 legs up to mirror, as experiments::mirror_scenarios.
  write(file, "scenarios = \"all\"\nruns = 1\n");
  EXPECT_NE(run_cli("run " + file + " --check").out.find("24 runs"), std::string::npos);
  // A fault timeline is a scenario too (docs/experiments.md "Experiment files").
  write(file, R"(scenarios = ["R1", {name = "R1-then-L2", faults = [
  {step = 0, legs = ["R1"]}, {step = 8000, legs = ["L2"]}, {step = 16000, legs = "R1", recover = true}]}]
runs = 2
)");
  const CliResult timeline = run_cli("run " + file + " --check");
  EXPECT_EQ(timeline.exit_code, 0) << timeline.err;
  EXPECT_NE(timeline.out.find("4 runs (1 grid point x 2 scenarios x 2 runs)"), std::string::npos)
      << timeline.out;
  // Terrain is a grid axis like any simulation option, written as --terrain takes it
  // (docs/faults.md), and faults of any kind are scenarios.
  write(file, R"(scenarios = ["R2.CTr:locked", "L1:weak=0.3", "imu:noise=1"]
runs = 1
[sim.scene]
terrain = ["flat", "slope:5", "rough:0.01:3"]
)");
  const CliResult terrain = run_cli("run " + file + " --check");
  EXPECT_EQ(terrain.exit_code, 0) << terrain.err;
  EXPECT_NE(terrain.out.find("9 runs (3 grid points x 3 scenarios x 1 run)"), std::string::npos)
      << terrain.out;
  // A terrain axis names its runs' files ("slope:5" as "slope_5"); two short robust runs.
  write(file,
        "scenarios = [\"R1.CTr:locked\"]\nruns = 1\n[sim.scene]\n"
        "terrain = [\"flat\", \"slope:5\"]\n");
  const fs::path walked_dir = fs::path(dir) / "terrain";
  const CliResult walked = run_cli("run " + file + " --out " + walked_dir.string());
  ASSERT_EQ(walked.exit_code, 0) << walked.err;
  EXPECT_TRUE(fs::exists(walked_dir / "runs" / "terrainslope_5_run000.json"));
  EXPECT_NE(read_file((walked_dir / "runs.csv").string()).find(",slope:5,"), std::string::npos);
  write(file, "scenarios = [\"R1\"]\n[sim.scene]\nterrain = \"slope:45\"\n");
  const CliResult steep = run_cli("run " + file + " --check");
  EXPECT_EQ(steep.exit_code, 2);
  EXPECT_NE(steep.err.find("sim.scene.terrain"), std::string::npos) << steep.err;
  fs::remove_all(dir);
}

struct BadFile {
  std::string text;
  std::string mention;  // after "FILE:"
};

TEST(Sweep, BadFilesNameFileLineAndKey) {
  const std::string dir = make_temp_dir("sweep-bad-");
  const std::string file = dir + "/bad.toml";
  const std::string ok = "scenarios = [\"R1\"]\n";
  const std::vector<BadFile> cases{
      {"robot = 5\n" + ok, "1: robot must be a string"},
      {"robot = \"spider\"\n" + ok, "1: robot"},
      {ok + "colour = 1\n", "2: colour is not an experiment key"},
      {"runs = 1\n", " scenarios is missing"},
      {"scenarios = \"some\"\n", "1: scenarios must be"},
      {"scenarios = []\n", "1: scenarios is an empty list"},
      {"scenarios = [\"R7\"]\n", "1: scenarios[0]"},
      {"scenarios = [\"R1+R1\"]\n", "1: scenarios[0] leg R1 is named twice"},
      {"scenarios = [\"R1\",\n  \"R1\"]\n", "2: scenarios[1] repeats"},
      {"scenarios = [5]\n", "1: scenarios[0] must be a leg set"},
      {"robot = \"octopod\"\nscenarios = \"paper\"\n", "2: scenarios"},
      {ok + "runs = 0\n", "2: runs must be in 1.."},
      {ok + "runs = \"ten\"\n", "2: runs must be a whole number"},
      {ok + "runs = 2.5\n", "2: runs must be a whole number"},
      {ok + "seed = -1\n", "2: seed must be in 0..4294967295, got -1"},
      {ok + "kind = \"tunnel\"\n", "2: kind must be"},
      {ok + "[learning]\nbeta = 1\n", "3: learning.beta is not an option"},
      {ok + "[learning.annealing]\nbeta = -1\n", "3: learning.annealing.beta"},
      {ok + "[learning.annealing]\nbeta = \"high\"\n",
       "3: learning.annealing.beta must be a number"},
      {ok + "[learning.annealing]\nmax_trials = 2.5\n",
       "3: learning.annealing.max_trials must be a whole number"},
      {ok + "[learning.annealing]\nperiod_set = [4, 10]\n", "3: learning.annealing.period_set"},
      {ok + "[learning.annealing]\nbeta = []\n", "3: learning.annealing.beta is an empty list"},
      {ok + "[learning.annealing]\nbeta = [1, \"x\"]\n", "3: learning.annealing.beta[1] must be"},
      {ok + "[learning]\nmode = \"fast\"\n", "3: learning.mode"},
      {ok + "[learning]\nwindow_steps = 0\n", "3: learning.window_steps"},
      {ok + "[learning]\ndisabled = [0]\n", "3: learning.disabled is set by each run"},
      {ok + "[learning]\nseed = 3\n", "3: learning.seed is set by each run"},
      {ok + "[learning]\nlearn_periods = \"yes\"\n", "3: learning.learn_periods must be true"},
      {ok + "[learning]\nsteering_params = 3\n", "3: learning.steering_params must be a table"},
      {ok + "[learning.steering_params]\nmax_effort = 2\n",
       "3: learning.steering_params.max_effort"},
      {ok + "[sim]\ngravity = 9.8\n", "3: sim.gravity is not an option"},
      {ok + "[sim]\ncontrol_dt = \"fast\"\n", "3: sim.control_dt must be a number"},
      {ok + "[sim]\ncontrol_dt = -1\n", "3: sim.control_dt"},
      {ok + "[sim.scene]\ntunnel = 1\n", "3: sim.scene.tunnel must be true or false"},
      // The body (robot/body_params.h) and its models.
      {ok + "[sim.body]\ntotal_mass = 20\n", "3: sim.body.total_mass must be in 4.5..9"},
      {ok + "[sim.body]\nslip = 0\n", "3: sim.body.slip must be in"},
      {ok + "[sim.body]\nmass = 5\n", "3: sim.body.mass is not an option"},
      {ok + "[sim.body]\nservo_torque = \"max\"\n", "3: sim.body.servo_torque must be a number"},
      {ok + "[sim.body]\ntotal_mass = 5\ntrunk_mass = 4\n", "4: sim.body.trunk_mass must leave"},
      {ok + "[sim.body.disabled_posture]\nctr = 2\n", "3: sim.body.disabled_posture.ctr"},
      {ok + "[[sim.body.leg_postures]]\nleg = \"R9\"\nfti = -0.5\n",
       "3: sim.body.leg_postures[0].leg"},
      {ok + "[[sim.body.leg_postures]]\nleg = \"R3\"\nfti = -1.5\n",
       "4: sim.body.leg_postures[0].fti"},
      {ok + "[sim]\nmodel = \"nosuch\"\n", "3: sim.model no body model 'nosuch'"},
      {ok + "[sim]\nmodel = 1\n", "3: sim.model must be a model name"},
      {ok + "[sim]\nmodel = [\"real\", \"paper-sim\"]\n", "3: sim.model takes one model"},
      {ok + "[record]\ncheck_windows = -1\n", "3: record.check_windows must be in 0..1000"},
      {ok + "[record]\nfilm = true\n", "3: record.film is not a record key"},
      {ok + "[record]\ntrace = 1\n", "3: record.trace must be true or false"},
      {ok + "runs = 1\nruns = 2\n", "3:"},
      {ok + "[learning]\nmode = \"paper\"\n[learning]\nhold_windows = 2\n", "4:"},
      {ok + "runs = \n", "2:"},
      {ok + "seed = 1979-05-27\n", "2: seed must be a number"},
      {"scenarios = [{faults = [{step = 0, legs = [\"R1\"]}]}]\n", "1: scenarios[0].name"},
      {"scenarios = [{name = \"x\", when = 3, faults = [{legs = [\"R1\"]}]}]\n",
       "1: scenarios[0].when is not a scenario key"},
      {"scenarios = [{name = \"x\", faults = [{step = 0, legs = []}]}]\n",
       "1: scenarios[0].faults[0].legs must name legs"},
      {"scenarios = [{name = \"a b\", faults = [{legs = \"R1\"}]}]\n", "1: scenarios[0].name"},
      {"scenarios = [{name = \"x\", faults = [\n {legs = \"R1\"},\n {step = 100, legs = "
       "\"L2\"}]}]\n"
       "[learning]\nmode = \"paper\"\n",
       "5: learning.mode paper mode takes one fault"},
  };
  for (const BadFile& c : cases) {
    write(file, c.text);
    SCOPED_TRACE(c.text);
    expect_bad_input("run " + file + " --check", file + ":" + c.mention);
  }
  EXPECT_GE(cases.size(), 30u);
  expect_bad_input("run " + dir + "/missing.toml --check", dir + "/missing.toml: cannot read");
  expect_bad_input("run " + dir + " --check", dir + ": is a directory");
  write(file, "\xff\xfe = 1\n");
  expect_bad_input("run " + file + " --check", file + ":1:");
  write(file, ok);
  for (const char* shard : {"2/2", "1/0", "a/b", "1", "-1/2"}) {
    expect_bad_input("run " + file + " --check --shard " + shard, "--shard must be i/N");
  }
  expect_bad_input("run " + file + " --check --runs 0", "--runs: must be in 1..100000, got 0");
  expect_bad_input("run " + file, "--out");
  fs::remove_all(dir);
}

TEST(Sweep, ShardsMergeToTheWholeAndAnyRunReruns) {
  const std::string dir = make_temp_dir("sweep-shard-");
  const std::string file = dir + "/small.toml";
  write(file, kSmall);
  ASSERT_EQ(run_cli("run " + file + " --jobs 2 --out " + dir + "/whole").exit_code, 0);
  for (const char* shard : {"0/2", "1/2"}) {
    const CliResult r = run_cli("run " + file + " --jobs 1 --shard " + shard + " --out " + dir +
                                "/shard" + std::string(shard).substr(0, 1));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/shard" + std::string(shard).substr(0, 1) + "/table.csv"));
  }
  const CliResult merged =
      run_cli("merge " + dir + "/merged " + dir + "/shard0 " + dir + "/shard1");
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  for (const char* name : {"experiment.json", "table.csv", "table.md", "summary.json", "runs.csv",
                           "trials.csv", "runs/beta0.5_run000.json", "runs/beta10_run000.json"}) {
    const std::string whole = comparable(dir + "/whole/" + name);
    EXPECT_FALSE(whole.empty()) << name;
    EXPECT_EQ(comparable(dir + "/merged/" + name), whole) << name;
  }
  // runs.csv: one row per run, a column per swept option.
  const std::string runs = read_file(dir + "/whole/runs.csv");
  EXPECT_EQ(count_lines(runs), 3);
  EXPECT_EQ(first_line(runs).rfind("key,scenario,run,seed,learning.annealing.beta,converged", 0),
            0u);
  EXPECT_EQ(first_line(read_file(dir + "/whole/trials.csv"))
                .rfind("key,scenario,run,seed,learning.annealing.beta,trial,period_R1", 0),
            0u);

  // A shard missing, or a shard of another experiment, is refused.
  expect_bad_input("merge " + dir + "/m2 " + dir + "/shard0", "is in none of the directories");
  expect_bad_input("merge " + dir + "/m3 " + dir + "/shard0 " + dir + "/shard0", "repeats");

  // Any run again: the identical run file.
  const CliResult again = run_cli("rerun " + dir + "/whole beta10_run000 --out " + dir + "/again");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("identical"), std::string::npos) << again.out;
  EXPECT_EQ(read_file(dir + "/again/runs/beta10_run000.json"),
            read_file(dir + "/whole/runs/beta10_run000.json"));
  expect_bad_input("rerun " + dir + "/whole nosuch_run000", "has no run nosuch_run000");
  expect_bad_input("rerun " + dir + "/whole beta10_run000 --film run.png", "--film");
  expect_bad_input("rerun " + dir + "/whole beta10_run000 --film run.gif", "run.gif");

  // Resuming with a changed file is refused, naming the key.
  std::string changed = kSmall;
  changed.replace(changed.find("max_trials = 4"), 14, "max_trials = 5");
  write(file, changed);
  expect_bad_input("run " + file + " --out " + dir + "/whole", "learning.annealing.max_trials");
  fs::remove_all(dir);
}

// The example file with fewer trials: `replace` inserted before the line starting `before`.
std::string example_with(const std::string& example, const std::string& before,
                         const std::string& insert) {
  std::string text = read_file(kExamples + example);
  text.insert(text.find(before), insert);
  return text;
}

TEST(Sweep, PaperPresetsEqualTheirExampleFiles) {
  const std::string dir = make_temp_dir("sweep-preset-");
  struct Case {
    std::string preset;
    std::string example;
    std::string before;
    std::string insert;
  };
  const std::vector<Case> cases{
      {"experiment table --robot quadruped", "paper-table-quadruped.toml", "steering",
       "annealing.max_trials = 2\n"},
      {"experiment beta", "paper-beta.toml", "beta = [", "max_trials = 2\n"}};
  for (const Case& c : cases) {
    const std::string file = dir + "/" + c.example;
    write(file, example_with(c.example, c.before, c.insert));
    const CliResult a = run_cli(c.preset + " --runs 1 --max-trials 2 --jobs 2 --out " + dir + "/a");
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const CliResult b = run_cli("run " + file + " --runs 1 --jobs 2 --out " + dir + "/b");
    ASSERT_EQ(b.exit_code, 0) << b.err;
    for (const char* name : {"experiment.json", "table.csv", "table.md", "summary.json"}) {
      EXPECT_EQ(comparable(dir + "/a/" + name), comparable(dir + "/b/" + name))
          << c.example << " " << name;
    }
    fs::remove_all(dir + "/a");
    fs::remove_all(dir + "/b");
  }
  fs::remove_all(dir);
}

// A body model supplies the body, [sim.body] keys override it, a body key can be a grid axis;
// the record holds the model and every resolved value, and a resume with another is refused.
TEST(Sweep, BodyModelAndKeysAreRecordedAndAResumeWithAnotherIsRefused) {
  const std::string dir = make_temp_dir("sweep-body-");
  const std::string file = dir + "/body.toml";
  const std::string text = R"(scenarios = ["R1"]
runs = 1
[learning]
mode = "paper"
[learning.annealing]
max_trials = 1
[sim]
model = "real"
[sim.body]
foot_friction = 1.5
trunk_friction = [1.0, 2.0]
[[sim.body.leg_postures]]
leg = "R3"
fti = -0.55
)";
  write(file, text);
  const CliResult r = run_cli("run " + file + " --jobs 2 --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 runs (2 grid points"), std::string::npos) << r.out;
  const nlohmann::json sim =
      nlohmann::json::parse(read_file(dir + "/out/experiment.json"))["arguments"]["sim"];
  EXPECT_EQ(sim["model"], "real");
  const nlohmann::json& body = sim["body"];
  EXPECT_EQ(body["total_mass"], 5.758);  // the model's
  EXPECT_EQ(body["trunk_mass"], 2.2);
  EXPECT_EQ(body["lift_body"], 5.0);
  EXPECT_EQ(body["foot_friction"], 1.5);  // the file's
  EXPECT_EQ(body["trunk_friction"], nlohmann::json::array({1.0, 2.0}));
  EXPECT_EQ(body["leg_postures"], nlohmann::json::parse(R"([{"leg": "R3", "fti": -0.55}])"));
  // the real model's calibrated dead-leg command (robot/body_models.cpp)
  EXPECT_EQ(body["disabled_posture"]["ctr"], 0.8942978086273929);
  EXPECT_EQ(first_line(read_file(dir + "/out/runs.csv"))
                .rfind("key,scenario,run,seed,sim.body.trunk_friction,", 0),
            0u);
  // The same file again resumes; another body value is refused, naming its key.
  ASSERT_EQ(run_cli("run " + file + " --jobs 2 --out " + dir + "/out").exit_code, 0);
  std::string changed = text;
  changed.replace(changed.find("foot_friction = 1.5"), 19, "foot_friction = 1.6");
  write(file, changed);
  expect_bad_input("run " + file + " --out " + dir + "/out", "sim.body.foot_friction");
  changed = text;
  changed.replace(changed.find("model = \"real\""), 14, "model = \"paper-sim\"");
  write(file, changed);
  expect_bad_input("run " + file + " --out " + dir + "/out", "sim.body.total_mass");
  fs::remove_all(dir);
}

TEST(Sweep, RunsRecordedWithoutTheirTraceStillMakeTheTables) {
  const std::string dir = make_temp_dir("sweep-notrace-");
  const std::string file = dir + "/notrace.toml";
  write(file, R"(scenarios = ["R1"]
runs = 1
[learning]
mode = "paper"
[learning.annealing]
max_trials = 1
[record]
trace = false
)");
  const CliResult r = run_cli("run " + file + " --jobs 1 --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json run = nlohmann::json::parse(read_file(dir + "/out/runs/R1_run000.json"));
  EXPECT_FALSE(run["result"].contains("trace"));
  EXPECT_TRUE(run["result"].contains("trials"));
  EXPECT_NE(read_file(dir + "/out/table.md").find("R1"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Sweep, LandscapePresetEqualsItsFile) {
  const std::string dir = make_temp_dir("sweep-landscape-");
  write(dir + "/l2.toml", R"(kind = "landscape"
robot = "quadruped"
scenarios = ["L2"]
[landscape]
period_set = [4, 5]
windows = 1
)");
  ASSERT_EQ(run_cli("run " + kExamples + "landscape-quadruped-l2.toml --check").exit_code, 0);
  const CliResult a = run_cli(
      "landscape --robot quadruped --disable L2 --periods-set 4,5 "
      "--windows 1 --jobs 2 --out " +
      dir + "/a");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const CliResult b = run_cli("run " + dir + "/l2.toml --jobs 2 --out " + dir + "/b");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(first_line(a.out), first_line(b.out));
  for (const char* name : {"experiment.json", "landscape.csv", "summary.json"}) {
    EXPECT_FALSE(comparable(dir + "/a/" + name).empty()) << name;
    EXPECT_EQ(comparable(dir + "/a/" + name), comparable(dir + "/b/" + name)) << name;
  }
  // A landscape is resumed by running it again, never rerun or merged like a sweep's runs.
  expect_bad_input("rerun " + dir + "/b R1-4_R2-4_L1-4", "holds a landscape, which is not rerun");
  expect_bad_input("merge " + dir + "/m " + dir + "/a", "holds a landscape, which is not rerun");
  // Several scenarios make a landscape set (a dataset); a scenario of no leg is none.
  write(dir + "/set.toml", "kind = \"landscape\"\nscenarios = [\"R1\", \"R2\"]\n");
  EXPECT_EQ(run_cli("run " + dir + "/set.toml --check").exit_code, 0);
  write(dir + "/bad.toml", "kind = \"landscape\"\nscenarios = [\"R1\", \"X9\"]\n");
  expect_bad_input("run " + dir + "/bad.toml --check", dir + "/bad.toml:2: scenarios");
  write(dir + "/bad.toml",
        "kind = \"landscape\"\nscenarios = [\"R1\"]\n[landscape]\nwindows = [1, 2]\n");
  expect_bad_input("run " + dir + "/bad.toml --check", dir + "/bad.toml:4: landscape.windows");
  write(dir + "/bad.toml", "kind = \"landscape\"\nscenarios = [\"R1\"]\nruns = 3\n");
  expect_bad_input("run " + dir + "/bad.toml --check",
                   dir + "/bad.toml:3: runs is not a landscape key");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace multicpg::testing
