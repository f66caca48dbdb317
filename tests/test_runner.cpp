// Experiment machinery without physics: scenario lists (docs/learning.md "The paper's
// experiments"), the parallel, resumable runner and the tables. The task function is a stand-in
// driven only by the task's seed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>

#include "common/errors.h"
#include "common/random.h"
#include "experiments/learning_experiments.h"
#include "experiments/runner.h"
#include "experiments/scenarios.h"
#include "experiments/sweep.h"
#include "experiments/tables.h"
#include "learning/annealing.h"
#include "learning/compensation.h"
#include "robot/leg_sets.h"
#include "tests/fake_body.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using robot::RobotKind;

const robot::Morphology& hexapod() {
  return robot::morphology(RobotKind::hexapod);
}

// The record (learning::to_json) of a learning result drawn from the task's seed only.
nlohmann::json fake_result(const Task& task) {
  std::mt19937_64 rng(task.seed);
  learning::LearningResult r;
  r.trials = 1 + static_cast<int>(draw_below(rng, 30));
  r.outcome =
      draw_unit(rng) < 0.8 ? learning::Outcome::converged : learning::Outcome::not_converged;
  for (std::size_t leg = 0; leg < hexapod().size(); ++leg) {
    r.periods.push_back(4 + static_cast<int>(draw_below(rng, 2)));
  }
  r.final_deviation_deg = 20.0 * draw_unit(rng);
  r.initial_deviation_deg = 40.0;
  return learning::to_json(r, hexapod(),
                           robot::leg_set_from_json(hexapod(), task.params.at("disabled")));
}

// A fresh directory under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(fs::temp_directory_path() / ("multicpg_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

RunnerOptions options(const fs::path& out, int jobs) {
  RunnerOptions o;
  o.out_dir = out;
  o.jobs = jobs;
  o.arguments = {{"robot", "hexapod"}, {"runs", 3}, {"seed", 1}};
  o.progress = false;
  return o;
}

std::vector<Task> small_experiment() {
  const std::vector<Scenario> all = paper_scenarios(RobotKind::hexapod);
  nlohmann::json names = nlohmann::json::array();
  for (std::size_t i = 0; i < 5; ++i) names.push_back(all[i].name);
  return tasks_of(resolve_sweep({{"scenarios", names}, {"runs", 3}, {"seed", 1}}));
}

std::string table_of(const std::vector<Task>& tasks, const RunnerOutcome& outcome) {
  const std::vector<GroupSummary> rows = summarize(hexapod(), tasks, outcome.results);
  return to_csv(scenario_data(rows)) + to_markdown(scenario_table(rows));
}

TEST(Scenarios, HexapodHas24UpToMirror) {
  const std::vector<Scenario> s = paper_scenarios(RobotKind::hexapod);
  ASSERT_EQ(s.size(), 24u);
  std::map<std::size_t, int> by_size;
  std::set<std::string> names;
  for (const Scenario& x : s) {
    ++by_size[x.disabled.size()];
    names.insert(x.name);
  }
  EXPECT_EQ(by_size[1], 6);
  EXPECT_EQ(by_size[2], 9);
  EXPECT_EQ(by_size[3], 9);
  for (const char* n : {"R1", "L1", "L3", "R1+R3", "R1+L2", "R1+R2", "R1+L1", "R1+R3+L2"}) {
    EXPECT_TRUE(names.contains(n)) << n;
  }
  // Mirror images and whole sides are left out.
  for (const char* n : {"L1+L3", "R2+L1", "L1+L3+R2", "R1+R2+R3", "L1+L2+L3"}) {
    EXPECT_FALSE(names.contains(n)) << n;
  }
  EXPECT_EQ(s.front().name, "R1");
  EXPECT_EQ(s.back().disabled.size(), 3u);
}

// A document without a learner gives each run the default a CLI run of its options gets
// (docs/learning.md "Which learner a run uses"): the prior for robust mode's leg losses, the
// annealing for a joint fault, in paper mode and where the document gives the annealing's beta
// (kept as given); every run records it.
TEST(Scenarios, ADocumentWithoutALearnerGivesEachRunItsDefault) {
  const auto learners = [](const nlohmann::json& doc) {
    std::vector<std::string> out;
    for (const Task& t : tasks_of(resolve_sweep(doc))) {
      out.push_back(t.params.at("learning")
                        .value("learner", nlohmann::json{{"name", "annealing"}})
                        .at("name")
                        .get<std::string>());
    }
    return out;
  };
  const nlohmann::json scenarios = {"R1+R3", "R2.CTr:locked"};
  EXPECT_EQ(learners({{"scenarios", scenarios}, {"runs", 1}}),
            (std::vector<std::string>{"prior", "annealing"}));
  EXPECT_EQ(learners({{"scenarios", scenarios}, {"runs", 1}, {"learning", {{"mode", "paper"}}}}),
            (std::vector<std::string>{"annealing", "annealing"}));
  const nlohmann::json beta = {
      {"scenarios", {"R1+R3"}}, {"runs", 1}, {"learning", {{"annealing", {{"beta", 2}}}}}};
  EXPECT_EQ(learners(beta), (std::vector<std::string>{"annealing"}));
  EXPECT_EQ(tasks_of(resolve_sweep(beta)).front().params.at("learning").at("annealing").at("beta"),
            2);
  EXPECT_EQ(learners({{"scenarios", {"R1+R3"}},
                      {"runs", 1},
                      {"learning", {{"learner", {{"name", "bayes"}}}}}}),
            (std::vector<std::string>{"bayes"}));
  // tell_fault may be a grid axis; told nothing of the fault a run's default is the annealing,
  // and its record says so (told, the record leaves the key out, as runs were recorded before).
  const nlohmann::json told = {
      {"scenarios", {"R1+R3"}}, {"runs", 1}, {"learning", {{"tell_fault", {true, false}}}}};
  EXPECT_EQ(learners(told), (std::vector<std::string>{"prior", "annealing"}));
  const std::vector<Task> tasks = tasks_of(resolve_sweep(told));
  EXPECT_FALSE(tasks.front().params.at("learning").contains("tell_fault"));
  EXPECT_EQ(tasks.back().params.at("learning").at("tell_fault"), false);
  EXPECT_THROW(resolve_sweep({{"scenarios", {"R1"}}, {"learning", {{"tell_fault", "no"}}}}),
               OptionError);
}

TEST(Scenarios, QuadrupedAndBetaStudy) {
  std::vector<std::string> names;
  for (const Scenario& s : paper_scenarios(RobotKind::quadruped)) names.push_back(s.name);
  EXPECT_EQ(names, (std::vector<std::string>{"R1", "R2", "L1", "L2"}));
  EXPECT_THROW(paper_scenarios(RobotKind::octopod), BadInput);
  EXPECT_EQ(beta_study_scenario().name, "R1+R2");

  // The beta study's runs: keys "beta<b>_run<NNN>" (seeds come from them), one group per beta.
  ExperimentSpec spec;
  spec.runs = kBetaRuns;
  const std::vector<Task> tasks =
      tasks_of(resolve_sweep(beta_study_document(spec, kBetaStudyValues)));
  EXPECT_EQ(tasks.size(), kBetaStudyValues.size() * kBetaRuns);
  EXPECT_EQ(tasks.front().key, "beta0_run000");
  EXPECT_EQ(tasks[kBetaRuns].group, "0.1");
  EXPECT_EQ(tasks[kBetaRuns].params.at("learning").at("annealing").at("beta"), 0.1);
  EXPECT_EQ(tasks.back().key, "beta10_run049");
  EXPECT_THROW(resolve_sweep(beta_study_document(spec, {-1.0})), OptionError);
  spec.runs = 0;
  EXPECT_THROW(resolve_sweep(scenario_table_document(spec)), OptionError);
}

TEST(Runner, SeedsComeFromKeysOnly) {
  const std::vector<Task> tasks = small_experiment();
  EXPECT_EQ(tasks.front().key, "R1_run000");
  EXPECT_EQ(tasks.front().seed, derive_seed(1, "R1_run000"));
  EXPECT_NE(derive_seed(1, "R1_run000"), derive_seed(2, "R1_run000"));
  EXPECT_NE(derive_seed(1, "R1_run000"), derive_seed(1, "R1_run001"));
  // Pinned (checked independently with Python): changing the derivation would silently change
  // every experiment's runs.
  EXPECT_EQ(derive_seed(1, "R1_run000"), 0x82eba1d17a2ecc9eULL);
  std::set<std::uint64_t> seeds;
  for (const Task& t : tasks) seeds.insert(t.seed);
  EXPECT_EQ(seeds.size(), tasks.size());
}

TEST(Runner, OneAndTwoJobsGiveTheSameTable) {
  const std::vector<Task> tasks = small_experiment();
  TempDir one("jobs1");
  TempDir two("jobs2");
  const RunnerOutcome a = run_tasks(tasks, fake_result, options(one.path(), 1));
  RunnerOptions o2 = options(two.path(), 2);
  o2.progress = true;  // exercises the progress lines (stderr, not checked)
  const RunnerOutcome b = run_tasks(tasks, fake_result, o2);
  EXPECT_EQ(a.ran, static_cast<int>(tasks.size()));
  EXPECT_EQ(a.results, b.results);
  EXPECT_EQ(table_of(tasks, a), table_of(tasks, b));
  EXPECT_TRUE(fs::exists(one.path() / "experiment.json"));
  for (const Task& t : tasks) EXPECT_TRUE(fs::exists(one.path() / "runs" / (t.key + ".json")));
}

TEST(Runner, InterruptedRunResumesWithoutRepeatingFinishedRuns) {
  const std::vector<Task> tasks = small_experiment();
  TempDir whole("whole");
  const std::string expected =
      table_of(tasks, run_tasks(tasks, fake_result, options(whole.path(), 1)));

  for (int jobs : {1, 2}) {
    TempDir dir("resume" + std::to_string(jobs));
    constexpr int kFinishedBeforeKill = 4;
    std::atomic<int> calls{0};
    std::atomic<int> completed{0};
    auto dies = [&](const Task& t) {
      if (calls++ >= kFinishedBeforeKill) throw std::runtime_error("killed");
      ++completed;
      return fake_result(t);
    };
    EXPECT_THROW(run_tasks(tasks, dies, options(dir.path(), jobs)), std::runtime_error);
    const int saved = completed.load();
    EXPECT_GE(saved, kFinishedBeforeKill);

    std::atomic<int> reruns{0};
    auto counts = [&](const Task& t) {
      ++reruns;
      return fake_result(t);
    };
    const RunnerOutcome resumed = run_tasks(tasks, counts, options(dir.path(), jobs));
    EXPECT_EQ(resumed.loaded, saved);
    EXPECT_EQ(resumed.ran, static_cast<int>(tasks.size()) - saved);
    EXPECT_EQ(reruns.load() + saved, static_cast<int>(tasks.size()));
    EXPECT_EQ(table_of(tasks, resumed), expected);

    // A third start has nothing left to do.
    const RunnerOutcome again = run_tasks(tasks, counts, options(dir.path(), jobs));
    EXPECT_EQ(again.ran, 0);
    EXPECT_EQ(table_of(tasks, again), expected);
  }
}

TEST(Runner, RefusesToResumeWithDifferentArguments) {
  const std::vector<Task> tasks = small_experiment();
  TempDir dir("refuse");
  run_tasks(tasks, fake_result, options(dir.path(), 1));
  RunnerOptions other = options(dir.path(), 1);
  other.arguments["seed"] = 2;
  try {
    run_tasks(tasks, fake_result, other);
    ADD_FAILURE() << "resumed with another seed";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("other arguments.seed;"), std::string::npos) << e.what();
  }
  const std::vector<Task> fewer(tasks.begin(), tasks.end() - 1);
  EXPECT_THROW(run_tasks(fewer, fake_result, options(dir.path(), 1)), BadInput);
  // The thread count is not an argument of the results.
  EXPECT_NO_THROW(run_tasks(tasks, fake_result, options(dir.path(), 2)));
}

TEST(Runner, RejectsBadInput) {
  TempDir dir("bad");
  EXPECT_THROW(run_tasks(small_experiment(), fake_result, options(dir.path(), 0)), BadInput);
  std::vector<Task> twice = small_experiment();
  twice.push_back(twice.front());
  EXPECT_THROW(run_tasks(twice, fake_result, options(dir.path(), 1)), BadInput);
  std::vector<Task> slash = small_experiment();
  slash.front().key = "a/b";
  EXPECT_THROW(run_tasks(slash, fake_result, options(dir.path(), 1)), BadInput);
}

// The pieces together: compensation on the fake walker as the task, through runner and tables.
TEST(Runner, CompensationRunsThroughRunnerIntoTables) {
  const robot::Morphology& quad = robot::morphology(RobotKind::quadruped);
  const std::vector<Task> tasks = tasks_of(
      resolve_sweep({{"robot", "quadruped"}, {"scenarios", "paper"}, {"runs", 2}, {"seed", 5}}));
  auto learn = [&](const Task& t) {
    learning::CompensationOptions o;
    o.mode = learning::Mode::paper;
    std::vector<std::size_t> disabled;
    for (const nlohmann::json& leg : t.params.at("disabled")) {
      disabled.push_back(robot::leg_index(quad, leg.get<std::string>()));
    }
    o.seed = t.seed;
    o.settle_steps = 0;
    learning::FakeBody walker(RobotKind::quadruped, body::fail_at(disabled, 0));
    return learning::to_json(learning::compensate(walker, o, {}), quad, disabled);
  };
  TempDir one("learn1");
  TempDir two("learn2");
  const std::vector<GroupSummary> rows =
      summarize(quad, tasks, run_tasks(tasks, learn, options(one.path(), 1)).results);
  const std::vector<GroupSummary> again =
      summarize(quad, tasks, run_tasks(tasks, learn, options(two.path(), 2)).results);
  EXPECT_EQ(to_csv(scenario_data(rows)), to_csv(scenario_data(again)));
  ASSERT_EQ(rows.size(), 4u);
  for (const GroupSummary& r : rows) {
    EXPECT_EQ(r.runs, 2);
    EXPECT_EQ(r.converged, 2) << r.group;
    EXPECT_LT(r.final_deviation_deg.mean, learning::kDefaultThresholdDeg);
    EXPECT_FALSE(r.best_periods.empty());
  }
}

// Every leaf of `j` as a JSON pointer ("/learning/annealing/beta").
void leaf_pointers(const nlohmann::json& j, const std::string& at, std::vector<std::string>& out) {
  if (j.is_object() && !j.empty()) {
    for (const auto& item : j.items()) leaf_pointers(item.value(), at + "/" + item.key(), out);
  } else {
    out.push_back(at);
  }
}

// Another value of the same kind as `v`.
nlohmann::json changed(const nlohmann::json& v) {
  if (v.is_boolean()) return !v.get<bool>();
  if (v.is_number_unsigned()) return v.get<std::uint64_t>() + 1;
  if (v.is_number_integer()) return v.get<long>() + 1;
  if (v.is_number_float()) return v.get<double>() + 1.0;
  if (v.is_string()) return v.get<std::string>() + "x";
  if (v.is_array()) {
    nlohmann::json more = v;
    more.push_back(1);
    return more;
  }
  return 1;  // null: an optional that was not set
}

// The record holds every option of an experiment (learning, simulation,
// controller parameters), and a resume with any one of them changed is refused naming its key.
TEST(Runner, RefusesToResumeWhenAnyRecordedOptionDiffers) {
  ExperimentSpec spec;
  spec.runs = 3;
  const nlohmann::json recorded = experiment_arguments(spec, ExperimentKind::table);
  for (const char* key :
       {"/learning/annealing/beta", "/learning/detection_windows", "/learning/annealing/period_set",
        "/sim/servo_gain", "/sim/controller/cpg/w11", "/sim/controller/delays/tau_l"}) {
    EXPECT_TRUE(recorded.contains(nlohmann::json::json_pointer(key))) << key;
  }
  std::vector<std::string> leaves;
  leaf_pointers(recorded, "", leaves);
  const std::vector<Task> tasks = small_experiment();
  TempDir dir("refuse_each");
  RunnerOptions first = options(dir.path(), 2);
  first.arguments = recorded;
  run_tasks(tasks, fake_result, first);
  for (const std::string& leaf : leaves) {
    RunnerOptions other = first;
    const nlohmann::json::json_pointer ptr(leaf);
    other.arguments[ptr] = changed(recorded[ptr]);
    std::string dotted = "arguments" + leaf;
    std::replace(dotted.begin(), dotted.end(), '/', '.');
    try {
      run_tasks(tasks, fake_result, other);
      ADD_FAILURE() << "resumed with another " << leaf;
    } catch (const BadInput& e) {
      EXPECT_NE(std::string(e.what()).find("other " + dotted + ";"), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(leaves.size(), 60u);  // the controller's parameters alone are 37
  EXPECT_NO_THROW(run_tasks(tasks, fake_result, first));
}

TEST(Tables, SummariesAndFormatting) {
  std::vector<Task> tasks;
  std::vector<nlohmann::json> results;
  auto add = [&](const std::string& group, bool converged, int trials, double deviation, int r2) {
    tasks.push_back({group + std::to_string(tasks.size()), group, 0, 0, {}});
    learning::LearningResult r;
    r.outcome = converged ? learning::Outcome::converged : learning::Outcome::no_deviation;
    r.trials = trials;
    r.initial_deviation_deg = 10.0 * trials;
    r.final_deviation_deg = deviation;
    r.periods = {4, r2, 4, 4, 4, 4};
    results.push_back(learning::to_json(r, hexapod(), {0}));
  };
  add("R1", true, 10, 2.0, 6);
  add("R1", true, 20, 4.0, 5);
  add("R1", false, 0, 6.0, 4);
  add("L1", true, 5, 1.0, 9);
  const std::vector<GroupSummary> rows = summarize(hexapod(), tasks, results);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].group, "R1");
  EXPECT_EQ(rows[0].runs, 3);
  EXPECT_EQ(rows[0].converged, 2);
  EXPECT_EQ(rows[0].no_deviation, 1);
  EXPECT_DOUBLE_EQ(rows[0].final_deviation_deg.mean, 4.0);
  EXPECT_DOUBLE_EQ(rows[0].final_deviation_deg.sd, 2.0);
  EXPECT_DOUBLE_EQ(rows[0].trials.mean, 10.0);
  EXPECT_DOUBLE_EQ(rows[0].trials.sd, 10.0);
  EXPECT_DOUBLE_EQ(rows[0].median_trials, 10.0);
  EXPECT_DOUBLE_EQ(rows[0].initial_deviation_deg.mean, 100.0);
  EXPECT_EQ(rows[0].within_paper_trials, 2);  // 10 and 20 trials: within the paper's 20
  // The summary survives its JSON form (experiment results pages are made from it).
  const GroupSummary back = group_summary_from_json(to_json(rows[0]));
  EXPECT_EQ(back.best_periods, rows[0].best_periods);
  EXPECT_DOUBLE_EQ(back.trials.sd, rows[0].trials.sd);
  EXPECT_EQ(back.within_paper_trials, rows[0].within_paper_trials);
  // A tie (one run each): the alphabetically first combination.
  EXPECT_EQ(rows[0].best_periods, "R2=5 R3=4 L1=4 L2=4 L3=4");
  EXPECT_EQ(rows[0].best_count, 1);
  EXPECT_EQ(rows[1].best_periods, "R2=9 R3=4 L1=4 L2=4 L3=4");
  EXPECT_DOUBLE_EQ(rows[1].trials.sd, 0.0);

  EXPECT_EQ(to_csv(scenario_data(rows)),
            "scenario,runs,converged,no_deviation,share_converged,final_deviation_mean_deg,"
            "final_deviation_sd_deg,trials_mean,trials_sd,best_periods,best_count\n"
            "R1,3,2,1,0.67,4.00,2.00,10.0,10.0,R2=5 R3=4 L1=4 L2=4 L3=4,1\n"
            "L1,1,1,0,1.00,1.00,0.00,5.0,0.0,R2=9 R3=4 L1=4 L2=4 L3=4,1\n");
  EXPECT_EQ(to_csv(beta_data(rows)),
            "beta,runs,converged,share_converged,trials_mean,trials_sd,"
            "final_deviation_mean_deg,final_deviation_sd_deg\n"
            "R1,3,2,0.67,10.0,10.0,4.00,2.00\n"
            "L1,1,1,1.00,5.0,0.0,1.00,0.00\n");
  const std::string md = to_markdown(scenario_table(rows));
  EXPECT_NE(
      md.find("| R1 | 3 | 0.67 | 1 | 4.00 ± 2.00 | 10.0 ± 10.0 | R2=5 R3=4 L1=4 L2=4 L3=4 (1) |"),
      std::string::npos);
  EXPECT_NE(to_markdown(beta_table(rows)).find("| L1 | 1 | 1.00 | 5.0 ± 0.0 | 1.00 ± 0.00 |"),
            std::string::npos);
}

}  // namespace
}  // namespace multicpg::experiments
