#include "body/start.h"

#include <algorithm>
#include <string>

#include "common/errors.h"
#include "common/interrupt.h"

namespace multicpg::body {

neural::ControllerState start_controller(const neural::ControllerModel& model,
                                         const std::vector<int>& periods) {
  // No periods: the controller's own start (every leg at the tripod's 4, paper Table 2's C0).
  neural::ControllerState state = periods.empty()
                                      ? neural::make_controller_state(model)
                                      : neural::make_controller_state(model, periods.front());
  if (std::any_of(periods.begin(), periods.end(), [&](int p) { return p != periods.front(); })) {
    neural::set_periods(model, state, periods);
    neural::set_synchronised(state, false);
  }
  return state;
}

void warm_up_controller(const neural::ControllerModel& model, neural::ControllerState& state,
                        long steps) {
  for (long t = 0; t < steps; ++t) {
    check_interrupted();
    neural::controller_step(model, state);
  }
}

void validate_walk(const FaultTimeline& faults, long settle, long steps, long window) {
  require_in("steps", steps, kRunStepsLimits);
  require_in("window", window, kRunStepsLimits);
  require_in("settle", settle, kStepLimits);
  if (settle > kMaxSteps - steps) {
    throw OptionError(
        "steps", "settle and steps are more than " + std::to_string(kMaxSteps) + " steps in all");
  }
  const long total = settle + steps;
  for (const Fault& f : faults) {
    if (f.step >= total) {
      throw OptionError("faults", std::string(f.recover ? "a recovery" : "a fault") + " at step " +
                                      std::to_string(f.step) +
                                      " comes after the last step of the walk, " +
                                      std::to_string(total - 1));
    }
  }
}

}  // namespace multicpg::body
