// The two-neuron chaotic CPG with adaptive chaos control (paper Eqs. 1-5; docs/controller.md
// "CPG").
#pragma once

#include <array>

namespace multicpg::neural {

// Periods the control buffer can hold (docs/controller.md "Control law": p <= 10; we allow 1-9).
inline constexpr int kMinPeriod = 1;
inline constexpr int kMaxPeriod = 9;

// What the CPG is: weights, biases and the adaptation rule (paper Eqs. 1-4).
struct CpgParams {
  double w11 = -22.0;
  double w12 = 5.9;
  double w21 = -6.6;
  double theta1 = -3.4;
  double theta2 = 3.8;
  double lambda = 0.05;  // adaptation rate of mu, paper Eq. 4
  double mu0 = -1.0;     // initial control strength: docs/controller.md "Control law"

  bool operator==(const CpgParams&) const = default;
};

// What the CPG is doing.
struct CpgState {
  double x1 = 0.0;
  double x2 = 0.0;
  double mu = -1.0;
  int period = 4;
  int counter = 0;       // updates since the last control event
  bool chaotic = false;  // uncontrolled mode: c = 0 on every step (paper §2.1)
  // Outputs stored since the last control event: buffer[0] is that event's output.
  std::array<std::array<double, 2>, kMaxPeriod + 1> buffer{};
};

// Master's output this step, fed to a client by paper Eq. 5.
struct SyncInput {
  double alpha = 0.0;      // 1 = synchronised (M-neuron active), 0 = independent
  double master_x1 = 0.0;  // master's x1 of the same step (the master is stepped first)
};

// Reset for period p: x = 0, mu = mu0, counters 0 (docs/controller.md "Control law").
void cpg_reset(const CpgParams& params, CpgState& state, int period);

// One update of both neurons. Control is applied once every p+1 updates with
// Delta = x(t) - x(t-p) (paper Eq. 3); a client's control input is shunted by (1 - alpha)
// and its x1 pulled to the master's by alpha (paper Eq. 5).
void cpg_step(const CpgParams& params, CpgState& state, const SyncInput& sync = {});

}  // namespace multicpg::neural
