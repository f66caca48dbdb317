// The real multicpg binary: learn and experiment commands.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "apps/learning_output.h"
#include "hw/hardware_record.h"
#include "learning/compensation.h"
#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

TEST(CliLearn, PrintsTheTraceAndTheFinalCombination) {
  const auto r = run_cli("learn --robot hexapod --disable R1,R3,L2 --seed 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("trial  R1  R2  R3  L1  L2  L3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4x"), std::string::npos) << "disabled legs are marked";
  EXPECT_NE(r.out.find("converged after"), std::string::npos) << r.out;
}

TEST(CliLearn, JsonHasTheDocumentedFields) {
  const auto r = run_cli("learn --disable R1,R3,L2 --seed 2 --json");
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
  EXPECT_TRUE(j.contains("learned_from")) << "robust mode's default learner is the prior";
  const auto annealing = run_cli("learn --disable R1,R3,L2 --seed 2 --learner annealing --json");
  ASSERT_EQ(annealing.exit_code, 0) << annealing.err;
  EXPECT_FALSE(nlohmann::json::parse(annealing.out).contains("learned_from"))
      << "the annealing learns from its trials alone";
  // Same seed, same run.
  EXPECT_EQ(run_cli("learn --disable R1,R3,L2 --seed 2 --json").out, r.out);
}

// The prior says which data it learned from, in the JSON and above the result line.
TEST(CliLearn, APriorRunSaysWhichDatasetItLearnedFrom) {
  const std::string run = "learn --disable R1,R3 --mode paper --learner prior";
  const auto r = run_cli(run + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto from = nlohmann::json::parse(r.out).at("learned_from");
  const fs::path dataset = from.at("dataset").get<std::string>();
  EXPECT_EQ(dataset.filename(), "hexapod");
  EXPECT_TRUE(fs::exists(dataset.string() + ".csv.gz")) << dataset;
  EXPECT_EQ(from.at("walked"), "periods alone");
  const auto text = run_cli(run);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(
      text.out.find("the prior learner learned from " + dataset.string() + " (periods alone)"),
      std::string::npos)
      << text.out;
}

// The header names the learner's options that are not its defaults (they are recorded whole).
TEST(CliLearn, TheHeaderNamesTheLearnersOptionsThatAreNotItsDefaults) {
  const auto header = [](const std::string& args) {
    const auto r = run_cli("learn --disable R1,R3 --max-trials 1 " + args);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3) << args << "\n" << r.err;
    return r.out.substr(0, r.out.find('\n'));
  };
  EXPECT_NE(header("--mode paper --learner prior").find(", learner prior, threshold"),
            std::string::npos);
  const std::string changed = header(
      "--mode paper --learner prior --learner-option scales=options --learner-option "
      "acquisition=ucb --learner-option kappa=3");
  // The given scales are used only with scales=options, which names them all.
  EXPECT_NE(changed.find(", learner prior (acquisition=ucb, effect_deg=4.0, intercept_deg=8.0, "
                         "kappa=3.0, noise_deg=3.0, pair_deg=1.5, scales=options), threshold"),
            std::string::npos)
      << changed;
  // The annealing's beta keeps its own place.
  const std::string annealing = header("--beta 2 --max-episodes 1");
  EXPECT_NE(annealing.find(", learner annealing, beta 2, threshold"), std::string::npos)
      << annealing;
}

// The learner a run gets when it names none (docs/learning.md "Which learner a run uses"): the
// prior where the robot's dataset walked as the run walks is, the annealing elsewhere; recorded.
TEST(CliLearn, TheDefaultLearnerIsThePriorWhereTheRobotsDatasetIsElseTheAnnealing) {
  const auto learner = [](const std::string& args) {
    // One trial, one episode and one window after it: the learner is chosen before the walk.
    const bool paper = args.find("--mode paper") != std::string::npos;  // one episode anyway
    const auto r = run_cli("learn " + args + " --max-trials 1 --json" +
                           (paper ? "" : " --max-episodes 1 --monitor-windows 1"));
    // 3: not converged within the one trial, which is all this test needs of the run.
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3) << args << "\n" << r.err;
    const auto j = nlohmann::json::parse(r.out);
    return j.at("options").value("learner", nlohmann::json{{"name", "annealing"}}).at("name");
  };
  EXPECT_EQ(learner("--disable R1,R3"), "prior");
  EXPECT_EQ(learner("--disable R1,R3 --steering off"), "prior");
  EXPECT_EQ(learner("--robot quadruped --disable R2"), "prior");
  EXPECT_EQ(learner("--mode paper --disable R1,R3"), "annealing");
  EXPECT_EQ(learner("--disable R1,R3 --beta 2"), "annealing");  // a beta asks for the annealing
  EXPECT_EQ(learner("--robot octopod --disable R1,R3"), "annealing");  // no dataset
  EXPECT_EQ(learner("--fault R2.CTr:passive@0"), "annealing");  // a body no dataset describes
  EXPECT_EQ(learner("--disable R1,R3 --learner annealing"), "annealing");
  EXPECT_EQ(learner("--disable R1,R3 --no-tell-fault"), "annealing");  // docs/learning.md
  const std::string robot_file =
      std::string(MULTICPG_SOURCE_DIR) + "/examples/robots/hobby_hexapod.toml";
  EXPECT_EQ(learner("--robot " + robot_file + " --disable R1,R3 --learner prior"), "prior");
  EXPECT_EQ(learner("--robot " + robot_file + " --disable R1,R3"), "annealing");  // another body
  const auto text = run_cli("learn --disable R1,R3 --max-trials 1 --max-episodes 1");
  ASSERT_TRUE(text.exit_code == 0 || text.exit_code == 3) << text.err;
  EXPECT_NE(text.out.find("robust mode (steering reflex, 3 windows to hold), faults R1+R3 fail@0, "
                          "learner prior,"),
            std::string::npos)
      << text.out;
}

// --no-tell-fault: the learner is told nothing of the fault, so it may change a failed leg's
// period (the prior does in its first trial here; told the legs it never does); the record keeps
// the option, the header says it, and a record without it reads as told.
TEST(CliLearn, ALearnerToldNothingSearchesTheFailedLegsToo) {
  const auto trials = [](const std::string& args) {
    const auto r = run_cli(
        "learn --disable R1,R3,L2 --learner prior --max-trials 2 "
        "--max-episodes 1 --json " +
        args);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3) << args << "\n" << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto failed_changed = [](const nlohmann::json& run) {
    bool changed = false;
    for (const nlohmann::json& t : run.at("trace")) {
      for (const char* leg : {"R1", "R3", "L2"}) changed = changed || t.at("periods").at(leg) != 4;
    }
    return changed;
  };
  const nlohmann::json told = trials("");
  const nlohmann::json blind = trials("--no-tell-fault");
  EXPECT_FALSE(told.at("options").contains("tell_fault")) << "written only when off";
  EXPECT_EQ(blind.at("options").at("tell_fault"), false);
  EXPECT_FALSE(failed_changed(told));
  EXPECT_TRUE(failed_changed(blind));
  const auto text = run_cli(
      "learn --disable R1,R3,L2 --no-tell-fault --learner prior "
      "--max-trials 1 --max-episodes 1");
  EXPECT_NE(text.out.find("learner prior told nothing of the fault,"), std::string::npos)
      << text.out;
}

TEST(CliLearn, OutKeepsTraceAndPerStepRecord) {
  const std::string dir = make_temp_dir("learn-");
  const auto r = run_cli(
      "learn --robot quadruped --disable L2 --learner annealing --seed 1 --out " + dir + "/run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(read_file(fs::path(dir) / "run/learning.json"));
  const std::string trace = read_file(fs::path(dir) / "run/trace.csv");
  EXPECT_EQ(trace.substr(0, trace.find('\n')),
            "trial,R1,R2,L1,L2,deviation_deg,accepted,acceptance_probability,legs_changed,redraws,"
            "tabu_redraw");
  EXPECT_EQ(count_lines(trace), j.at("trials").get<int>() + 1);
  const std::string steps = read_file(fs::path(dir) / "run/steps.csv");
  EXPECT_EQ(steps.rfind("step,time_s,x_m,y_m,z_m,yaw_deg,sensed_yaw_deg,R1_TC_command,", 0), 0u);
  EXPECT_EQ(count_lines(steps), j.at("steps_walked").get<int>() + 2);  // header + row 0
  fs::remove_all(dir);
}

// Learning under a joint fault (docs/faults.md "Learning under any fault"): a passive CTr on R2
// that comes after the robot walks straight is noticed by robust mode's monitoring, learned
// with no leg taken out of the search (R2 still oscillates), and recorded as the fault it is,
// not as a lost leg.
TEST(CliLearn, RobustModeNoticesALateJointFaultAndLearnsWithItsLeg) {
  const CliResult r = run_cli("learn --mode robust --fault R2.CTr:passive@1200 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "converged");
  EXPECT_GE(j.at("detection_step").get<long>(), 1200);
  EXPECT_TRUE(j.at("disabled").empty());
  const auto& faults = j.at("options").at("faults");
  ASSERT_EQ(faults.size(), 1U);
  EXPECT_EQ(faults[0].at("kind"), "passive");
  EXPECT_EQ(faults[0].at("step"), 1200);
  EXPECT_TRUE(j.at("options").at("disabled").empty());
}

// A run's table streams: the header at once and each trial's row as it is decided, read from a
// pipe while the process still runs (the dog that cannot compensate R1 walks for minutes).
TEST(CliLearn, StreamsEachTrialBeforeTheRunEnds) {
  const std::string cmd = "sh -c 'echo $$; exec " + std::string(MULTICPG_EXE) + " learn --robot " +
                          MULTICPG_SOURCE_DIR +
                          "/examples/robots/dog12.toml --disable R1' 2>/dev/null";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[4096];
  ASSERT_NE(std::fgets(buffer, sizeof buffer, pipe), nullptr);
  const long pid = std::stol(buffer);
  std::vector<std::string> lines;
  bool trial = false;
  while (!trial && std::fgets(buffer, sizeof buffer, pipe) != nullptr) {
    lines.emplace_back(buffer);
    trial = lines.back().rfind("    1 ", 0) == 0;  // the first trial's row
  }
  // Still running (not a zombie): the row came before the end.
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_text, name, state;
  stat >> pid_text >> name >> state;
  ::kill(static_cast<pid_t>(pid), SIGKILL);
  ::pclose(pipe);
  ASSERT_TRUE(trial) << "no trial row before the output ended";
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines.front().rfind("quadruped from ", 0), 0u) << lines.front();
  EXPECT_NE(lines[1].find("terrain flat"), std::string::npos) << lines[1];
  EXPECT_NE(state, "Z") << "the process had ended";
  EXPECT_FALSE(state.empty()) << "the process had ended";
}

// The step budget ends the dog's R1 run, which never converges, with a clear result, recorded
// with the result; its trials are numbered across the table.
TEST(CliLearn, StepBudgetEndsARunThatCannotConverge) {
  const std::string dir = make_temp_dir("learn-budget-");
  const auto r =
      run_cli("learn --robot " + std::string(MULTICPG_SOURCE_DIR) +
              "/examples/robots/dog12.toml --disable R1 --step-budget 12000 --out " + dir);
  // Not converged: exit 3, every output written (docs/cli.md "Exit codes and signals").
  ASSERT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto j = nlohmann::json::parse(read_file(dir + "/learning.json"));
  EXPECT_EQ(j.at("status"), "budget reached");
  EXPECT_FALSE(j.at("converged").get<bool>());
  EXPECT_EQ(j.at("options").at("step_budget"), 12000);
  const int trials = j.at("trials").get<int>();
  EXPECT_GE(trials, 1);
  // The budget is checked after each trial: one trial at most past it (settle and 3 windows),
  // then the monitored windows.
  EXPECT_LT(j.at("steps_walked").get<long>(), 12000 + 2045 + 10 * 400 + 4000);
  EXPECT_NE(r.out.find("budget reached after " + std::to_string(trials) + " trial"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("--step-budget"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("best trial measured: trial "), std::string::npos) << r.out;
  std::ostringstream last_row;
  last_row << "\n" << std::setw(5) << trials << "  4x";
  EXPECT_NE(r.out.find(last_row.str()), std::string::npos)
      << "the last trial's row carries the run's trial count\n"
      << r.out;
  fs::remove_all(dir);
}

// The default budget is the documented one, recorded with every result and shown in --help.
TEST(CliLearn, DefaultStepBudgetIsTheDocumentedOne) {
  EXPECT_EQ(multicpg::learning::kDefaultStepBudget, 1'000'000);
  const auto golden = nlohmann::json::parse(
      read_file(std::string(MULTICPG_SOURCE_DIR) + "/tests/data/golden/learn-paper-R1.json"));
  EXPECT_EQ(golden.at("options").at("step_budget"), multicpg::learning::kDefaultStepBudget);
  const std::string docs = read_file(std::string(MULTICPG_SOURCE_DIR) + "/docs/learning.md");
  EXPECT_NE(docs.find("`--step-budget` (default 1,000,000"), std::string::npos);
  const auto help = run_cli("learn --help");
  EXPECT_NE(help.out.find("--step-budget"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("1000000"), std::string::npos) << help.out;
}

// Trials are numbered across episodes; "1 trial", not "1 trials".
TEST(CliLearn, TableNumbersTrialsAcrossEpisodes) {
  multicpg::experiments::RunSpec spec;
  spec.learning = multicpg::learning::CompensationOptions{};
  spec.faults = multicpg::body::fail_at({0}, 0);
  std::ostringstream out;
  multicpg::apps::LearningTable table(out, spec);
  const auto event = [](multicpg::body::EventKind kind, int episode, int trial) {
    multicpg::body::Event e;
    e.kind = kind;
    e.episode = episode;
    e.trial = trial;
    e.periods = {4, 5, 4, 4, 4, 4};
    e.deviation_deg = 10.0;
    return e;
  };
  using multicpg::body::EventKind;
  for (const auto& e : {event(EventKind::detection, 1, 0), event(EventKind::trial_end, 1, 1),
                        event(EventKind::trial_end, 1, 2), event(EventKind::episode_end, 1, 2),
                        event(EventKind::detection, 2, 0), event(EventKind::trial_end, 2, 1),
                        event(EventKind::episode_end, 2, 1)}) {
    table.event(e);
  }
  const std::string text = out.str();
  EXPECT_NE(text.find("\n    3  4x   5"), std::string::npos) << text;
  EXPECT_EQ(text.find("\n    1  4x   5", text.find("episode 2:")), std::string::npos) << text;
  EXPECT_NE(text.find("episode 2 ended after 1 trial: "), std::string::npos) << text;
  EXPECT_NE(text.find("episode 1 ended after 2 trials: "), std::string::npos) << text;
  EXPECT_EQ(multicpg::apps::counted(1, "trial"), "1 trial");
}

// When the reflex alone holds the course the output says so, and how to see period learning.
TEST(CliLearn, SaysWhenTheReflexHeldTheCourse) {
  const auto r = run_cli("learn --disable R1 --seed 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("The steering reflex held the course"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--steering off"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--mode paper"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("body model paper-sim"), std::string::npos) << r.out;
}

TEST(CliLearn, BadInput) {
  expect_bad_input("learn --disable R1 --beta -1", "beta");
  expect_bad_input("learn --disable R1 --threshold 0", "threshold");
  expect_bad_input("learn --disable R1 --window 0", "window");
  expect_bad_input("learn --disable R1 --max-trials 0", "--max-trials");
  expect_bad_input("learn --disable R1 --max-episodes 0", "--max-episodes");
  expect_bad_input("learn --disable R1 --mode paper --max-episodes 2", "robust-mode");
  // beta is the annealing's option: refused for another learner, and given once.
  expect_bad_input("learn --disable R1 --learner random --beta 1", "--beta");
  expect_bad_input("learn --disable R1 --beta 1 --learner-option beta=2", "given twice");
  expect_bad_input("learn --disable R1,R2,R3,L1,L2,L3", "every leg");
  expect_bad_input("learn --disable R9", "R9");
  expect_bad_input("learn --robot quadruped --disable R3", "R3");
  expect_bad_input("learn --robot spider --disable R1", "spider");
  expect_bad_input("learn", "--disable");
  expect_bad_input("learn --disable R1 --out /proc/multicpg-out", "/proc/multicpg-out");
  expect_bad_input("learn --disable R1 --disable-at -3", "--disable-at");
  // Robust mode's options.
  expect_bad_input("learn --disable R1 --mode fast", "fast");
  expect_bad_input("learn --disable R1 --steering wheel", "wheel");
  expect_bad_input("learn --disable R1 --mode paper --steering off", "robust-mode");
  expect_bad_input("learn --fault R1,R1@0", "twice");
  expect_bad_input("learn --fault R1@0 --fault R1@500", "already failed");
  expect_bad_input("learn --fault R1@900 --recover R1@400", "has not failed");
  expect_bad_input("learn --recover R1@400", "has not failed");
  expect_bad_input("learn --fault R1@-5", "--fault");
  expect_bad_input("learn --fault R1@12x", "--fault");
  expect_bad_input("learn --fault R1", "LEGS@STEP");
  expect_bad_input("learn --fault @400", "LEGS@STEP");
  expect_bad_input("learn --fault R1@0 --fault R2@0 --mode paper", "paper mode");
  expect_bad_input("learn --disable R1 --hold-windows 0", "--hold-windows");
  expect_bad_input("learn --disable R1 --monitor-windows 0", "--monitor-windows");
}

// --mode paper is the paper's algorithm as it was before robust mode existed. The
// fixtures were recorded by `learn --json` before that change; the explicit contact pairs
// (docs/robots.md) changed the physics in its last bits (1e-13 deg), so deviations match to 1e-9
// and every decision exactly.
TEST(CliLearn, PaperModeReproducesTheRecordedTraces) {
  const fs::path dir = fs::path(MULTICPG_SOURCE_DIR) / "tests/data/paper_traces";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const auto want = nlohmann::json::parse(read_file(entry.path().string()));
    std::string legs;
    for (const auto& leg : want.at("disabled")) {
      if (!legs.empty()) legs += ',';
      legs += leg.get<std::string>();
    }
    const auto r = run_cli("learn --mode paper --robot " + want.at("robot").get<std::string>() +
                           " --disable " + legs + " --seed " +
                           std::to_string(want.at("seed").get<int>()) + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto got = nlohmann::json::parse(r.out);
    EXPECT_EQ(got.at("steps_walked"), want.at("steps_walked")) << entry.path();
    EXPECT_EQ(got.at("detection_step"), want.at("detection_step")) << entry.path();
    const auto& a = got.at("trace");
    const auto& b = want.at("trace");
    ASSERT_EQ(a.size(), b.size()) << entry.path();
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].at("periods"), b[i].at("periods")) << entry.path() << " trial " << i + 1;
      EXPECT_EQ(a[i].at("accepted"), b[i].at("accepted")) << entry.path() << " trial " << i + 1;
      EXPECT_NEAR(a[i].at("deviation_deg").get<double>(), b[i].at("deviation_deg").get<double>(),
                  1e-9)
          << entry.path() << " trial " << i + 1;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

// Robust mode on the real robot: R1 and R2 fail while it walks; learning holds and the JSON says
// so, one episode per trigger, the monitored windows all under the threshold.
TEST(CliLearn, RobustRunHoldsAndReportsItsEpisodes) {
  const auto r = run_cli("learn --disable R1,R2 --seed 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("mode"), "robust");
  EXPECT_EQ(j.at("options").at("steering"), "reflex");
  ASSERT_GE(j.at("episodes").size(), 1u);
  EXPECT_TRUE(j.at("converged").get<bool>());
  ASSERT_EQ(j.at("final_windows").size(), 6u);
  for (const auto& w : j.at("final_windows")) {
    EXPECT_LT(std::abs(w.at("yaw_deg").get<double>()), 8.0);
    EXPECT_LT(std::abs(w.at("path_deg").get<double>()), 8.0);
  }
}

// R1 alone: the steering reflex holds the course from the window after the fault (with all
// periods 4 and less than max_effort of a side's swing), so no window asks for learning.
TEST(CliLearn, RobustReflexAloneHoldsR1) {
  const auto r = run_cli("learn --disable R1 --seed 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "no deviation");
  EXPECT_TRUE(j.at("episodes").empty());
  ASSERT_EQ(j.at("final_windows").size(), 6u);
  for (const auto& w : j.at("final_windows")) {
    EXPECT_LT(std::abs(w.at("yaw_deg").get<double>()), 8.0);
    EXPECT_LT(std::abs(w.at("path_deg").get<double>()), 8.0);
    EXPECT_LT(w.at("steering_effort").get<double>(), 0.75);
  }
}

// A second fault learns again; a recovery of every leg resynchronises at the master's period.
TEST(CliLearn, FaultsThatComeAndGo) {
  const auto two = run_cli("learn --fault R1,R3@0 --fault L1@20000 --seed 1 --json");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const auto a = nlohmann::json::parse(two.out);
  // At least one episode for each fault (monitoring may add one when a held gait drifts later).
  int before = 0;
  int after = 0;
  for (const auto& e : a.at("episodes")) {
    (e.at("detection_step").get<long>() < 20000 ? before : after) += 1;
  }
  EXPECT_GE(before, 1) << a.at("episodes").dump();
  EXPECT_GE(after, 1) << a.at("episodes").dump();
  EXPECT_TRUE(a.at("episodes").back().at("held").get<bool>());

  const auto back = run_cli("learn --fault R1@0 --recover R1@20000 --seed 1 --json");
  ASSERT_EQ(back.exit_code, 0) << back.err;
  const auto b = nlohmann::json::parse(back.out);
  for (const auto& [leg, period] : b.at("periods").items()) EXPECT_EQ(period, 4) << leg;
  ASSERT_EQ(b.at("final_windows").size(), 6u);
  for (const auto& w : b.at("final_windows")) {
    EXPECT_LT(std::abs(w.at("yaw_deg").get<double>()), 8.0);
    EXPECT_LT(std::abs(w.at("path_deg").get<double>()), 8.0);
  }
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
  // Runs of at most 10 trials: each still walks for about a second, so that the kill below
  // lands between the second saved run and the last.
  const std::string args = "experiment table --robot quadruped --runs 1 --seed 7 --max-trials 10 ";
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

  // Each session's provenance is recorded (the killed start and the resume), apart from the
  // options, so equal experiments keep equal experiment.json files.
  const auto sessions = nlohmann::json::parse(read_file(killed / "provenance.json"));
  ASSERT_EQ(sessions.size(), 2u);
  for (const auto& s : sessions) {
    EXPECT_NE(s.at("command_line").get<std::string>().find("--out"), std::string::npos);
    EXPECT_FALSE(s.at("git_commit").get<std::string>().empty());
    EXPECT_EQ(s.at("mujoco_version"), "2.2.2");
    EXPECT_FALSE(s.at("cpu").get<std::string>().empty());
  }
  EXPECT_EQ(read_file(killed / "experiment.json"),
            read_file(fs::path(dir) / "one/experiment.json"));

  // Resuming with other arguments is refused, naming what differs.
  const auto other = run_cli(args + "--servo-gain 20 --out " + killed.string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("arguments.sim.servo_gain"), std::string::npos) << other.err;
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

// A run's link errors say whether they are to worry about (docs/hardware.md "Rehearse on the
// emulator"): late answers are a busy machine's, garbled ones are not.
TEST(HardwareSummary, LinkErrorsSayWhetherTheyAreNormal) {
  const auto summary = [](const nlohmann::json& bus) {
    const nlohmann::json none{{"timeout", 0}, {"bad_checksum", 0}};
    return multicpg::hw::hardware_summary(
        {{"pacing", "lock_step"},
         {"timing", {{"period_mean_s", 0.001}, {"jitter_p99_s", 0.0}, {"overruns", 0}}},
         {"errors", {{"bus", bus}, {"yaw", none}}},
         {"clamped_targets", 0}});
  };
  const std::string clean = summary({{"timeout", 0}, {"bad_checksum", 0}});
  EXPECT_NE(clean.find("link errors: none"), std::string::npos) << clean;
  EXPECT_EQ(clean.find("normal"), std::string::npos) << clean;
  const std::string late = summary({{"timeout", 2}, {"bad_checksum", 0}});
  EXPECT_NE(late.find("bus timeout 2 (isolated late answers are normal on a busy machine"),
            std::string::npos)
      << late;
  const std::string garbled = summary({{"timeout", 2}, {"bad_checksum", 1}});
  EXPECT_NE(garbled.find("not a busy machine's doing"), std::string::npos) << garbled;
}

}  // namespace
