#include "neural/motor_neurons.h"

#include <cmath>

namespace multicpg::neural {

MotorNeuronOutputs motor_neurons(const MotorNeuronParams& p, double psn_output, double vrn_output,
                                 bool front_leg, const DriveInputs& drive) {
  const double inhibit = p.inhibition * drive.inhibition;
  MotorNeuronOutputs out;
  out.tc = std::tanh(p.tc_weight * vrn_output + (front_leg ? inhibit : -inhibit));
  out.ctr = std::tanh(p.psn_weight * psn_output + p.bias + inhibit);
  out.fti = std::tanh(p.psn_weight * psn_output * drive.lateral + p.bias + inhibit);
  return out;
}

}  // namespace multicpg::neural
