// Gaits of the neural controller alone (paper Fig. 2, Fig. 9): per-step swing/stance and
// motor commands of every leg, equal periods, all clients synchronised.
#pragma once

#include <array>
#include <vector>

#include "neural/controller.h"

namespace multicpg::experiments {

struct GaitRecord {
  std::vector<std::vector<bool>> swing;                   // [step][leg]
  std::vector<std::vector<std::array<double, 3>>> motor;  // [step][leg] = TC, CTr, FTi (m)
};

// Steps a fresh controller needs before the gait shows: the slowest CPG lock from reset
// (p = 4, about 740 steps, docs/controller.md "Steps to lock, from reset") plus the longest delay
// line.
inline constexpr long kDefaultGaitWarmup = 1000;

// Runs `warmup` steps unrecorded, then records `steps` steps.
GaitRecord record_gait(const neural::ControllerModel& model, neural::ControllerState& state,
                       long warmup, long steps);

// Fraction of steps each leg swings.
std::vector<double> swing_fractions(const GaitRecord& record);

}  // namespace multicpg::experiments
