// The three motor neurons of a leg (docs/controller.md "Motor neurons").
#pragma once

#include "neural/drive.h"

namespace multicpg::neural {

// Weights of docs/controller.md "Motor neurons".
struct MotorNeuronParams {
  double tc_weight = -2.5;   // TC_pre = tanh(-2.5 v +- 10 input0)
  double inhibition = 10.0;  // input0 weight
  double psn_weight = 5.0;   // CTr_pre = tanh(5 o11 - 0.5 + 10 input0)
  double bias = -0.5;

  bool operator==(const MotorNeuronParams&) const = default;
};

// Pre-motor signals of one leg, before the delay lines.
struct MotorNeuronOutputs {
  double tc = 0.0;
  double ctr = 0.0;
  double fti = 0.0;
};

// `front_leg` picks the sign of the inhibition input on TC (+ front, - middle and hind).
MotorNeuronOutputs motor_neurons(const MotorNeuronParams& params, double psn_output,
                                 double vrn_output, bool front_leg, const DriveInputs& drive);

}  // namespace multicpg::neural
