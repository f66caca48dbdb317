// The controller's parameters checked, as they are recorded and read (neural/json.h): every
// weight and constant finite and in range, whatever struct it is in.
#pragma once

#include "neural/controller.h"

namespace multicpg::neural {

// Far beyond any weight, bias or constant of the paper (the largest is |w11| = 22, Eq. 1), yet
// small enough that no neuron input overflows.
inline constexpr double kMaxParamMagnitude = 1000.0;
// Longest delay line step of tau or tau_l (ours are 18 and 90, docs/controller.md "Delay lines"): a
// delay line holds a leg's whole history over 6 * tau + tau_l steps, so this keeps it small.
inline constexpr int kMaxDelayStep = 1000;

// Throws OptionError (key "cpg.w11", ...) for a non-finite parameter, one beyond
// kMaxParamMagnitude, or a delay step outside 0..kMaxDelayStep.
void validate(const ControllerParams& params);

}  // namespace multicpg::neural
