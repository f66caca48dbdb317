#include "sim/record_csv.h"

#include <iomanip>
#include <string>
#include <utility>

#include "common/atomic_file.h"
#include "common/errors.h"

namespace multicpg::sim {
namespace {

// Significant digits of every number of the CSV.
constexpr int kCsvDigits = 9;

void write_header(std::ostream& out, const robot::Morphology& morph) {
  out << "step,time_s,x_m,y_m,z_m,yaw_deg,sensed_yaw_deg";
  for (const robot::Leg& leg : morph.legs) {
    for (robot::Joint j : robot::kJoints) {
      const std::string name = leg.name + "_" + std::string(robot::to_string(j));
      out << "," << name << "_command," << name << "_target_rad," << name << "_actual_rad";
    }
    out << "," << leg.name << "_contact";
  }
  out << "\n" << std::setprecision(kCsvDigits);
}

// Row `row` of `r` as the line of step `step`.
void write_row(std::ostream& out, std::size_t legs, const WalkRecord& r, std::size_t row,
               std::size_t step) {
  out << step << "," << r.time[row] << "," << r.x[row] << "," << r.y[row] << "," << r.z[row] << ","
      << r.yaw_deg[row] << "," << r.sensed_yaw_deg[row];
  for (std::size_t leg = 0; leg < legs; ++leg) {
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const std::size_t k = (row * legs + leg) * robot::kJointsPerLeg + j;
      out << "," << r.command[k] << "," << r.target[k] << "," << r.actual[k];
    }
    out << "," << static_cast<int>(r.contact[row * legs + leg]);
  }
  out << "\n";
}

}  // namespace

RecordCsvWriter::RecordCsvWriter(std::ostream& out, const robot::Morphology& morph,
                                 std::string name)
    : out_(out), morph_(morph), name_(std::move(name)) {
  row_.legs = morph.size();
}

void RecordCsvWriter::on_start(const SimModel& model, const SimState& state) {
  write_header(out_, morph_);
  write(model, state);
}

void RecordCsvWriter::on_step(const SimModel& model, const SimState& state) {
  write(model, state);
}

void RecordCsvWriter::write(const SimModel& model, const SimState& state) {
  for (auto* v : {&row_.time, &row_.x, &row_.y, &row_.z, &row_.yaw_deg, &row_.sensed_yaw_deg,
                  &row_.command, &row_.target, &row_.actual}) {
    v->clear();
  }
  row_.contact.clear();
  append_record(model, state, /*joints=*/true, row_);
  write_row(out_, morph_.size(), row_, 0, step_++);
  if (!out_) throw RuntimeFailure("writing '" + name_ + "' failed: " + write_failure(out_));
}

}  // namespace multicpg::sim
