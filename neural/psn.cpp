#include "neural/psn.h"

#include <cmath>

namespace multicpg::neural {

void psn_step(const PsnParams& p, PsnState& s, double y1, double y2, const DriveInputs& drive) {
  const std::array<double, 12>& o = s.o;
  std::array<double, 12> n{};
  n[0] = std::tanh(-p.selector_weight * drive.phase_switch + p.selector_bias);
  n[1] = std::tanh(p.selector_weight * drive.phase_switch);
  n[2] = std::tanh(p.input_weight * y2 - p.inhibition * o[0]);
  n[3] = std::tanh(p.input_weight * y1 - p.inhibition * o[1]);
  n[4] = std::tanh(p.input_weight * y1 - p.inhibition * o[0]);
  n[5] = std::tanh(p.input_weight * y2 - p.inhibition * o[1]);
  for (int i = 6; i <= 9; ++i) n[i] = std::tanh(p.hidden_weight * o[i - 4] + p.hidden_bias);
  n[10] = std::tanh(p.output_weight * (o[6] + o[7]) + p.output_bias);
  n[11] = std::tanh(p.output_weight * (o[8] + o[9]) + p.output_bias);
  s.o = n;
}

}  // namespace multicpg::neural
