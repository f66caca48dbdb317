#include "neural/delay_lines.h"

namespace multicpg::neural {

DelayLine make_delay_line(int delay) {
  return DelayLine{std::vector<MotorNeuronOutputs>(static_cast<std::size_t>(delay) + 2), 0};
}

int leg_delay(const DelayParams& params, int legs_per_side, int position, bool left) {
  return (legs_per_side - 1 - position) * params.tau + (left ? params.tau_l : 0);
}

DelayedSignals delay_step(DelayLine& line, const MotorNeuronOutputs& input, bool hind_leg) {
  const std::size_t size = line.ring.size();
  line.head = (line.head + 1) % size;
  line.ring[line.head] = input;
  // Oldest two entries: d and d+1 steps ago.
  const MotorNeuronOutputs& now = line.ring[(line.head + 2) % size];
  const MotorNeuronOutputs& before = line.ring[(line.head + 1) % size];
  DelayedSignals out{now, now.ctr > before.ctr};
  if (now.ctr < before.ctr) out.pre.ctr = -1.0;  // stance: CTr fully depressed
  if (hind_leg) out.pre.fti = -now.fti;          // "push the leg outwards" (paper §4.1)
  return out;
}

}  // namespace multicpg::neural
