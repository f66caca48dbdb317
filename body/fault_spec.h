// Faults written as text, the one parser and formatter of a fault's text, used by the CLI
// (--fault, --recover), experiment files' scenario names, the Python API and the fuzzer:
//
//   LEGS@STEP                    the legs fail (the paper's malfunction): R1@0, R1,R3@6000
//   LEGS[.JOINT]:KIND[=VALUE]@STEP   R2.CTr:locked@0, R2.CTr:locked=40@0, R3.FTi:passive@0,
//                                L1:weak=0.3@0, L1.TC:weak=0.5@0, R1:short=0.5@0, L2:slip=0.2@0
//   imu:KIND=VALUE@STEP          imu:drift=0.5@0 (deg/s), imu:noise=1@0 (deg)
//
// LEGS is a leg set (robot/leg_sets.h: "R1", "R1,R3", "R1+R3"), JOINT one of TC, CTr, FTi, KIND
// one of body/faults.h. A recovery names what it ends; its value may be left out.
#pragma once

#include <string>
#include <string_view>

#include "body/events.h"
#include "robot/morphology.h"

namespace multicpg::body {

// The word that names the yaw sensor as a fault's target.
inline constexpr std::string_view kSensorTarget = "imu";

// "SPEC@STEP" -> a fault (or a recovery) before controller step STEP, a whole number in
// 0..kMaxSteps written in digits. Throws BadInput (one line, no flag name) for text of another
// form, an unknown leg, joint or kind, or a value or step out of range.
Fault parse_fault(const robot::Morphology& morph, std::string_view text, bool recover);

// A fault's SPEC without "@STEP" (a scenario of an experiment file): the fault at step 0.
Fault parse_malfunction(const robot::Morphology& morph, std::string_view spec, bool recover);

// The text parse_fault reads back: "R1+R3@6000", "R2.CTr:locked@0", "imu:noise=1@0".
std::string fault_text(const robot::Morphology& morph, const Fault& fault);
// The SPEC alone, without "@STEP": "R1+R3", "L1:weak=0.3".
std::string malfunction_text(const robot::Morphology& morph, const Fault& fault);

// A controller step written in digits, in 0..kMaxSteps. Throws BadInput naming the text.
long parse_step(std::string_view text);

}  // namespace multicpg::body
