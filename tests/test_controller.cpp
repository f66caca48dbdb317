// The multi-CPG controller: gaits from the delay lines, synchronisation, disabled legs
// (docs/controller.md §3-§5).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "common/errors.h"
#include "experiments/cpg_pair.h"
#include "experiments/gait.h"
#include "neural/controller.h"

namespace {

using namespace multicpg;
using robot::RobotKind;

long cycle_length(int p) {
  return static_cast<long>(p) * (2 * p + 1);
}

experiments::GaitRecord gait(RobotKind kind, int p, long cycles = 3) {
  const auto model = neural::make_controller_model(kind);
  auto state = neural::make_controller_state(model, p);
  return experiments::record_gait(model, state, experiments::kDefaultGaitWarmup,
                                  cycles * cycle_length(p));
}

std::vector<bool> column(const experiments::GaitRecord& r, std::size_t leg) {
  std::vector<bool> out;
  for (const auto& row : r.swing) out.push_back(row[leg]);
  return out;
}

// First step at which `leg` starts a swing.
long first_onset(const experiments::GaitRecord& r, std::size_t leg) {
  for (std::size_t t = 1; t < r.swing.size(); ++t) {
    if (r.swing[t][leg] && !r.swing[t - 1][leg]) return static_cast<long>(t);
  }
  return -1;
}

TEST(Gait, PeriodFourIsAnExactTripod) {
  const auto r = gait(RobotKind::hexapod, 4);
  const std::size_t R1 = 0, R2 = 1, R3 = 2, L1 = 3, L2 = 4, L3 = 5;
  EXPECT_EQ(column(r, R1), column(r, R3));
  EXPECT_EQ(column(r, R1), column(r, L2));
  EXPECT_EQ(column(r, R2), column(r, L1));
  EXPECT_EQ(column(r, R2), column(r, L3));
  // Antiphase: the second tripod is the first shifted by half a cycle (18 steps).
  const long half = cycle_length(4) / 2;
  const auto a = column(r, R1);
  const auto b = column(r, R2);
  for (std::size_t t = half; t < a.size(); ++t) EXPECT_EQ(a[t], b[t - half]) << "step " << t;
  for (std::size_t t = 0; t < a.size(); ++t) EXPECT_FALSE(a[t] && b[t]) << "step " << t;
}

TEST(Gait, QuadrupedPeriodFourIsATrot) {
  const auto r = gait(RobotKind::quadruped, 4);
  const std::size_t R1 = 0, R2 = 1, L1 = 2, L2 = 3;
  EXPECT_EQ(column(r, R1), column(r, L2));  // diagonal pairs swing together
  EXPECT_EQ(column(r, R2), column(r, L1));
  const long half = cycle_length(4) / 2;
  const auto a = column(r, R1);
  const auto b = column(r, R2);
  for (std::size_t t = half; t < a.size(); ++t) EXPECT_EQ(a[t], b[t - half]) << "step " << t;
}

TEST(Gait, SwingOnsetsMatchReferenceTable) {
  // docs/controller.md "Gaits": swing onsets as fractions of the cycle after R3 (tau = 18, tau_L =
  // 90).
  const std::map<int, std::vector<double>> onsets{{5, {0.655, 0.327, 0.0, 0.291, 0.964, 0.636}},
                                                  {6, {0.462, 0.231, 0.0, 0.615, 0.385, 0.154}},
                                                  {8, {0.265, 0.132, 0.0, 0.926, 0.794, 0.662}},
                                                  {9, {0.211, 0.105, 0.0, 0.737, 0.632, 0.526}}};
  for (const auto& [p, expected] : onsets) {
    const auto r = gait(RobotKind::hexapod, p);
    const long T = cycle_length(p);
    const long r3 = first_onset(r, 2);
    for (std::size_t leg = 0; leg < expected.size(); ++leg) {
      const long lag = ((first_onset(r, leg) - r3) % T + T) % T;
      EXPECT_NEAR(static_cast<double>(lag) / T, expected[leg], 1.0 / T)
          << "period " << p << " leg " << leg;
    }
  }
}

TEST(Gait, EveryLegSwingsOnePthOfTheCycle) {
  for (RobotKind kind : {RobotKind::quadruped, RobotKind::hexapod, RobotKind::octopod}) {
    for (int p : {4, 5, 6, 8, 9}) {
      for (double f : experiments::swing_fractions(gait(kind, p, 2))) {
        EXPECT_DOUBLE_EQ(f, 1.0 / p) << robot::to_string(kind) << " period " << p;
      }
    }
  }
}

TEST(Gait, PeriodOneHoldsEveryJointConstant) {
  const auto r = gait(RobotKind::hexapod, 1, 100);
  for (const auto& row : r.motor) EXPECT_EQ(row, r.motor.front());
  for (const auto& row : r.swing) {
    for (bool s : row) EXPECT_FALSE(s);
  }
}

TEST(Sync, SynchronisedClientsEqualTheMasterBitForBit) {
  const auto model = neural::make_controller_model(RobotKind::hexapod);
  auto state = neural::make_controller_state(model, 5);
  for (int t = 0; t < 3000; ++t) {
    neural::controller_step(model, state);
    const auto& master = state.legs[0];
    for (std::size_t i = 1; i < state.legs.size(); ++i) {
      const auto& c = state.legs[i];
      ASSERT_EQ(c.cpg.x1, master.cpg.x1) << "step " << t;
      ASSERT_EQ(c.post.y1, master.post.y1) << "step " << t;
      ASSERT_EQ(c.post.y2, master.post.y2) << "step " << t;
      ASSERT_EQ(c.psn.output(), master.psn.output()) << "step " << t;
      // Motor neurons before the per-leg delays (input0 = 0, so TC has no front/hind sign).
      ASSERT_EQ(c.pre.tc, master.pre.tc) << "step " << t;
      ASSERT_EQ(c.pre.ctr, master.pre.ctr) << "step " << t;
      // x2 is not coupled by Eq. 5: it differs only by the master's own (vanishing) control.
      if (t > 2500) {
        ASSERT_NEAR(c.cpg.x2, master.cpg.x2, 1e-9) << "step " << t;
      }
    }
  }
}

TEST(Sync, DesynchronisedClientKeepsItsOwnOrbitAndResyncBringsItBack) {
  const auto model = neural::make_controller_model(RobotKind::hexapod);
  auto state = neural::make_controller_state(model, 5);
  neural::set_synchronised(state, false);
  std::vector<int> periods(model.size(), 5);
  periods[1] = 6;  // R2 is the client under test
  neural::set_periods(model, state, periods);
  std::vector<double> master, client;
  for (int t = 0; t < 3000; ++t) {
    neural::controller_step(model, state);
    master.push_back(state.legs[0].cpg.x1);
    client.push_back(state.legs[1].cpg.x1);
  }
  EXPECT_EQ(experiments::orbit_period(master, neural::kMaxPeriod, 200), 5);
  EXPECT_EQ(experiments::orbit_period(client, neural::kMaxPeriod, 200), 6);

  // Re-synchronise mid-run: x1 follows at once, the post-processed output within a few windows.
  neural::set_synchronised(state, true);
  const long few_windows = 3 * cycle_length(5);
  long identical_from = -1;
  for (long t = 0; t < few_windows + 200; ++t) {
    neural::controller_step(model, state);
    ASSERT_EQ(state.legs[1].cpg.x1, state.legs[0].cpg.x1);
    const bool same = state.legs[1].post.y1 == state.legs[0].post.y1 &&
                      state.legs[1].post.y2 == state.legs[0].post.y2;
    if (!same) identical_from = -1;
    if (same && identical_from < 0) identical_from = t;
  }
  ASSERT_GE(identical_from, 0);
  EXPECT_LE(identical_from, few_windows);
}

TEST(Sync, CpgPairMasterFiveClientSixOutOfSync) {
  experiments::CpgPairOptions o;
  o.master_period = 5;
  o.client_period = 6;
  o.synchronised = false;
  o.steps = 3000;
  const auto samples = experiments::run_cpg_pair(neural::CpgParams{}, o);
  std::vector<double> m, c;
  for (const auto& s : samples) {
    m.push_back(s.master_x1);
    c.push_back(s.client_x1);
  }
  EXPECT_EQ(experiments::orbit_period(m, neural::kMaxPeriod, 200), 5);
  EXPECT_EQ(experiments::orbit_period(c, neural::kMaxPeriod, 200), 6);
  o.synchronised = true;
  for (const auto& s : experiments::run_cpg_pair(neural::CpgParams{}, o)) {
    ASSERT_EQ(s.client_x1, s.master_x1);
  }
}

TEST(Disabled, LegHoldsItsPostureFromTheStepItIsDisabled) {
  const auto model = neural::make_controller_model(RobotKind::hexapod);
  auto state = neural::make_controller_state(model, 4);
  constexpr long kDisableAt = 500;
  for (long t = 0; t < kDisableAt; ++t) neural::controller_step(model, state);
  neural::set_disabled(state, 1, true);
  for (long t = 0; t < 500; ++t) {
    neural::controller_step(model, state);
    const auto& cmd = state.legs[1].command;
    ASSERT_EQ(cmd.tc, robot::kReferenceDisabledPosture.tc);
    ASSERT_EQ(cmd.ctr, robot::kReferenceDisabledPosture.ctr);
    ASSERT_EQ(cmd.fti, robot::kReferenceDisabledPosture.fti);
  }
  // The other legs keep walking.
  double lo = 1.0, hi = -1.0;
  for (long t = 0; t < 100; ++t) {
    neural::controller_step(model, state);
    lo = std::min(lo, state.legs[0].command.tc);
    hi = std::max(hi, state.legs[0].command.tc);
  }
  EXPECT_GT(hi - lo, 0.3);
}

// The body's postures (robot/body_params.h): every disabled leg holds the all-legs posture but a
// leg with its own; the body lift shifts the CTr and FTi windows (docs/robots.md Joint angles) by
// degrees.
TEST(Disabled, EachLegHoldsItsBodysPostureAndTheLiftShiftsTheWindows) {
  robot::BodyParams body;
  body.disabled_posture = {0.1, 0.9, -0.5};
  body.leg_postures = {{"R3", std::nullopt, std::nullopt, -0.55}};
  body.lift_body = 5.0;
  const auto model = neural::make_controller_model(RobotKind::hexapod, {}, body);
  auto state = neural::make_controller_state(model, 4);
  neural::set_disabled(state, 0, true);  // R1
  neural::set_disabled(state, 2, true);  // R3
  neural::controller_step(model, state);
  EXPECT_EQ(state.legs[0].command.ctr, 0.9);
  EXPECT_EQ(state.legs[0].command.fti, -0.5);
  EXPECT_EQ(state.legs[2].command.tc, 0.1);
  EXPECT_EQ(state.legs[2].command.ctr, 0.9);
  EXPECT_EQ(state.legs[2].command.fti, -0.55);
  const auto plain = neural::make_controller_model(RobotKind::hexapod);
  for (std::size_t i = 0; i < model.size(); ++i) {
    EXPECT_NEAR(model.legs[i].map.ctr.to_lo, plain.legs[i].map.ctr.to_lo - 5.0 / 75.0, 1e-12);
    EXPECT_NEAR(model.legs[i].map.ctr.to_hi, plain.legs[i].map.ctr.to_hi - 5.0 / 75.0, 1e-12);
    EXPECT_NEAR(model.legs[i].map.fti.to_lo, plain.legs[i].map.fti.to_lo + 5.0 / 55.0, 1e-12);
    EXPECT_EQ(model.legs[i].map.tc.to_lo, plain.legs[i].map.tc.to_lo);
  }
  body.leg_postures = {{"R4", 0.0, std::nullopt, std::nullopt}};
  try {
    neural::make_controller_model(RobotKind::hexapod, {}, body);
    ADD_FAILURE() << "a posture for a leg the hexapod does not have was taken";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "leg_postures[0].leg");
  }
}

TEST(Controller, SameInputsGiveIdenticalCommands) {
  const auto model = neural::make_controller_model(RobotKind::octopod);
  auto a = neural::make_controller_state(model, 6);
  auto b = a;
  for (int t = 0; t < 1000; ++t) {
    neural::controller_step(model, a);
    neural::controller_step(model, b);
    for (std::size_t i = 0; i < model.size(); ++i) {
      ASSERT_EQ(a.legs[i].command.tc, b.legs[i].command.tc);
      ASSERT_EQ(a.legs[i].command.fti, b.legs[i].command.fti);
    }
  }
}

TEST(Controller, CommandsStayInTheirWindows) {
  const auto model = neural::make_controller_model(RobotKind::hexapod);
  auto state = neural::make_controller_state(model, 4);
  // The PSN starts from zero outputs; its first steps overshoot the steady range (the servo
  // clips them) and reach each leg through its delay line, so the windows hold from then on.
  constexpr int kStartup = 5;
  int longest_delay = 0;
  for (const auto& leg : model.legs) longest_delay = std::max(longest_delay, leg.delay);
  for (int t = 0; t < 2000; ++t) {
    neural::controller_step(model, state);
    if (t < kStartup + longest_delay) continue;
    for (const auto& leg : state.legs) {
      EXPECT_GE(leg.command.ctr, 0.5985 - 1e-9);  // CTr 45..75 deg (docs/controller.md)
      EXPECT_LE(leg.command.ctr, 0.9975 + 1e-9);
      EXPECT_GE(leg.command.fti, -1.0024 - 1e-9);
      EXPECT_LE(leg.command.fti, -0.8204 + 1e-9);
    }
  }
}

}  // namespace
