// What a learning mode needs the body to sense beyond the orientation sensor's yaw (paper §3:
// the paper's mode reads the yaw alone). Robust mode also judges each window's path angle (paper
// Table 1's measure) and its steering reflex keeps a course line, both from the trunk's
// position, which a body with an orientation sensor only does not report (body::Pose2 with NaN x
// and y; docs/hardware.md "What the learner reads"). Nothing here knows which body it is.
#pragma once

#include "common/errors.h"
#include "learning/compensation.h"

namespace multicpg::learning {

// Throws OptionError (key "mode") when `options` need a position the body does not sense
// (`senses_position`: its pose has one, body::Pose2::has_position).
inline void require_senses(const CompensationOptions& options, bool senses_position) {
  if (options.mode == Mode::robust && !senses_position) {
    throw OptionError("mode",
                      "robust mode judges the trunk's path and steers by its position, which this "
                      "robot does not sense (docs/hardware.md \"What the learner reads\"); use "
                      "paper mode, or a yaw line that reports POSE lines");
  }
}

}  // namespace multicpg::learning
