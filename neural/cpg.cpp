#include "neural/cpg.h"

#include <cmath>

namespace multicpg::neural {
namespace {

double sigmoid(double a) {
  return 1.0 / (1.0 + std::exp(-a));
}

}  // namespace

void cpg_reset(const CpgParams& params, CpgState& state, int period) {
  state.x1 = 0.0;
  state.x2 = 0.0;
  state.mu = params.mu0;
  state.period = period;
  state.counter = 0;
  state.buffer = {};
}

void cpg_step(const CpgParams& params, CpgState& state, const SyncInput& sync) {
  const int p = state.period;
  const bool control_event = !state.chaotic && state.counter == p;
  double c1 = 0.0;
  double c2 = 0.0;
  if (control_event) {
    // Paper Eqs. 2-4 in the authors' form (docs/controller.md "Control law"): Delta compares
    // outputs p apart.
    const double d1 = state.buffer[p][0] - state.buffer[0][0];
    const double d2 = state.buffer[p][1] - state.buffer[0][1];
    const double shunt = 1.0 - sync.alpha;  // Paper §2.3: a synchronised client is uncontrolled
    c1 = shunt * state.mu * (params.w11 * d1 + params.w12 * d2);
    c2 = shunt * state.mu * (params.w21 * d1);
    state.mu += params.lambda * (d1 * d1 + d2 * d2) / p;
  }
  // Paper Eq. 6 (w22 = 0), then Eq. 5 for the client's first neuron.
  const double a1 = params.theta1 + params.w11 * state.x1 + params.w12 * state.x2 + c1;
  const double a2 = params.theta2 + params.w21 * state.x1 + c2;
  const double s1 = sigmoid(a1);
  // Written as a blend so alpha = 1 gives the master's value bit for bit.
  state.x1 = (1.0 - sync.alpha) * s1 + sync.alpha * sync.master_x1;
  state.x2 = sigmoid(a2);

  if (state.chaotic) return;
  state.counter = control_event ? 0 : state.counter + 1;
  state.buffer[state.counter] = {state.x1, state.x2};
}

}  // namespace multicpg::neural
