// Drive inputs of the neural motor control (docs/controller.md "Drive inputs").
#pragma once

namespace multicpg::neural {

// Forward walking: input0 = 0, input1 = 1, input2 = 1, input3 = input4 = -1.
struct DriveInputs {
  double inhibition = 0.0;    // input0: 1 inhibits every joint
  double lateral = 1.0;       // input1: scales the FTi drive (sideways walking)
  double phase_switch = 1.0;  // input2: PSN selector
  double turn_left = -1.0;    // input3: left VRN; +1 reverses the left TC
  double turn_right = -1.0;   // input4: right VRN; +1 reverses the right TC
};

}  // namespace multicpg::neural
