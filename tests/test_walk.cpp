// Walking in MuJoCo: straight tripod, slower gaits, standing, turning with a disabled
// front leg, the quadruped, determinism, faults at a given step, physics blow-ups.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <thread>

#include "body/deviation.h"
#include "common/errors.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace {

using namespace multicpg;
using robot::RobotKind;

// p = 4 from reset locks after about 740 steps (docs/controller.md "Steps to lock, from reset")
// and the delay lines fill after 126; measuring starts after both.
constexpr long kSettle = 800;
constexpr double kStraightDeg = 8.0;  // paper §4.1 threshold

const sim::SimModel& model(RobotKind kind) {
  static const std::array<sim::SimModel, robot::kRobotKinds.size()> models{
      sim::make_sim_model(RobotKind::hexapod), sim::make_sim_model(RobotKind::quadruped),
      sim::make_sim_model(RobotKind::octopod)};
  return models[robot::robot_index(kind)];
}

sim::WalkResult walk(RobotKind kind, int period, std::vector<std::size_t> disabled, long settle,
                     long steps, bool record = false) {
  const sim::SimModel& m = model(kind);
  sim::WalkSpec spec;
  spec.start.periods.assign(m.legs.size(), period);
  spec.faults = body::fail_at(disabled, 0);
  spec.settle = settle;
  spec.steps = steps;
  spec.record = record;
  return sim::walk(m, spec);
}

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

std::string list(const std::vector<double>& v) {
  std::string s;
  for (double d : v) s += std::to_string(d) + " ";
  return s;
}

TEST(Walk, HexapodTripodWalksForwardAndStraight) {
  const sim::WalkResult r = walk(RobotKind::hexapod, 4, {}, kSettle, 1200);
  ASSERT_EQ(r.window_deviations_deg.size(), 3u);
  for (double d : r.window_deviations_deg) {
    EXPECT_LT(std::abs(d), kStraightDeg) << list(r.window_deviations_deg);
  }
  EXPECT_GT(r.forward_m, 0.5);
  EXPECT_LT(std::abs(r.lateral_m), 0.2 * r.forward_m);
  RecordProperty("speed_cm_s", std::to_string(100.0 * r.speed_m_s));
  RecordProperty("deviations_deg", list(r.window_deviations_deg));
}

TEST(Walk, SlowerGaitsWalkForwardSlower) {
  double previous = std::numeric_limits<double>::infinity();
  for (int p : {4, 5, 6, 8, 9}) {
    const sim::WalkResult r = walk(RobotKind::hexapod, p, {}, 400, 800);
    EXPECT_GT(r.forward_m, 0.1) << "p = " << p;
    EXPECT_LT(r.speed_m_s, previous) << "p = " << p;
    previous = r.speed_m_s;
    RecordProperty("speed_cm_s_p" + std::to_string(p), std::to_string(100.0 * r.speed_m_s));
  }
}

TEST(Walk, PeriodOneStands) {
  // From the start the legs move into the p = 1 posture and the trunk settles (a warmed-up
  // controller commands the posture at once, so the trunk shifts by about 2.3 cm); then it stays.
  const sim::WalkResult r = walk(RobotKind::hexapod, 1, {}, 0, 800);
  EXPECT_LT(r.distance_m, 0.03);
  const sim::WalkResult settled = walk(RobotKind::hexapod, 1, {}, 200, 600);
  EXPECT_LT(settled.distance_m, 0.002);
}

TEST(Walk, DisabledFrontLegTurnsTowardItsSide) {
  const sim::WalkResult right = walk(RobotKind::hexapod, 4, {0}, kSettle, 1200, true);  // R1
  const sim::WalkResult left = walk(RobotKind::hexapod, 4, {3}, kSettle, 1200, true);   // L1
  ASSERT_EQ(right.window_deviations_deg.size(), 3u);
  for (double d : right.window_deviations_deg) {
    EXPECT_LT(d, -kStraightDeg) << list(right.window_deviations_deg);  // right turn
  }
  for (double d : left.window_deviations_deg) {
    EXPECT_GT(d, kStraightDeg) << list(left.window_deviations_deg);  // left turn
  }
  const double r = -mean(right.window_deviations_deg);
  const double l = mean(left.window_deviations_deg);
  EXPECT_NEAR(l, r, 0.25 * r);
  RecordProperty("R1_deviations_deg", list(right.window_deviations_deg));
  RecordProperty("L1_deviations_deg", list(left.window_deviations_deg));

  // The disabled leg still touches the ground at times (paper §4).
  const sim::WalkRecord& rec = right.record;
  long touches = 0;
  for (std::size_t row = kSettle; row < rec.rows(); ++row) touches += rec.contact[row * rec.legs];
  EXPECT_GT(touches, 50);
}

TEST(Walk, QuadrupedTrotsStraightAndDeviatesWithADisabledLeg) {
  const sim::WalkResult trot = walk(RobotKind::quadruped, 4, {}, kSettle, 1200);
  ASSERT_EQ(trot.window_deviations_deg.size(), 3u);
  for (double d : trot.window_deviations_deg) {
    EXPECT_LT(std::abs(d), kStraightDeg) << list(trot.window_deviations_deg);
  }
  EXPECT_GT(trot.forward_m, 0.5);
  const sim::WalkResult broken = walk(RobotKind::quadruped, 4, {0}, 400, 800);
  for (double d : broken.window_deviations_deg) {
    EXPECT_GT(std::abs(d), kStraightDeg) << list(broken.window_deviations_deg);
  }
}

TEST(Walk, OctopodWalksForward) {
  const sim::WalkResult r = walk(RobotKind::octopod, 4, {}, 400, 400);
  EXPECT_GT(r.forward_m, 0.2);
}

sim::WalkSpec mixed_spec() {
  sim::WalkSpec spec;
  spec.start.periods = {4, 5, 4, 6, 4, 9};
  spec.faults = body::fail_at({2}, 100);
  spec.steps = 250;
  return spec;
}

void expect_same(const sim::WalkRecord& a, const sim::WalkRecord& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.yaw_deg, b.yaw_deg);
  EXPECT_EQ(a.actual, b.actual);
  EXPECT_EQ(a.contact, b.contact);
}

TEST(Walk, SameInputsGiveIdenticalTrajectories) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  const sim::WalkResult a = sim::walk(m, mixed_spec());
  const sim::WalkResult b = sim::walk(m, mixed_spec());
  expect_same(a.record, b.record);
  // A second model compiled from the same inputs gives the same trajectory too.
  const sim::SimModel other = sim::make_sim_model(RobotKind::hexapod);
  expect_same(a.record, sim::walk(other, mixed_spec()).record);
}

TEST(Walk, OneModelSharedByThreads) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  const sim::WalkResult alone = sim::walk(m, mixed_spec());
  sim::WalkResult first, second;
  std::thread t1([&] { first = sim::walk(m, mixed_spec()); });
  std::thread t2([&] { second = sim::walk(m, mixed_spec()); });
  t1.join();
  t2.join();
  expect_same(alone.record, first.record);
  expect_same(alone.record, second.record);
}

TEST(Walk, LegsFailAtTheGivenStep) {
  const sim::WalkResult r = sim::walk(model(RobotKind::hexapod), mixed_spec());
  const sim::WalkRecord& rec = r.record;
  const std::size_t r3 = 2 * 3;  // R3's TC, CTr, FTi in a row
  const auto command = [&](std::size_t row, std::size_t j) {
    return rec.command[row * rec.legs * 3 + r3 + j];
  };
  // Row k is the state after k steps; the leg fails before step 100 runs.
  bool moved = false;
  for (std::size_t row = 1; row <= 100; ++row) moved = moved || command(row, 1) != command(1, 1);
  EXPECT_TRUE(moved);
  for (std::size_t row = 101; row < rec.rows(); ++row) {
    EXPECT_EQ(command(row, 0), 0.0);  // docs/controller.md "Disabled legs"
    EXPECT_EQ(command(row, 1), 0.7);
    EXPECT_EQ(command(row, 2), -0.7);
  }
}

TEST(Walk, UnequalPeriodsFreeTheClients) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  const sim::SimState mixed = sim::start_walk_state(m, {5, 4, 4, 4, 4, 4});
  const sim::SimState equal = sim::start_walk_state(m, {6, 6, 6, 6, 6, 6});
  for (std::size_t leg = 1; leg < 6; ++leg) {
    EXPECT_FALSE(neural::follows_master(mixed.controller, leg));
    EXPECT_TRUE(neural::follows_master(equal.controller, leg));
    EXPECT_EQ(mixed.controller.legs[leg].cpg.period, 4);
  }
  EXPECT_EQ(mixed.controller.legs[0].cpg.period, 5);
}

TEST(Walk, BadSpecsAreRejected) {
  const sim::SimModel& m = model(RobotKind::quadruped);
  sim::WalkSpec spec;
  spec.faults = body::fail_at({0, 1, 2, 3}, 0);
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.faults = {};
  spec.steps = 0;
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.steps = body::kMaxSteps + 1;
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.steps = 10;
  spec.start.periods = {4, 4};
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.start.periods = {};
  spec.faults = body::fail_at({1}, 10);  // past the run
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.faults = {{0, {1}, false}, {5, {1}, false}};  // fails twice
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.faults = {{3, {1}, true}};  // recovers before it failed
  EXPECT_THROW(sim::walk(m, spec), BadInput);
  spec.faults = {};
  spec.start.warmup = -1;
  EXPECT_THROW(sim::walk(m, spec), BadInput);
}

// Without any option the robot starts from a running, locked controller, so the
// intact hexapod walks straight in every window from the first, by heading and by path.
TEST(Walk, IntactHexapodWithDefaultsIsStraightFromTheFirstWindow) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  const sim::WalkResult r = sim::walk(m, sim::WalkSpec{});
  ASSERT_EQ(r.windows.size(), 3u);
  for (const body::WindowMeasure& w : r.windows) {
    EXPECT_LT(std::abs(w.yaw_deg), 8.0) << w.yaw_deg;
    EXPECT_LT(std::abs(w.path_deg), 8.0) << w.path_deg;
  }
}

// R1 disabled turns right and L1 disabled left, by magnitudes within 10 % of each other.
TEST(Walk, R1AndL1TurnsMirrorEachOther) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  const auto mean_turn = [&](std::size_t leg) {
    sim::WalkSpec spec;
    spec.faults = body::fail_at({leg}, 0);
    spec.record = false;
    return mean(sim::walk(m, spec).window_deviations_deg);
  };
  const double r1 = mean_turn(0);
  const double l1 = mean_turn(3);
  EXPECT_LT(r1, -8.0);
  EXPECT_GT(l1, 8.0);
  EXPECT_NEAR(-r1 / l1, 1.0, 0.1) << "R1 " << r1 << ", L1 " << l1;
  RecordProperty("r1_deg_per_window", std::to_string(r1));
  RecordProperty("l1_deg_per_window", std::to_string(l1));
}

TEST(Stepper, FaultsAndRecoveriesReachTheObserverAtTheirSteps) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  struct Log final : sim::Observer {
    std::vector<body::Event> events;
    long steps = 0;
    void on_step(const sim::SimModel&, const sim::SimState&) override { ++steps; }
    void on_event(const sim::SimModel&, const sim::SimState&, const body::Event& e) override {
      events.push_back(e);
    }
  } log;
  sim::Stepper stepper(m, {{}, 0}, {{0, {0}, false}, {5, {2}, false}, {8, {0}, true}}, &log);
  EXPECT_TRUE(stepper.state().controller.legs[0].disabled);  // failed from the start
  stepper.steps(10);
  EXPECT_EQ(log.steps, 10);
  ASSERT_EQ(log.events.size(), 3u);
  EXPECT_EQ(log.events[1].kind, body::EventKind::fault);
  EXPECT_EQ(log.events[1].step, 5);
  EXPECT_EQ(log.events[2].kind, body::EventKind::recovery);
  EXPECT_EQ(log.events[2].step, 8);
  EXPECT_FALSE(stepper.state().controller.legs[0].disabled);
  EXPECT_TRUE(stepper.state().controller.legs[2].disabled);
}

TEST(Stepper, RestoredCheckpointContinuesIdentically) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  sim::Stepper stepper(m, {}, {{50, {1}, false}, {90, {1}, true}});
  stepper.steps(40);
  const sim::StepperCheckpoint saved = stepper.checkpoint();
  const auto walk_on = [&] {
    stepper.steps(30);
    stepper.apply_now({0, {4}, false});  // L2, now
    stepper.steps(40);
    return stepper.pose();
  };
  const body::Pose2 first = walk_on();
  stepper.restore(saved);
  EXPECT_EQ(stepper.step_count(), 40);
  EXPECT_FALSE(stepper.faults().failed(4));
  const body::Pose2 second = walk_on();
  EXPECT_EQ(first.x, second.x);
  EXPECT_EQ(first.y, second.y);
  EXPECT_EQ(first.yaw_deg, second.yaw_deg);
  EXPECT_EQ(stepper.step_count(), 110);
  EXPECT_FALSE(stepper.faults().failed(1));  // the scheduled recovery came after the restore too
}

TEST(Stepper, LegsFailAndRecoverNowOrSayWhyNot) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  sim::Stepper stepper(m, {{}, 0}, {{0, {0}, false}});
  EXPECT_THROW(stepper.apply_now({0, {0}, false}), BadInput);              // already failed
  EXPECT_THROW(stepper.apply_now({0, {1}, true}), BadInput);               // has not failed
  EXPECT_THROW(stepper.apply_now({0, {1, 2, 3, 4, 5}, false}), BadInput);  // every leg
  stepper.apply_now({0, {0}, true});
  EXPECT_FALSE(stepper.state().controller.legs[0].disabled);
  EXPECT_FALSE(stepper.faults().failed(0));
}

TEST(Walk, WindowDeviationsWrapAndSign) {
  // A left turn across +-180 deg is +20, not -340 (docs/learning.md "Deviation").
  const std::vector<double> yaw{170.0, 0.0, -170.0, 0.0, -150.0};
  EXPECT_EQ(sim::window_deviations(yaw, 0, 2), (std::vector<double>{20.0, 20.0}));
  EXPECT_EQ(sim::window_deviations(yaw, 1, 2), (std::vector<double>{0.0}));
  EXPECT_DOUBLE_EQ(wrap_degrees(540.0), 180.0);
  EXPECT_DOUBLE_EQ(wrap_degrees(-180.0), 180.0);
}

// A robot walking along +x with its body turned 10 deg left (a compensated crab): against its
// heading the path is 10 deg to the right; against its course line (+x) it is straight.
TEST(Walk, PathAngleAgainstTheHeadingOrTheCourse) {
  const body::Pose2 start{0.0, 0.0, 10.0};
  const body::Pose2 end{0.5, 0.0, 10.0};
  const body::WindowMeasure heading = body::measure_window(start, end);
  EXPECT_NEAR(heading.path_deg, -10.0, 1e-9);
  EXPECT_NEAR(heading.yaw_deg, 0.0, 1e-12);
  const body::WindowMeasure course = body::measure_window(start, end, 0.0);
  EXPECT_NEAR(course.path_deg, 0.0, 1e-12);
  EXPECT_NEAR(course.forward_m, 0.5, 1e-12);
  // Drifting off the line shows against the course whatever the heading.
  EXPECT_NEAR(body::measure_window(start, {0.5, -0.5, 10.0}, 0.0).path_deg, -45.0, 1e-9);
}

TEST(Physics, NanStateStopsTheRunNamingTheStep) {
  const sim::SimModel& m = model(RobotKind::hexapod);
  sim::SimState state = sim::make_sim_state(m);
  for (int i = 0; i < 3; ++i) sim::sim_step(m, state);
  state.data->qvel[0] = std::numeric_limits<double>::quiet_NaN();
  try {
    sim::sim_step(m, state);
    FAIL() << "no error";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find("unstable at step 3"), std::string::npos) << e.what();
  }
}

TEST(Physics, TooLongPhysicsStepBlowsUpWithAnError) {
  sim::SimOptions options;
  options.physics_dt = options.control_dt;  // 37 ms: far beyond what the contacts tolerate
  const sim::SimModel m = sim::make_sim_model(RobotKind::hexapod, options);
  sim::WalkSpec spec;
  spec.steps = 100;
  try {
    sim::walk(m, spec);
    FAIL() << "no error";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find("physics became unstable at step"), std::string::npos);
  }
}

}  // namespace
