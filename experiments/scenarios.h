// The malfunction scenarios the paper reports (paper Fig. 11, 13, 14; docs/learning.md "The paper's
// experiments").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::experiments {

// A set of disabled legs, named "R1+R3+L2" (legs in morphology order, R side first).
struct Scenario {
  std::string name;
  std::vector<std::size_t> disabled;  // sorted leg indices
};

inline constexpr int kScenarioRuns = 10;  // runs per scenario, paper Fig. 11 and 13
inline constexpr int kBetaRuns = 50;      // runs per beta, paper Fig. 14
// Beta study (paper Fig. 14): 0 = random search, 10 ~ greedy.
inline const std::vector<double> kBetaStudyValues{0.0, 0.1, 0.3, 0.5, 1.0, 5.0, 10.0};

// The legs' left-right mirror images (R1 <-> L1, ...), sorted.
std::vector<std::size_t> mirror(const robot::Morphology& morph,
                                const std::vector<std::size_t>& legs);
// Periods per leg (morphology order) with each leg's period moved to its mirror image.
std::vector<int> mirror_periods(const robot::Morphology& morph, const std::vector<int>& periods);

// Every set of 1..max_disabled legs up to left-right mirror, without a whole disabled side.
// Single legs are all listed (the paper's six one-leg rows); a larger set and its mirror image
// appear once, as the one with more right legs, ties going to the smaller leg indices (the
// paper's R1+R3, R1+R3+L2, R1+L2). Ordered by size, then by leg indices.
std::vector<Scenario> mirror_scenarios(const robot::Morphology& morph, std::size_t max_disabled);

// Every set of 1..max_disabled legs without a whole disabled side, mirror images apart (a robot
// file's robot need not be symmetric). Ordered by size, then by leg indices.
std::vector<Scenario> leg_loss_scenarios(const robot::Morphology& morph, std::size_t max_disabled);

// Hexapod: mirror_scenarios(hexapod, 3) = 6 + 9 + 9 = 24. Quadruped: R1, R2, L1, L2 (Fig. 13).
// Throws BadInput for the octopod, for which the paper reports none.
std::vector<Scenario> paper_scenarios(robot::RobotKind kind);

// Beta study (Fig. 14): the hexapod with R1 and R2 disabled.
Scenario beta_study_scenario();

// Shortest text that reads back as the same double: "0.1", "10".
std::string format_number(double value);

}  // namespace multicpg::experiments
