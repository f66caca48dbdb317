// Fault timelines and window measures as JSON (nlohmann's type macros; keys are the member
// names). No MuJoCo here, so the learner's records can use them (sim/CMakeLists.txt).
#pragma once

#include <nlohmann/json.hpp>

#include "body/deviation.h"
#include "body/events.h"

namespace multicpg::body {

// A fault's one JSON shape: {step, legs (indices), recover}, the form leg faults have always been
// recorded in, with "kind" (its name), "joint" and "value" for every other kind. Written by hand,
// not with a type macro: the kind is a variant and a whole leg's fault leaves its keys out. A
// timeline is a list of them.
void to_json(nlohmann::json& j, const Fault& fault);
// Throws BadInput for an unknown kind or joint, or a value its kind does not take.
void from_json(const nlohmann::json& j, Fault& fault);

// The form learning records have always carried a run's faults in (learn --json, tunnel --json;
// tests/data/golden holds it), kept so old and new records compare byte for byte: the keys
// "disabled", "fail_step" and "faults" of the learning options. The paper's case, one whole-leg
// failure, is {"disabled": its leg indices, "fail_step": its step, "faults": []}; any other
// timeline (none included) is {"disabled": [], "fail_step": 0, "faults": the timeline}. Read it
// back as the timeline `faults`, or fail_at(disabled, fail_step) when `faults` is empty.
nlohmann::json faults_record(const FaultTimeline& faults);

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Pose2, x, y, yaw_deg)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(WindowMeasure, yaw_deg, path_deg, forward_m,
                                                lateral_m, steering_effort)

}  // namespace multicpg::body
