#include "sim/walk_record.h"

#include "sim/fault_effects.h"

namespace multicpg::sim {

void append_record(const SimModel& model, const SimState& state, bool joints, WalkRecord& r) {
  const Position p = trunk_position(model, state);
  r.time.push_back(state.data->time);
  r.x.push_back(p.x);
  r.y.push_back(p.y);
  r.z.push_back(p.z);
  r.yaw_deg.push_back(trunk_yaw_deg(model, state));
  r.sensed_yaw_deg.push_back(sensed_yaw_deg(model, state));
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

}  // namespace multicpg::sim
