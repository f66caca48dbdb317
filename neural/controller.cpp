#include "neural/controller.h"

#include <string>

#include "common/errors.h"
#include "common/limits.h"
#include "neural/json.h"

namespace multicpg::neural {
namespace {

using robot::LegType;
using robot::Side;

constexpr std::size_t kMaster = 0;  // R1 (paper §2.2)

void step_cpgs(const ControllerModel& model, ControllerState& state) {
  LegState& master = state.legs[kMaster];
  cpg_step(model.params.cpg, master.cpg);
  for (std::size_t i = 1; i < state.legs.size(); ++i) {
    LegState& leg = state.legs[i];
    cpg_step(model.params.cpg, leg.cpg, SyncInput{leg.alpha, master.cpg.x1});
  }
}

void step_postprocessing(const ControllerModel& model, ControllerState& state) {
  const LegState& master = state.legs[kMaster];
  const int master_period = master.cpg.period;
  bool master_window = false;
  for (std::size_t i = 0; i < state.legs.size(); ++i) {
    LegState& leg = state.legs[i];
    const bool window = advance_window(leg.post, leg.cpg.period);
    if (i == kMaster) master_window = window;
    // docs/controller.md "Synchronisation": a synchronised client's post-processing follows the
    // master: its period, window and CPG output. Eq. 5 already makes x1 equal; x2 is not coupled
    // and differs by the master's own control input, so reading the master's keeps the outputs
    // equal bit for bit.
    const bool follow = follows_master(state, i);
    const CpgState& source = follow ? master.cpg : leg.cpg;
    postprocessing_step(model.params.post, leg.post, source.x1, source.x2,
                        follow ? master_period : leg.cpg.period, follow ? master_window : window);
  }
}

void step_psns(const ControllerModel& model, ControllerState& state) {
  for (LegState& leg : state.legs) {
    psn_step(model.params.psn, leg.psn, leg.post.y1, leg.post.y2, state.drive);
  }
}

void step_vrns(const ControllerModel& model, ControllerState& state) {
  for (std::size_t i = 0; i < state.legs.size(); ++i) {
    LegState& leg = state.legs[i];
    const bool left = model.morphology.legs[i].side == Side::left;
    vrn_step(model.params.vrn, leg.vrn, leg.psn.output(),
             left ? state.drive.turn_left : state.drive.turn_right);
  }
}

void step_motor_neurons(const ControllerModel& model, ControllerState& state) {
  for (std::size_t i = 0; i < state.legs.size(); ++i) {
    LegState& leg = state.legs[i];
    leg.pre = motor_neurons(model.params.motor, leg.psn.output(), leg.vrn.v, model.legs[i].front,
                            state.drive);
  }
}

void step_delay_lines(const ControllerModel& model, ControllerState& state) {
  for (std::size_t i = 0; i < state.legs.size(); ++i) {
    LegState& leg = state.legs[i];
    leg.delayed = delay_step(leg.delay, leg.pre, model.legs[i].hind);
  }
}

void map_joint_commands(const ControllerModel& model, ControllerState& state) {
  for (std::size_t i = 0; i < state.legs.size(); ++i) {
    LegState& leg = state.legs[i];
    leg.command = leg.disabled ? model.legs[i].disabled : model.legs[i].map(leg.delayed.pre);
  }
}

void check_period(int period) {
  if (period < kMinPeriod || period > kMaxPeriod) {
    throw BadInput("period " + std::to_string(period) + " is outside 1-9");
  }
}

}  // namespace

void validate(const ControllerParams& params) {
  // Walks the recorded form, so a parameter added to a struct is checked without a new line here.
  const nlohmann::json all = params;
  for (const auto& [stage, values] : all.items()) {
    for (const auto& [name, value] : values.items()) {
      const std::string key = stage + "." + name;
      if (value.is_number_integer()) {
        require_in(key, value.get<int>(), Limits<int>{0, kMaxDelayStep});
      } else {
        require_in(key, value.get<double>(),
                   Limits<double>{-kMaxParamMagnitude, kMaxParamMagnitude});
      }
    }
  }
}

ControllerModel make_controller_model(robot::RobotKind kind, const ControllerParams& params,
                                      const robot::BodyParams& body) {
  ControllerModel model{robot::morphology(kind), params, {}};
  const robot::Morphology& morph = model.morphology;
  const std::vector<robot::LegPosture> postures = robot::disabled_postures(body, morph);
  for (std::size_t i = 0; i < morph.size(); ++i) {
    const robot::Leg& leg = morph.legs[i];
    LegCircuit c;
    c.delay = leg_delay(params.delays, morph.legs_per_side, leg.position, leg.side == Side::left);
    c.front = leg.type == LegType::front;
    c.hind = leg.type == LegType::hind;
    c.map = leg_motor_map(kind, leg.type, body.lift_body);
    c.disabled = {postures[i].tc, postures[i].ctr, postures[i].fti};
    model.legs.push_back(c);
  }
  return model;
}

ControllerState make_controller_state(const ControllerModel& model, int period) {
  ControllerState state;
  for (const LegCircuit& c : model.legs) {
    LegState leg;
    leg.delay = make_delay_line(c.delay);
    state.legs.push_back(std::move(leg));
  }
  set_period(model, state, period);
  set_synchronised(state, true);
  return state;
}

void set_periods(const ControllerModel& model, ControllerState& state,
                 std::span<const int> periods) {
  if (periods.size() != state.legs.size()) {
    throw BadInput("expected " + std::to_string(state.legs.size()) + " periods, got " +
                   std::to_string(periods.size()));
  }
  for (int p : periods) check_period(p);
  for (std::size_t i = 0; i < state.legs.size(); ++i) {
    cpg_reset(model.params.cpg, state.legs[i].cpg, periods[i]);
    state.legs[i].post.window_counter = 0;
  }
}

void set_period(const ControllerModel& model, ControllerState& state, int period) {
  const std::vector<int> periods(state.legs.size(), period);
  set_periods(model, state, periods);
}

void set_synchronised(ControllerState& state, bool synchronised) {
  for (std::size_t i = 1; i < state.legs.size(); ++i) state.legs[i].alpha = synchronised ? 1 : 0;
}

void set_chaotic(ControllerState& state, bool chaotic) {
  for (LegState& leg : state.legs) leg.cpg.chaotic = chaotic;
}

void set_disabled(ControllerState& state, std::size_t leg, bool disabled) {
  state.legs.at(leg).disabled = disabled;
}

bool follows_master(const ControllerState& state, std::size_t leg) {
  return leg != kMaster && state.legs[leg].alpha == 1.0;
}

void controller_step(const ControllerModel& model, ControllerState& state) {
  step_cpgs(model, state);
  step_postprocessing(model, state);
  step_psns(model, state);
  step_vrns(model, state);
  step_motor_neurons(model, state);
  step_delay_lines(model, state);
  map_joint_commands(model, state);
  ++state.step;
}

}  // namespace multicpg::neural
