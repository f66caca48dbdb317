// Online malfunction compensation (paper §3-§4, SPEC §5-§6): the robot walks on without resets,
// legs fail, a deviating 400-step window desynchronises the CPGs and starts the annealing of
// learning/annealing.h, each trial walking the candidate periods for one window.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "learning/annealing.h"
#include "neural/controller.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// What compensation needs of a walking robot. The MuJoCo simulation implements it through an
// adapter; tests use a fake whose yaw follows the current periods.
class Walker {
 public:
  virtual ~Walker() = default;
  // One controller step and the physics it drives.
  virtual void step() = 0;
  // Trunk yaw in degrees, (-180, 180] (SPEC §6).
  virtual double yaw_deg() const = 0;
  // Controller steps taken so far.
  virtual long step_count() const = 0;
  virtual neural::ControllerState& controller() = 0;
  virtual const neural::ControllerModel& controller_model() const = 0;
  // Legs fail from the next step on: they hold the disabled posture (SPEC §4).
  virtual void disable(const std::vector<std::size_t>& legs) = 0;
};

inline constexpr long kDefaultWindowSteps = 400;  // paper §3 step 2
// Windows walked after the failure without a deviation above the threshold before the run
// ends "no deviation": 5 windows = 2000 steps, 74 s at 27 Hz.
inline constexpr long kDefaultDetectionWindows = 5;
// Steps a leg's CPG needs from a reset to its locked orbit, slowest learnable period p = 9
// (measured with neural/: 211 steps; p = 5, 6, 8 need 46, 67, 87). p = 4 locks exactly only
// after about 740 steps, but its swing pattern is right from the first cycle except for a few
// isolated steps (18 of 540 after step 200), so it does not set the settle time.
inline constexpr long kSlowestLockSteps = 211;

// Steps walked unmeasured after a period change: the slowest CPG lock plus the longest delay
// line, whose contents still come from before the change (SPEC §3). Hexapod 211 + 126 = 337,
// quadruped 211 + 108 = 319, octopod 211 + 144 = 355.
long default_settle_steps(const neural::ControllerModel& model);

// Steps after a reset of every CPG to `periods` until no window can see a transient: the
// slowest of these periods to lock exactly (neural::lock_steps; 737 for p = 4) plus the longest
// delay line, so the joints carry only locked signals. Hexapod with a leg at 4: 737 + 126 = 863.
long locked_settle_steps(const neural::ControllerModel& model, const Periods& periods);

// How a compensation run is made.
struct CompensationOptions {
  AnnealingParams annealing;
  std::vector<std::size_t> disabled;  // legs that fail
  long fail_step = 0;                 // steps after the run starts at which they fail
  long window_steps = kDefaultWindowSteps;
  // Unmeasured steps after every period change, and before the first detection window (the
  // run starts from a CPG reset too). Empty = default_settle_steps(model).
  std::optional<long> settle_steps;
  long detection_windows = kDefaultDetectionWindows;
  std::uint64_t seed = 0;
};

// Throws BadInput (one line, naming legs) for invalid annealing params, window < 1,
// settle < 0, fail step < 0, detection windows < 1, an unknown or repeated leg, or every leg
// disabled.
void validate(const CompensationOptions& options, const robot::Morphology& morph);

struct LearningResult {
  bool converged = false;
  std::string status;                // "converged", "not converged" or "no deviation"
  std::optional<StopReason> reason;  // why annealing stopped; empty when it never started
  int trials = 0;
  double initial_deviation_deg = 0.0;  // E of C0: the detecting window (or the last window)
  double final_deviation_deg = 0.0;    // E of the accepted combination when the run ended
  Periods periods;                     // the accepted combination, left on the controller
  std::vector<TrialRecord> trace;
  long steps_walked = 0;
  std::optional<long> detection_step;  // steps after the start when the deviation was seen
  long settle_steps = 0;               // as used
};

// Runs the whole online loop on `walker`, which should be walking forward with every leg
// working and every client synchronised (as make_controller_state leaves it).
LearningResult compensate(Walker& walker, const CompensationOptions& options);

// JSON with converged, status, reason, trials, initial/final_deviation_deg, periods
// (leg name -> period), disabled (names), steps_walked, detection_step (null if none),
// settle_steps and trace (trial, periods, deviation_deg, accepted, acceptance_probability,
// legs_changed, redraws, tabu_redraw).
nlohmann::json to_json(const LearningResult& result, const robot::Morphology& morph,
                       const std::vector<std::size_t>& disabled);

}  // namespace multicpg::learning
