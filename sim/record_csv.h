// The per-step sensor record of a run as CSV: trunk pose, every joint's command,
// target and actual angle, and every foot's contact. Used by `walk --csv` and `learn --out`,
// which stream it (RecordCsvWriter) so a run's memory does not grow with its length.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "robot/morphology.h"
#include "sim/stepper.h"
#include "sim/walk_record.h"

namespace multicpg::sim {

// The CSV written as the run goes: the header and row 0 when the stepper starts, one line per
// step after it. Columns: step,time_s,x_m,y_m,z_m,yaw_deg, then per leg and joint
// <leg>_<joint>_command, _target_rad, _actual_rad, and per leg <leg>_contact. Throws
// RuntimeFailure naming `name` as soon as `out` fails (a full disk), instead of walking on.
class RecordCsvWriter final : public Observer {
 public:
  RecordCsvWriter(std::ostream& out, const robot::Morphology& morph, std::string name);
  void on_start(const SimModel& model, const SimState& state) override;
  void on_step(const SimModel& model, const SimState& state) override;

 private:
  void write(const SimModel& model, const SimState& state);

  std::ostream& out_;
  const robot::Morphology& morph_;
  std::string name_;
  WalkRecord row_;  // one row, reused: its vectors keep their capacity
  std::size_t step_ = 0;
};

}  // namespace multicpg::sim
