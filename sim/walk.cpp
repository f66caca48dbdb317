#include "sim/walk.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.h"

namespace multicpg::sim {
namespace {

void check_spec(const SimModel& model, const WalkSpec& spec) {
  const std::size_t legs = model.legs.size();
  const auto check_count = [](long value, const char* flag, long min) {
    if (value < min || value > kMaxSteps) {
      throw BadInput(std::string(flag) + " must be in " + std::to_string(min) + ".." +
                     std::to_string(kMaxSteps) + ", got " + std::to_string(value));
    }
  };
  check_count(spec.steps, "--steps", 1);
  check_count(spec.settle, "--settle", 0);
  check_count(spec.controller_warmup, "--warmup", 0);
  if (spec.window <= 0) {
    throw BadInput("--window must be positive, got " + std::to_string(spec.window));
  }
  if (!spec.periods.empty() && spec.periods.size() != legs) {
    throw BadInput("expected " + std::to_string(legs) + " periods, got " +
                   std::to_string(spec.periods.size()));
  }
  for (std::size_t leg : spec.disabled) {
    if (leg >= legs) throw BadInput("leg index " + std::to_string(leg) + " out of range");
  }
  std::vector<std::size_t> unique = spec.disabled;
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  if (unique.size() == legs) {
    throw BadInput("cannot disable every leg of the " + model.controller.morphology.name);
  }
  const long total = spec.settle + spec.steps;
  if (!spec.disabled.empty() && (spec.disable_at < 0 || spec.disable_at >= total)) {
    throw BadInput("--disable-at must be in 0.." + std::to_string(total - 1) + ", got " +
                   std::to_string(spec.disable_at));
  }
}

}  // namespace

SimState start_walk_state(const SimModel& model, const std::vector<int>& periods) {
  if (periods.empty()) return make_sim_state(model);
  const bool equal =
      std::all_of(periods.begin(), periods.end(), [&](int p) { return p == periods.front(); });
  SimState state = make_sim_state(model, periods.front());
  if (!equal) {
    neural::set_periods(model.controller, state.controller, periods);
    neural::set_synchronised(state.controller, false);
  }
  return state;
}

void warm_up_controller(const SimModel& model, SimState& state, long steps) {
  for (long t = 0; t < steps; ++t) neural::controller_step(model.controller, state.controller);
}

void append_record(const SimModel& model, const SimState& state, bool joints, WalkRecord& r) {
  const Position p = trunk_position(model, state);
  r.time.push_back(state.data->time);
  r.x.push_back(p.x);
  r.y.push_back(p.y);
  r.z.push_back(p.z);
  r.yaw_deg.push_back(trunk_yaw_deg(model, state));
  if (!joints) return;
  for (std::size_t leg = 0; leg < r.legs; ++leg) {
    const neural::MotorCommands& m = state.controller.legs[leg].command;
    r.command.insert(r.command.end(), {m.tc, m.ctr, m.fti});
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      r.target.push_back(state.targets[leg][j]);
      r.actual.push_back(joint_angle(model, state, leg, robot::kJoints[j]));
    }
    r.contact.push_back(foot_contact(model, state, leg) ? 1 : 0);
  }
}

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
  SimState state = start_walk_state(model, spec.periods);
  warm_up_controller(model, state, spec.controller_warmup);
  WalkResult result;
  WalkRecord& r = result.record;
  r.legs = model.legs.size();
  const long total = spec.settle + spec.steps;
  const auto rows = static_cast<std::size_t>(total) + 1;
  for (auto* v : {&r.time, &r.x, &r.y, &r.z, &r.yaw_deg}) v->reserve(rows);
  if (spec.record) {
    r.command.reserve(rows * r.legs * robot::kJointsPerLeg);
    r.target.reserve(rows * r.legs * robot::kJointsPerLeg);
    r.actual.reserve(rows * r.legs * robot::kJointsPerLeg);
    r.contact.reserve(rows * r.legs);
  }
  append_record(model, state, spec.record, r);
  for (long step = 0; step < total; ++step) {
    if (step == spec.disable_at) {
      for (std::size_t leg : spec.disabled) neural::set_disabled(state.controller, leg, true);
    }
    sim_step(model, state);
    append_record(model, state, spec.record, r);
    if (spec.on_step) spec.on_step(state);
  }

  const auto first = static_cast<std::size_t>(spec.settle);
  result.duration_s = static_cast<double>(spec.steps) * model.control_dt;
  const double dx = r.x.back() - r.x[first];
  const double dy = r.y.back() - r.y[first];
  const double heading = r.yaw_deg[first] * std::numbers::pi / 180.0;
  result.distance_m = std::hypot(dx, dy);
  result.forward_m = dx * std::cos(heading) + dy * std::sin(heading);
  result.lateral_m = -dx * std::sin(heading) + dy * std::cos(heading);
  result.speed_m_s = result.distance_m / result.duration_s;
  result.window_deviations_deg = window_deviations(r.yaw_deg, first, spec.window);
  result.final_yaw_deg = r.yaw_deg.back();
  return result;
}

}  // namespace multicpg::sim
