#include "sim/walk.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.h"
#include "common/limits.h"
#include "sim/fault_effects.h"

namespace multicpg::sim {
namespace {

// Named by the spec's keys (OptionError): the CLI and Python name their flags and arguments.
void check_spec(const SimModel& model, const WalkSpec& spec) {
  require_in("start.warmup", spec.start.warmup, body::kStepLimits);
  if (!spec.start.periods.empty() && spec.start.periods.size() != model.legs.size()) {
    throw OptionError("start.periods", "expected " + std::to_string(model.legs.size()) +
                                           " periods, got " +
                                           std::to_string(spec.start.periods.size()));
  }
  try {
    validate(model.controller.morphology, spec.faults);
  } catch (const OptionError&) {
    throw;
  } catch (const BadInput& e) {
    throw OptionError("faults", e.what());
  }
  body::validate_walk(spec.faults, spec.settle, spec.steps, spec.window);
}

// Trunk poses at the rows a walk's measures need (rows settle, settle + window, ... and the
// last), taken as the steps come: what measure_walk reads from a full record, in memory that
// grows by one pose per window instead of one row per step.
class WindowPoses final : public Observer {
 public:
  WindowPoses(long settle, long window) : settle_(settle), window_(window) {}
  void on_start(const SimModel& model, const SimState& state) override { take(model, state); }
  void on_step(const SimModel& model, const SimState& state) override { take(model, state); }

  std::vector<body::Pose2> boundaries;  // rows settle + k * window
  body::Pose2 last;                     // the last row

 private:
  void take(const SimModel& model, const SimState& state) {
    const Position p = trunk_position(model, state);
    last = {p.x, p.y, sensed_yaw_deg(model, state)};
    if (row_ >= settle_ && (row_ - settle_) % window_ == 0) boundaries.push_back(last);
    ++row_;
  }

  long settle_;
  long window_;
  long row_ = 0;
};

// The measures of a walk of `steps` measured steps from its window boundary poses and its last.
void measure_poses(const SimModel& model, long steps, const std::vector<body::Pose2>& boundaries,
                   const body::Pose2& last, WalkResult& result) {
  result.duration_s = static_cast<double>(steps) * model.control_dt;
  body::WalkMeasure m = body::measure_walk(boundaries, last);
  result.distance_m = m.distance_m;
  result.forward_m = m.forward_m;
  result.lateral_m = m.lateral_m;
  result.speed_m_s = result.distance_m / result.duration_s;
  result.window_deviations_deg = std::move(m.window_deviations_deg);
  result.windows = std::move(m.windows);
  result.final_yaw_deg = m.final_yaw_deg;
}

}  // namespace

std::vector<double> window_deviations(const std::vector<double>& yaw_deg, std::size_t first,
                                      long window) {
  std::vector<double> out;
  const auto w = static_cast<std::size_t>(window);
  for (std::size_t end = first + w; end < yaw_deg.size(); end += w) {
    out.push_back(wrap_degrees(yaw_deg[end] - yaw_deg[end - w]));
  }
  return out;
}

WalkResult walk(const SimModel& model, const WalkSpec& spec) {
  check_spec(model, spec);
  WalkResult result;
  WalkRecord& r = result.record;
  const long total = spec.settle + spec.steps;
  if (!spec.keep_record) {
    WindowPoses poses(spec.settle, spec.window);
    Observers observers({&poses, spec.observer});
    Stepper stepper(model, spec.start, spec.faults, &observers);
    stepper.steps(total);
    measure_poses(model, spec.steps, poses.boundaries, poses.last, result);
    result.final_state = std::move(stepper.state());
    return result;
  }
  const auto rows = static_cast<std::size_t>(total) + 1;
  for (auto* v : {&r.time, &r.x, &r.y, &r.z, &r.yaw_deg, &r.sensed_yaw_deg}) v->reserve(rows);
  if (spec.record) {
    const std::size_t legs = model.legs.size();
    r.command.reserve(rows * legs * robot::kJointsPerLeg);
    r.target.reserve(rows * legs * robot::kJointsPerLeg);
    r.actual.reserve(rows * legs * robot::kJointsPerLeg);
    r.contact.reserve(rows * legs);
  }
  Stepper stepper(model, spec.start, spec.faults, spec.observer, &r, spec.record);
  stepper.steps(total);
  measure_walk(model, spec.settle, spec.steps, spec.window, result);
  result.final_state = std::move(stepper.state());
  return result;
}

void measure_walk(const SimModel& model, long settle, long steps, long window, WalkResult& result) {
  const WalkRecord& r = result.record;
  std::vector<body::Pose2> boundaries;
  const auto w = static_cast<std::size_t>(window);
  for (auto row = static_cast<std::size_t>(settle); row < r.rows(); row += w) {
    boundaries.push_back({r.x[row], r.y[row], r.sensed_yaw_deg[row]});
  }
  measure_poses(model, steps, boundaries, {r.x.back(), r.y.back(), r.sensed_yaw_deg.back()},
                result);
}

}  // namespace multicpg::sim
