// The per-step sensor record of a run as CSV (issue 3): trunk pose, every joint's command,
// target and actual angle, and every foot's contact. Used by `walk --csv` and `learn --out`.
#pragma once

#include <ostream>

#include "robot/morphology.h"
#include "sim/walk.h"

namespace multicpg::sim {

// Columns: step,time_s,x_m,y_m,z_m,yaw_deg, then per leg and joint <leg>_<joint>_command,
// _target_rad, _actual_rad, and per leg <leg>_contact. `record` must hold joint rows.
void write_record_csv(std::ostream& out, const robot::Morphology& morph, const WalkRecord& record);

}  // namespace multicpg::sim
