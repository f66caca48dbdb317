// Phase switching network, one per leg (docs/controller.md "PSN").
#pragma once

#include <array>

#include "neural/drive.h"

namespace multicpg::neural {

// Weights of docs/controller.md "PSN".
struct PsnParams {
  double selector_weight = 1.0;  // o0 = tanh(-w input2 + bias), o1 = tanh(w input2)
  double selector_bias = 1.0;
  double input_weight = 0.5;   // o2..o5 from the ramps
  double inhibition = 5.0;     // o0/o1 -> o2..o5
  double hidden_weight = 0.5;  // o6..o9 = tanh(0.5 o + 0.5)
  double hidden_bias = 0.5;
  double output_weight = 3.0;  // o10, o11 = tanh(3 o + 3 o - 1.35)
  double output_bias = -1.35;

  bool operator==(const PsnParams&) const = default;
};

// Neuron outputs o0..o11, all starting at 0.
struct PsnState {
  std::array<double, 12> o{};
  // o11: the PSN output fed to the VRN and the motor neurons (docs/controller.md "PSN").
  double output() const { return o[11]; }
};

// One synchronous update: the first layer reads this step's ramps, deeper layers the previous
// outputs, so o11(t) follows y1(t-2).
void psn_step(const PsnParams& params, PsnState& state, double y1, double y2,
              const DriveInputs& drive);

}  // namespace multicpg::neural
