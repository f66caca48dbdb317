// CPG post-processing: hysteresis neurons and ramp integrators (SPEC §2, reference §2).
#pragma once

namespace multicpg::neural {

// What the post-processing is (reference §2 constants).
struct PostProcessingParams {
  double input_gain = 8.0;   // FAC: I = 8 (x - b) at a window step
  double bias1 = 0.5;        // b1
  double bias2 = 0.6;        // b2
  double self_weight = 1.1;  // w_hys
  double gain = 5.0;         // tanh5(u) = tanh(5u)
  double flip = 0.5;         // EPS: |h(t) - h(t-1)| above this is a flip
};

// What it is doing: window counter, hysteresis outputs h, ramp outputs y (all start at 0).
struct PostProcessingState {
  long window_counter = 0;
  double h1 = 0.0;
  double h2 = 0.0;
  double y1 = 0.0;
  double y2 = 0.0;
};

// Window length N = 2p + 1 steps (reference §2.1).
int window_length(int period);

// Advances this leg's window counter; true when this step is a window step (k mod N == 0).
bool advance_window(PostProcessingState& state, int period);

// One step of both hysteresis neurons and ramps, from the newest CPG output. `window` says
// whether this step samples the CPG; `period` sets the ramp slopes (2/N up, 2/((1-p)N) down).
void postprocessing_step(const PostProcessingParams& params, PostProcessingState& state, double x1,
                         double x2, int period, bool window);

}  // namespace multicpg::neural
