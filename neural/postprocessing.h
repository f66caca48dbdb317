// CPG post-processing: hysteresis neurons and ramp integrators (docs/controller.md
// "Post-processing").
#pragma once

namespace multicpg::neural {

// What the post-processing is (its constants).
struct PostProcessingParams {
  double input_gain = 8.0;   // FAC: I = 8 (x - b) at a window step
  double bias1 = 0.5;        // b1
  double bias2 = 0.6;        // b2
  double self_weight = 1.1;  // w_hys
  double gain = 5.0;         // tanh5(u) = tanh(5u)
  double flip = 0.5;         // EPS: |h(t) - h(t-1)| above this is a flip

  bool operator==(const PostProcessingParams&) const = default;
};

// What it is doing: window counter, hysteresis outputs h, ramp outputs y (all start at 0).
struct PostProcessingState {
  long window_counter = 0;
  double h1 = 0.0;
  double h2 = 0.0;
  double y1 = 0.0;
  double y2 = 0.0;
};

// Window length N = 2p + 1 steps .
int window_length(int period);

// Controller steps after a CPG reset (x = 0, mu = -1) until this period's post-processed output
// is exactly periodic (docs/controller.md "Steps to lock, from reset";
// tests/test_postprocessing.cpp): 737 for p = 4, 43 / 64 / 84 / 208 for p = 5 / 6 / 8 / 9, 0 for
// the constant output of p = 1. Periods that never lock (2, 3, 7) throw BadInput.
long lock_steps(int period);

// Advances this leg's window counter; true when this step is a window step (k mod N == 0).
bool advance_window(PostProcessingState& state, int period);

// One step of both hysteresis neurons and ramps, from the newest CPG output. `window` says
// whether this step samples the CPG; `period` sets the ramp slopes (2/N up, 2/((1-p)N) down).
void postprocessing_step(const PostProcessingParams& params, PostProcessingState& state, double x1,
                         double x2, int period, bool window);

}  // namespace multicpg::neural
