// Velocity regulating network, one half per leg (docs/controller.md "VRN").
#pragma once

#include <array>

namespace multicpg::neural {

// Weights of docs/controller.md "VRN".
struct VrnParams {
  double input_weight = 1.75;  // u0 = tanh(1.75 o11)
  double steer_weight = 5.0;   // u1 = tanh(5 input3/4)
  double hidden_weight = 1.7246;
  double hidden_bias = -2.48285;
  double output_weight = 0.5;

  bool operator==(const VrnParams&) const = default;
};

// Outputs u0, u1, h4..h7 and v, all starting at 0.
struct VrnState {
  std::array<double, 2> u{};
  std::array<double, 4> h{};
  double v = 0.0;
};

// One synchronous update; `steer` is input3 (left legs) or input4 (right legs). The VRN acts
// like u0 * u1, so v follows -1.2 o11(t-2) when walking forward and its sign reverses with steer.
void vrn_step(const VrnParams& params, VrnState& state, double psn_output, double steer);

}  // namespace multicpg::neural
