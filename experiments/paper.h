// What the paper (Ren et al. 2015) states in numbers, in one typed place: the report's captions
// (report/stages) and docs/results.md (results_page.cpp) read these, never retype them.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>

namespace multicpg::experiments::paper {

// One controller step of the paper's robot: 27 Hz (paper §4).
inline constexpr double kStepSeconds = 0.037;
// The deviation threshold E_req in degrees (§4.1, docs/learning.md "Deviation").
inline constexpr double kThresholdDeg = 8.0;
// §4.1: "the learning time for most of the scenarios can be normally controlled within 20
// trials".
inline constexpr int kMostTrials = 20;

// §4.1, Fig. 8: R1 disabled, all periods 4, then learning.
inline constexpr double kR1InitialDeg = 37.86;  // after the first 400 steps
inline constexpr double kR1Trial1Deg = 21.46;   // trial 1, L1 = 5: kept
inline constexpr double kR1Trial2Deg = 64.12;   // trial 2, R3 = 9: rejected
inline constexpr double kR1Trial2Acceptance = 5.45e-10;
inline constexpr double kR1FinalDeg = 0.25;
inline constexpr int kR1Trials = 7;

// A working leg's learned period, e.g. {"R2", 5}.
struct LegPeriod {
  std::string_view leg;
  int period;
};

// §5, Table 1 and docs/learning.md "Learned periods of the authors' code": the tunnel runs on the
// real robot with the combinations the paper learned; deviation before (all periods 4) and after
// learning.
struct TunnelResult {
  std::string_view disabled;  // "R1+R3", legs in morphology order
  std::span<const LegPeriod> learned;
  double before_deg;
  double after_deg;
};
inline constexpr LegPeriod kLearnedR1[]{{"R2", 5}, {"R3", 4}, {"L1", 5}, {"L2", 6}, {"L3", 5}};
inline constexpr LegPeriod kLearnedR1R3[]{{"R2", 4}, {"L1", 6}, {"L2", 4}, {"L3", 9}};
inline constexpr LegPeriod kLearnedR1R3L2[]{{"R2", 4}, {"L1", 4}, {"L3", 9}};
inline constexpr std::array<TunnelResult, 3> kTunnel{{{"R1", kLearnedR1, 42.0, 7.97},
                                                      {"R1+R3", kLearnedR1R3, 21.0, 0.95},
                                                      {"R1+R3+L2", kLearnedR1R3L2, 23.0, 2.67}}};

// §5: "the robot deviated to the right and hit the right board in all three experiments". Our
// deviations count + = left, so the real robot's before-learning angles are these, negated.
inline constexpr double signed_before_deg(const TunnelResult& result) {
  return -result.before_deg;
}
// Table 1 does not say to which side the learned periods erred; the text gives distances only.

// §4.1: the deviation the paper's simulator shows with R1 disabled, all periods 4, per 400 steps.
inline constexpr double kR1SimulatorDeg = 38.0;

// "R2=5 R3=4 L1=5 L2=6 L3=5", as experiments::working_periods_text writes a combination.
inline std::string combination_text(std::span<const LegPeriod> learned) {
  std::string out;
  for (const LegPeriod& p : learned) {
    if (!out.empty()) out += ' ';
    out += p.leg;
    out += '=';
    out += std::to_string(p.period);
  }
  return out;
}

}  // namespace multicpg::experiments::paper
