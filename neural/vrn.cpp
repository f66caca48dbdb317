#include "neural/vrn.h"

#include <cmath>

namespace multicpg::neural {

void vrn_step(const VrnParams& p, VrnState& s, double psn_output, double steer) {
  const double sum = s.u[0] + s.u[1];
  const double diff = s.u[0] - s.u[1];
  const double v = std::tanh(p.output_weight * (s.h[0] + s.h[1] - s.h[2] - s.h[3]));
  s.h = {std::tanh(p.hidden_weight * sum + p.hidden_bias),
         std::tanh(-p.hidden_weight * sum + p.hidden_bias),
         std::tanh(p.hidden_weight * diff + p.hidden_bias),
         std::tanh(-p.hidden_weight * diff + p.hidden_bias)};
  s.v = v;
  // The input layer reads the PSN output of this same step (docs/controller.md "VRN").
  s.u = {std::tanh(p.input_weight * psn_output), std::tanh(p.steer_weight * steer)};
}

}  // namespace multicpg::neural
