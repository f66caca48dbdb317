// The online compensation loop (docs/learning.md "Online compensation") on a fake walker whose yaw
// rate is a fixed function of the periods of its working legs, plus the settle-time claim behind
// the default.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "common/errors.h"
#include "learning/choice_options.h"
#include "learning/compensation.h"
#include "learning/json.h"
#include "learning/number_options.h"
#include "tests/fake_body.h"

namespace multicpg::learning {
namespace {

using robot::RobotKind;

// The paper's algorithm (§3); robust mode has its own tests below.
CompensationOptions options_for(std::uint64_t seed) {
  CompensationOptions o;
  o.mode = Mode::paper;
  o.seed = seed;
  return o;
}

// The legs fail at the start of the walk.
body::FaultTimeline failing(std::vector<std::size_t> legs) {
  return body::fail_at(legs, 0);
}

Periods periods_of(body::Body& w) {
  Periods p;
  for (const neural::LegState& leg : w.controller().legs) p.push_back(leg.cpg.period);
  return p;
}

TEST(Compensation, ConvergesOnFakeHexapodWithR1Disabled) {
  const CompensationOptions o = options_for(1);
  FakeBody walker(RobotKind::hexapod, failing({0}));
  const LearningResult r = compensate(walker, o, {});

  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.outcome, learning::Outcome::converged);
  EXPECT_EQ(r.reason, StopReason::below_threshold);
  EXPECT_NEAR(r.initial_deviation_deg, 0.25 * FakeBody::kGainDegPerStep * kDefaultWindowSteps,
              1e-9);
  EXPECT_LT(r.final_deviation_deg, kDefaultThresholdDeg);
  EXPECT_GE(r.trials, 1);
  ASSERT_EQ(r.trace.size(), static_cast<std::size_t>(r.trials));
  EXPECT_TRUE(r.trace.back().accepted);
  EXPECT_EQ(r.trace.back().periods, r.periods);
  for (const TrialRecord& t : r.trace) EXPECT_EQ(t.periods[0], kStartPeriod);  // R1 fixed

  // The controller walks on with the learned periods, every client desynchronised.
  EXPECT_EQ(periods_of(walker), r.periods);
  for (std::size_t i = 1; i < walker.controller().legs.size(); ++i) {
    EXPECT_FALSE(neural::follows_master(walker.controller(), i));
  }
  // Detection: settle + one window; each trial: settle + one window.
  const long settle = default_settle_steps(walker.controller_model());
  EXPECT_EQ(r.settle_steps, settle);
  EXPECT_EQ(r.detection_step, settle + kDefaultWindowSteps);
  EXPECT_EQ(r.steps_walked, (r.trials + 1) * (settle + kDefaultWindowSteps));
  EXPECT_EQ(walker.step_count(), r.steps_walked);
}

TEST(Compensation, SameSeedSameRunOtherSeedOtherTrace) {
  const robot::Morphology& morph = robot::morphology(RobotKind::hexapod);
  auto run = [&](std::uint64_t seed) {
    const CompensationOptions o = options_for(seed);
    FakeBody walker(RobotKind::hexapod, failing({0, 2}));
    return to_json(compensate(walker, o, {}), morph, {0, 2});
  };
  const nlohmann::json a = run(7);
  EXPECT_EQ(a, run(7));
  EXPECT_NE(a.at("trace"), run(8).at("trace"));
}

TEST(Compensation, HealthyRobotNeedsNoCompensation) {
  CompensationOptions o = options_for(1);
  o.settle_steps = 10;
  FakeBody walker(RobotKind::hexapod);
  const LearningResult r = compensate(walker, o, {});
  EXPECT_FALSE(r.converged());
  EXPECT_EQ(r.outcome, learning::Outcome::no_deviation);
  EXPECT_FALSE(r.reason.has_value());
  EXPECT_FALSE(r.detection_step.has_value());
  EXPECT_EQ(r.trials, 0);
  EXPECT_EQ(r.steps_walked, 10 + kDefaultDetectionWindows * kDefaultWindowSteps);
  EXPECT_TRUE(neural::follows_master(walker.controller(), 1));  // still synchronised
}

TEST(Compensation, LateFailureIsDetectedAfterIt) {
  CompensationOptions o = options_for(1);
  o.settle_steps = 0;
  // Healthy windows [0,400) and [400,800) come first.
  FakeBody walker(RobotKind::hexapod, body::fail_at({0}, 1000));
  const LearningResult r = compensate(walker, o, {});
  ASSERT_TRUE(r.detection_step.has_value());
  // [800,1200) holds 200 disabled steps: 19 deg > 8, detected at its end.
  EXPECT_EQ(*r.detection_step, 1200);
  EXPECT_NEAR(r.initial_deviation_deg, 0.25 * FakeBody::kGainDegPerStep * 200, 1e-9);
  EXPECT_TRUE(r.converged());
}

TEST(Compensation, TrialCapEndsNotConvergedWithTheAcceptedPeriods) {
  // A bias no period combination can cancel: 0.2 deg/step, 80 deg per window.
  CompensationOptions o = options_for(3);
  o.search.max_trials = 12;
  o.settle_steps = 0;
  FakeBody walker(RobotKind::hexapod, failing({0}), 0.2);
  const LearningResult r = compensate(walker, o, {});
  EXPECT_FALSE(r.converged());
  EXPECT_EQ(r.outcome, learning::Outcome::not_converged);
  EXPECT_EQ(r.reason, StopReason::trial_cap);
  EXPECT_EQ(r.trials, 12);
  EXPECT_GE(r.final_deviation_deg, kDefaultThresholdDeg);
  EXPECT_EQ(periods_of(walker), r.periods);
}

// The step budget counts the trials' steps over every episode: past it, no trial and no episode
// starts, and the run ends "budget reached" with the accepted periods (docs/learning.md "Step
// budget").
TEST(Compensation, StepBudgetEndsBudgetReachedInBothModes) {
  for (const Mode mode : {Mode::paper, Mode::robust}) {
    CompensationOptions o = options_for(3);
    o.mode = mode;
    o.settle_steps = 0;
    o.steering = Steering::off;
    // 5 trials of one window (paper) or of the first window over the threshold (robust).
    o.step_budget = 5 * kDefaultWindowSteps;
    FakeBody walker(RobotKind::hexapod, failing({0}), 0.2);
    const LearningResult r = compensate(walker, o, {});
    EXPECT_EQ(r.outcome, Outcome::budget_reached) << to_string(mode);
    EXPECT_FALSE(r.converged());
    EXPECT_FALSE(r.reason.has_value());
    EXPECT_EQ(r.trials, 5) << to_string(mode);
    ASSERT_EQ(r.episodes.size(), 1u) << to_string(mode);
    EXPECT_EQ(periods_of(walker), r.periods);
    EXPECT_EQ(parse_outcome("budget reached"), Outcome::budget_reached);
  }
}

TEST(Compensation, ExhaustedSearchSpaceEndsNotConverged) {
  CompensationOptions o = options_for(4);
  o.settle_steps = 0;
  FakeBody walker(RobotKind::quadruped, failing({0, 1, 2}), 0.2);  // only L2: 5 combinations
  const LearningResult r = compensate(walker, o, {});
  EXPECT_EQ(r.outcome, learning::Outcome::not_converged);
  EXPECT_EQ(r.reason, StopReason::space_exhausted);
  EXPECT_EQ(r.trials, 4);
}

TEST(Compensation, JsonHasTheReportedFields) {
  const robot::Morphology& morph = robot::morphology(RobotKind::hexapod);
  const CompensationOptions o = options_for(1);
  FakeBody walker(RobotKind::hexapod, failing({0}));
  const nlohmann::json j = to_json(compensate(walker, o, {}), morph, {0});
  EXPECT_TRUE(j.at("converged").is_boolean());
  EXPECT_TRUE(j.at("trials").is_number_integer());
  EXPECT_TRUE(j.at("final_deviation_deg").is_number());
  EXPECT_EQ(j.at("periods").at("R1"), kStartPeriod);
  EXPECT_EQ(j.at("periods").size(), morph.size());
  EXPECT_EQ(j.at("disabled"), nlohmann::json::array({"R1"}));
  EXPECT_EQ(j.at("reason"), "below threshold");
  ASSERT_EQ(j.at("trace").size(), j.at("trials").get<std::size_t>());
  for (const nlohmann::json& t : j.at("trace")) {
    EXPECT_TRUE(t.at("periods").is_object());
    EXPECT_TRUE(t.at("deviation_deg").is_number());
    EXPECT_TRUE(t.at("accepted").is_boolean());
  }
}

// Each numeric option the CLI and Python make from learning/number_options.h is the record's key
// it names: its highest value is written under that key, reads back into the same member, and
// one above it is refused naming that key.
TEST(Compensation, EveryNumberOptionIsTheRecordKeyItNames) {
  for (const LearningNumber& option : kLearningNumbers) {
    std::visit(
        [](const auto& n) {
          SCOPED_TRACE(std::string(n.flag));
          CompensationOptions o;
          n.field(o) = n.limits.hi;
          const nlohmann::json j = o;
          std::string pointer = "/" + std::string(n.key);
          std::replace(pointer.begin(), pointer.end(), '.', '/');
          EXPECT_EQ(j.at(nlohmann::json::json_pointer(pointer)), n.limits.hi);
          CompensationOptions back = j.get<CompensationOptions>();
          EXPECT_EQ(n.field(o), n.field(back));
          EXPECT_NO_THROW(validate(o));
          n.field(o) = n.limits.hi + 1;
          try {
            validate(o);
            ADD_FAILURE() << "one above the limits is taken";
          } catch (const OptionError& e) {
            EXPECT_EQ(e.key(), n.key);
          }
        },
        option);
  }
}

// The options set by a name or a switch (learning/choice_options.h) are the record keys they
// name: each value they take is written under that key and reads back into the same member.
TEST(Compensation, EveryNameAndSwitchOptionIsTheRecordKeyItNames) {
  for (const NameOption& option : kLearningNames) {
    SCOPED_TRACE(std::string(option.flag));
    for (const std::string& name : option.names()) {
      CompensationOptions o;
      option.set(o, name);
      const nlohmann::json j = o;
      EXPECT_EQ(j.at(std::string(option.key)), name);
      EXPECT_EQ(option.get(j.get<CompensationOptions>()), name);
    }
    EXPECT_EQ(option.get(CompensationOptions{}), option.names().front()) << "default first";
    CompensationOptions o;
    EXPECT_THROW(option.set(o, "sideways"), BadInput);
  }
  for (const SwitchOption& option : kLearningSwitches) {
    SCOPED_TRACE(std::string(option.flag));
    CompensationOptions o;
    EXPECT_TRUE(option.field(o)) << "on by default";
    option.field(o) = false;
    const nlohmann::json j = o;
    EXPECT_EQ(j.at(std::string(option.key)), false);
    CompensationOptions back = j.get<CompensationOptions>();
    EXPECT_FALSE(option.field(back));
  }
}

TEST(Compensation, RejectsBadInput) {
  auto bad = [&](const std::function<void(CompensationOptions&)>& change) {
    CompensationOptions o = options_for(1);
    change(o);
    EXPECT_THROW(validate(o), OptionError);
  };
  bad([](CompensationOptions& o) { o.window_steps = 0; });
  bad([](CompensationOptions& o) { o.settle_steps = -1; });
  bad([](CompensationOptions& o) { o.detection_windows = 0; });
  bad([](CompensationOptions& o) { o.learner.options["beta"] = -1.0; });
  bad([](CompensationOptions& o) { o.search.threshold_deg = 0.0; });
  // A timeline no walker can have: a schedule refuses it before any learning.
  const robot::Morphology& hex = robot::morphology(RobotKind::hexapod);
  EXPECT_THROW(body::FaultSchedule(hex, failing({0, 1, 2, 3, 4, 5})), BadInput);
  EXPECT_THROW(body::FaultSchedule(hex, failing({6})), BadInput);
  EXPECT_THROW(body::FaultSchedule(hex, failing({1, 1})), BadInput);
  FakeBody walker(RobotKind::hexapod);
  CompensationOptions o = options_for(1);
  o.window_steps = 0;
  EXPECT_THROW(compensate(walker, o, {}), BadInput);
  EXPECT_EQ(walker.step_count(), 0);
}

TEST(Compensation, WrapsYawToHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(multicpg::wrap_degrees(190.0), -170.0);
  EXPECT_DOUBLE_EQ(multicpg::wrap_degrees(-190.0), 170.0);
  EXPECT_DOUBLE_EQ(multicpg::wrap_degrees(180.0), 180.0);
  EXPECT_DOUBLE_EQ(multicpg::wrap_degrees(-180.0), 180.0);
  EXPECT_DOUBLE_EQ(multicpg::wrap_degrees(540.0), 180.0);
  EXPECT_DOUBLE_EQ(multicpg::wrap_degrees(-30.0), -30.0);
}

// The default settle time covers the lock of every learnable period except p = 4 (which is
// nearly right long before it locks): from each period, after a reset to p in {5, 6, 8, 9},
// every leg's swing pattern repeats with the gait period p(2p+1) from the settle step on.
TEST(Compensation, DefaultSettleCoversCpgLockAndDelays) {
  constexpr long kWarmup = 2000;
  constexpr long kChecked = 1000;
  for (RobotKind kind : {RobotKind::hexapod, RobotKind::quadruped}) {
    const neural::ControllerModel model = neural::make_controller_model(kind);
    const long settle = default_settle_steps(model);
    for (int from : {4, 5, 6, 8, 9}) {
      for (int p : {5, 6, 8, 9}) {
        neural::ControllerState state = neural::make_controller_state(model, from);
        for (long t = 0; t < kWarmup; ++t) neural::controller_step(model, state);
        neural::set_synchronised(state, false);
        neural::set_period(model, state, p);
        const long cycle = p * (2L * p + 1);
        std::vector<std::vector<bool>> swing;
        for (long t = 0; t < settle + kChecked + cycle; ++t) {
          neural::controller_step(model, state);
          std::vector<bool> now;
          for (const neural::LegState& leg : state.legs) now.push_back(leg.delayed.swing);
          swing.push_back(now);
        }
        for (long t = settle; t < settle + kChecked; ++t) {
          ASSERT_EQ(swing[t], swing[t + cycle])
              << model.morphology.name << " from p" << from << " to p" << p << " at step " << t;
        }
      }
    }
  }
  EXPECT_EQ(default_settle_steps(neural::make_controller_model(RobotKind::hexapod)), 337);
  EXPECT_EQ(default_settle_steps(neural::make_controller_model(RobotKind::quadruped)), 319);
}

// Robust mode on the fake walker: faults that come and go.
CompensationOptions robust_options(std::uint64_t seed) {
  CompensationOptions o;
  o.mode = Mode::robust;
  o.steering = Steering::off;  // the fake walker has no VRN
  o.seed = seed;
  return o;
}

int count(const std::vector<body::Event>& events, body::EventKind kind) {
  return static_cast<int>(std::count_if(events.begin(), events.end(),
                                        [&](const body::Event& e) { return e.kind == kind; }));
}

TEST(RobustCompensation, HeldCombinationHoldsEveryWindowItWasJudgedOn) {
  const CompensationOptions o = robust_options(1);
  FakeBody walker(RobotKind::hexapod, {{0, {0}, false}});
  const LearningResult r = compensate(walker, o, {});
  ASSERT_TRUE(r.converged());
  ASSERT_EQ(r.episodes.size(), 1u);
  EXPECT_TRUE(r.episodes[0].held);
  // The run ends with the monitored windows, every one under the threshold on yaw and path.
  ASSERT_EQ(r.final_windows.size(), static_cast<std::size_t>(kDefaultMonitorWindows));
  for (const body::WindowMeasure& m : r.final_windows) EXPECT_LT(m.worst_deg(), 8.0);
  EXPECT_EQ(count(walker.events, body::EventKind::detection), 1);
  EXPECT_EQ(count(walker.events, body::EventKind::trial_end), r.trials);
  EXPECT_EQ(count(walker.events, body::EventKind::episode_end), 1);
}

TEST(RobustCompensation, RefusesAWalkerThatHasWalked) {
  const CompensationOptions o = robust_options(1);
  FakeBody walked(RobotKind::hexapod, {{0, {0}, false}});
  walked.step();
  EXPECT_THROW(compensate(walked, o, {}), std::invalid_argument);
}

TEST(RobustCompensation, SecondFaultLearnsTwice) {
  const CompensationOptions o = robust_options(2);
  FakeBody walker(RobotKind::hexapod, {{0, {0}, false}, {30000, {4}, false}});
  const LearningResult r = compensate(walker, o, {});
  ASSERT_EQ(r.episodes.size(), 2u);
  EXPECT_LT(r.episodes[0].detection_step, 30000);
  EXPECT_GT(r.episodes[1].detection_step, 30000);
  EXPECT_TRUE(r.episodes[1].held);
  EXPECT_TRUE(r.converged());
  // The second episode never changes a failed leg (R1, L2).
  EXPECT_EQ(r.periods[0], kStartPeriod);
  EXPECT_EQ(r.periods[4], r.episodes[0].periods[4]);
  EXPECT_EQ(count(walker.events, body::EventKind::fault), 2);
}

// The second fault comes after the one episode the run may start: the windows after it deviate
// and nothing is left to learn with, so the run ends not converged for the episode cap, although
// its one episode held.
TEST(RobustCompensation, EpisodeCapEndsTheRunAndIsItsReason) {
  CompensationOptions o = robust_options(2);
  o.max_episodes = 1;
  FakeBody walker(RobotKind::hexapod, {{0, {0}, false}, {30000, {4}, false}});
  const LearningResult r = compensate(walker, o, {});
  ASSERT_EQ(r.episodes.size(), 1u);
  EXPECT_TRUE(r.episodes[0].held);
  EXPECT_EQ(r.outcome, Outcome::not_converged);
  EXPECT_EQ(r.reason, StopReason::episode_cap);
  EXPECT_EQ(parse_stop_reason(to_string(StopReason::episode_cap)), StopReason::episode_cap);
}

// Every combination turns the fake walker, and only L2 of the quadruped works (5 periods): the
// first episode tries the 4 other than the start, the second the start's (it walks on from
// another), the third nothing. No episode starts after that one: the next would start where it
// did, told the same trials, and try nothing either (before: seven more such, to the cap).
TEST(RobustCompensation, NoEpisodeStartsOnceOneFoundNothingLeftToTry) {
  CompensationOptions o = robust_options(4);
  o.settle_steps = 0;
  FakeBody walker(RobotKind::quadruped, failing({0, 1, 2}), 0.2);
  const LearningResult r = compensate(walker, o, {});
  ASSERT_EQ(r.episodes.size(), 3u);
  EXPECT_EQ(r.episodes[0].trials, 4);
  EXPECT_EQ(r.episodes[1].trials, 1);
  EXPECT_EQ(r.episodes[2].trials, 0);
  EXPECT_EQ(r.trials, 5);
  EXPECT_EQ(r.outcome, Outcome::not_converged);
  EXPECT_EQ(r.reason, StopReason::space_exhausted);
  EXPECT_EQ(r.final_windows.size(), static_cast<std::size_t>(o.monitor_windows));
}

TEST(RobustCompensation, RecoveryResynchronisesAtTheMastersPeriod) {
  const CompensationOptions o = robust_options(3);
  FakeBody walker(RobotKind::hexapod, {{0, {0}, false}, {30000, {0}, true}});
  const LearningResult r = compensate(walker, o, {});
  ASSERT_EQ(r.episodes.size(), 1u);
  EXPECT_EQ(count(walker.events, body::EventKind::recovery), 1);
  const neural::ControllerState& c = walker.controller();
  for (std::size_t i = 0; i < c.legs.size(); ++i) {
    EXPECT_EQ(c.legs[i].cpg.period, c.legs[0].cpg.period) << "leg " << i;
    if (i > 0) {
      EXPECT_TRUE(neural::follows_master(c, i)) << "leg " << i;
    }
  }
  for (const body::WindowMeasure& m : r.final_windows) EXPECT_LT(std::abs(m.yaw_deg), 1e-9);
}

TEST(RobustCompensation, PaperModeRefusesTimelines) {
  CompensationOptions o = robust_options(1);
  o.mode = Mode::paper;
  FakeBody twice(RobotKind::hexapod, {{0, {0}, false}, {900, {0}, true}});
  EXPECT_THROW(compensate(twice, o, {}), OptionError);
  EXPECT_EQ(twice.step_count(), 0);
  const robot::Morphology& hex = robot::morphology(RobotKind::hexapod);
  // Timelines that cannot happen never make a walker.
  EXPECT_THROW(body::FaultSchedule(hex, {{900, {0}, true}}), BadInput);    // recovery before fault
  EXPECT_THROW(body::FaultSchedule(hex, {{0, {0, 0}, false}}), BadInput);  // a leg listed twice
  o = robust_options(1);
  o.hold_windows = 0;
  FakeBody walker(RobotKind::hexapod, {{0, {0}, false}});
  EXPECT_THROW(compensate(walker, o, {}), OptionError);
}

TEST(Steering, CutsTheSideTowardWhichTheRobotMustTurn) {
  const SteeringParams p;
  SteeringState s = start_steering({0.0, 0.0, 0.0});
  // Pointing 5 deg right of the course: turn left, so the left side swings less.
  neural::DriveInputs d = steer(p, s, {0.0, 0.0, -5.0}, {});
  EXPECT_GT(d.turn_left, -1.0);
  EXPECT_EQ(d.turn_right, -1.0);
  // On course, on the line: both sides full forward.
  s = start_steering({0.0, 0.0, 0.0});
  d = steer(p, s, {0.0, 0.0, 0.0}, {});
  EXPECT_EQ(d.turn_left, -1.0);
  EXPECT_EQ(d.turn_right, -1.0);
  // Left of the line, heading along it: turn right (the right side swings less).
  s = start_steering({0.0, 0.0, 0.0});
  d = steer(p, s, {0.0, 0.2, 0.0}, {});
  EXPECT_GT(d.turn_right, -1.0);
  EXPECT_EQ(d.turn_left, -1.0);
}

}  // namespace
}  // namespace multicpg::learning
