#include "neural/postprocessing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/errors.h"

namespace multicpg::neural {
namespace {

double clip(double v) {
  return std::clamp(v, -1.0, 1.0);
}

double slope_up(int period) {
  return 2.0 / window_length(period);
}

// docs/controller.md "Post-processing": 2/((1-p)N). At p = 1 it is 2/0 = +inf, so the ramp
// clips to a constant +1: the paper's "stop" (docs/controller.md "Period 1: stop"). We name that
// case instead of dividing by zero.
double slope_down(int period) {
  if (period == 1) return std::numeric_limits<double>::infinity();
  return 2.0 / ((1.0 - period) * window_length(period));
}

}  // namespace

int window_length(int period) {
  return 2 * period + 1;
}

bool advance_window(PostProcessingState& state, int period) {
  ++state.window_counter;  // pre-incremented, as the authors' code
  return state.window_counter % window_length(period) == 0;
}

void postprocessing_step(const PostProcessingParams& params, PostProcessingState& state, double x1,
                         double x2, int period, bool window) {
  const double i1 = window ? params.input_gain * (x1 - params.bias1) : 0.0;
  const double i2 = window ? params.input_gain * (x2 - params.bias2) : 0.0;
  const double h1 = std::tanh(params.gain * (params.self_weight * state.h1 + i1));
  const double h2 = std::tanh(params.gain * (params.self_weight * state.h2 + i2));
  const bool flip1 = std::abs(h1 - state.h1) > params.flip;
  const bool flip2 = std::abs(h2 - state.h2) > params.flip;
  state.h1 = h1;
  state.h2 = h2;

  // Ramp 1 restarts at -1 on an upward flip and rises (swing); ramp 2 has opposite polarity.
  double y1 = flip1 ? (h1 > 0.0 ? -1.0 : 1.0) : state.y1;
  y1 += h1 > 0.0 ? slope_up(period) : slope_down(period);
  double y2 = flip2 ? (h2 > 0.0 ? 1.0 : -1.0) : state.y2;
  y2 += h2 < 0.0 ? slope_up(period) : slope_down(period);
  state.y1 = clip(y1);
  state.y2 = clip(y2);
}

long lock_steps(int period) {
  switch (period) {
    case 1:
      return 0;
    case 4:
      return 737;
    case 5:
      return 43;
    case 6:
      return 64;
    case 8:
      return 84;
    case 9:
      return 208;
    default:
      break;
  }
  throw BadInput("period " + std::to_string(period) +
                 " never locks (paper §2.1: 1, 4, 5, 6, 8, 9 do)");
}

}  // namespace multicpg::neural
