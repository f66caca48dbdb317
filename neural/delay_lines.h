// Delay lines and post-delay shaping (docs/controller.md "Delay lines", "Post-delay shaping").
#pragma once

#include <vector>

#include "neural/motor_neurons.h"

namespace multicpg::neural {

// Inter-leg delays in controller steps. Defaults are the authors' code (docs/controller.md
// "Delay lines"); the paper's text says 16 and 48, which do not give the named gaits
// (docs/controller.md "Gaits").
struct DelayParams {
  int tau = 18;    // ipsilateral lag per leg, hind to front
  int tau_l = 90;  // left side lags the right

  bool operator==(const DelayParams&) const = default;
};

// One leg's FIFO of pre-motor signals, starting as zeros. Holds d + 2 entries:
// the value d steps ago and the one before it (for the CTr falling test).
struct DelayLine {
  std::vector<MotorNeuronOutputs> ring;
  std::size_t head = 0;  // index of the newest entry
};

DelayLine make_delay_line(int delay);

// Delay of a leg: (legs per side - 1 - position) tau, plus tau_L on the left.
int leg_delay(const DelayParams& params, int legs_per_side, int position, bool left);

// A leg's delayed, shaped pre-motor signals and its phase.
struct DelayedSignals {
  MotorNeuronOutputs pre;
  bool swing = false;  // the delayed CTr signal rises (swing = rising part)
};

// Pushes this step's signals; returns the delayed ones shaped as docs/controller.md "Post-delay
// shaping": CTr = -1 while the delayed CTr falls (stance), hind-leg FTi inverted, TC unchanged.
DelayedSignals delay_step(DelayLine& line, const MotorNeuronOutputs& input, bool hind_leg);

}  // namespace multicpg::neural
