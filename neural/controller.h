// The multi-CPG locomotion controller: one CPG circuit per leg, R1 the master (paper §2;
// docs/controller.md).
#pragma once

#include <span>
#include <vector>

#include "neural/cpg.h"
#include "neural/delay_lines.h"
#include "neural/drive.h"
#include "neural/motor_map.h"
#include "neural/motor_neurons.h"
#include "neural/postprocessing.h"
#include "neural/psn.h"
#include "neural/vrn.h"
#include "robot/body_params.h"
#include "robot/morphology.h"

namespace multicpg::neural {

// Every weight and constant of the controller.
struct ControllerParams {
  CpgParams cpg;
  PostProcessingParams post;
  PsnParams psn;
  VrnParams vrn;
  MotorNeuronParams motor;
  DelayParams delays;

  bool operator==(const ControllerParams&) const = default;
};

// The fixed wiring of one leg's circuit.
struct LegCircuit {
  int delay = 0;
  bool front = false;
  bool hind = false;
  LegMotorMap map;
  MotorCommands disabled;  // what the leg's joints hold while it is disabled (paper §4)
};

// What the controller is: immutable once made, shared by any number of states.
struct ControllerModel {
  robot::Morphology morphology;
  ControllerParams params;
  std::vector<LegCircuit> legs;

  std::size_t size() const { return legs.size(); }
};

// The controller of `kind` with `params`; `body` gives each leg's disabled posture and the body
// lift of its motor maps (robot/body_params.h). Throws OptionError ("leg_postures[0].leg") for a
// posture of a leg the robot does not have.
ControllerModel make_controller_model(robot::RobotKind kind, const ControllerParams& params = {},
                                      const robot::BodyParams& body = {});

// What one leg's circuit is doing.
struct LegState {
  CpgState cpg;
  PostProcessingState post;
  PsnState psn;
  VrnState vrn;
  MotorNeuronOutputs pre;  // motor-neuron outputs before the delay
  DelayLine delay;
  DelayedSignals delayed;  // after the delay and shaping
  MotorCommands command;   // to the joints, m in [-1, 1]
  double alpha = 0.0;      // synchronisation to the master (paper Eq. 5); unused on the master
  bool disabled = false;   // holds its circuit's disabled posture (paper §4)
};

// What the controller is doing.
struct ControllerState {
  std::vector<LegState> legs;
  DriveInputs drive;
  long step = 0;
};

// A state with every CPG reset to `period` and every client synchronised (paper §2.3: all legs
// functional means alpha = 1).
ControllerState make_controller_state(const ControllerModel& model, int period = 4);

// Sets each leg's period and resets every CPG together (x, mu, counters, windows), so legs with
// equal periods stay phase-locked (docs/controller.md "Control law"). Throws BadInput for a period
// outside 1-9.
void set_periods(const ControllerModel& model, ControllerState& state,
                 std::span<const int> periods);
void set_period(const ControllerModel& model, ControllerState& state, int period);

// Alpha of every client: 1 synchronises all to the master, 0 frees all (paper Eq. 5).
void set_synchronised(ControllerState& state, bool synchronised);
void set_disabled(ControllerState& state, std::size_t leg, bool disabled);

// True when `leg` currently follows the master's output and post-processing.
bool follows_master(const ControllerState& state, std::size_t leg);

// One controller step: CPGs -> post-processing -> PSN -> VRN -> motor neurons -> delays ->
// joint commands. Results are in state.legs[i].command.
void controller_step(const ControllerModel& model, ControllerState& state);

}  // namespace multicpg::neural
