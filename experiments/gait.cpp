#include "experiments/gait.h"

#include "common/interrupt.h"

namespace multicpg::experiments {

GaitRecord record_gait(const neural::ControllerModel& model, neural::ControllerState& state,
                       long warmup, long steps) {
  for (long t = 0; t < warmup; ++t) {
    check_interrupted();
    neural::controller_step(model, state);
  }
  GaitRecord record;
  record.swing.reserve(steps);
  record.motor.reserve(steps);
  for (long t = 0; t < steps; ++t) {
    check_interrupted();
    neural::controller_step(model, state);
    std::vector<bool> swing;
    std::vector<std::array<double, 3>> motor;
    for (const neural::LegState& leg : state.legs) {
      swing.push_back(!leg.disabled && leg.delayed.swing);
      motor.push_back({leg.command.tc, leg.command.ctr, leg.command.fti});
    }
    record.swing.push_back(std::move(swing));
    record.motor.push_back(std::move(motor));
  }
  return record;
}

std::vector<double> swing_fractions(const GaitRecord& record) {
  if (record.swing.empty()) return {};
  std::vector<double> out(record.swing.front().size(), 0.0);
  for (const auto& row : record.swing) {
    for (std::size_t i = 0; i < row.size(); ++i) out[i] += row[i] ? 1.0 : 0.0;
  }
  for (double& f : out) f /= static_cast<double>(record.swing.size());
  return out;
}

}  // namespace multicpg::experiments
