// The controller's parameters as JSON (nlohmann's type macros): keys are the member names, a
// missing key keeps its default. Recorded with every result and read from experiment files.
// Its states too, every key required: a run's checkpoint (sim/checkpoint.h).
#pragma once

#include <nlohmann/json.hpp>

#include "neural/controller.h"

namespace multicpg::neural {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(CpgParams, w11, w12, w21, theta1, theta2, lambda,
                                                mu0)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(PostProcessingParams, input_gain, bias1, bias2,
                                                self_weight, gain, flip)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(PsnParams, selector_weight, selector_bias,
                                                input_weight, inhibition, hidden_weight,
                                                hidden_bias, output_weight, output_bias)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(VrnParams, input_weight, steer_weight,
                                                hidden_weight, hidden_bias, output_weight)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(MotorNeuronParams, tc_weight, inhibition,
                                                psn_weight, bias)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(DelayParams, tau, tau_l)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ControllerParams, cpg, post, psn, vrn, motor,
                                                delays)

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CpgState, x1, x2, mu, period, counter, chaotic, buffer)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PostProcessingState, window_counter, h1, h2, y1, y2)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PsnState, o)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(VrnState, u, h, v)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(MotorNeuronOutputs, tc, ctr, fti)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(MotorCommands, tc, ctr, fti)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DelayLine, ring, head)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DelayedSignals, pre, swing)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LegState, cpg, post, psn, vrn, pre, delay, delayed, command,
                                   alpha, disabled)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DriveInputs, inhibition, lateral, phase_switch, turn_left,
                                   turn_right)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ControllerState, legs, drive, step)

}  // namespace multicpg::neural
