// Faults written as text: "R1@0", "R1,R3@6000" (these legs fail, or recover, before that step).
// The one parser and formatter of a fault's text, used by the CLI (--fault, --recover), the
// Python API and the fuzzer; experiment files write the same faults as tables.
#pragma once

#include <string>
#include <string_view>

#include "robot/morphology.h"
#include "sim/events.h"

namespace multicpg::sim {

// "LEGS@STEP" -> a fault (or a recovery) of those legs before controller step STEP, a whole
// number in 0..kMaxSteps written in digits. Throws BadInput (one line, no flag name) for text of
// another form, an unknown or repeated leg, or a step out of range.
Fault parse_fault(const robot::Morphology& morph, std::string_view text, bool recover);

// The text parse_fault reads back: "R1+R3@6000".
std::string fault_text(const robot::Morphology& morph, const Fault& fault);

// A controller step written in digits, in 0..kMaxSteps. Throws BadInput naming the text.
long parse_step(std::string_view text);

}  // namespace multicpg::sim
