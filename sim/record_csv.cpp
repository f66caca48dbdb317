#include "sim/record_csv.h"

#include <iomanip>
#include <string>

namespace multicpg::sim {

void write_record_csv(std::ostream& out, const robot::Morphology& morph, const WalkRecord& r) {
  out << "step,time_s,x_m,y_m,z_m,yaw_deg";
  for (const robot::Leg& leg : morph.legs) {
    for (robot::Joint j : robot::kJoints) {
      const std::string name = leg.name + "_" + std::string(robot::to_string(j));
      out << "," << name << "_command," << name << "_target_rad," << name << "_actual_rad";
    }
    out << "," << leg.name << "_contact";
  }
  out << "\n" << std::setprecision(9);
  const std::size_t legs = morph.size();
  for (std::size_t row = 0; row < r.rows(); ++row) {
    out << row << "," << r.time[row] << "," << r.x[row] << "," << r.y[row] << "," << r.z[row] << ","
        << r.yaw_deg[row];
    for (std::size_t leg = 0; leg < legs; ++leg) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        const std::size_t k = (row * legs + leg) * robot::kJointsPerLeg + j;
        out << "," << r.command[k] << "," << r.target[k] << "," << r.actual[k];
      }
      out << "," << static_cast<int>(r.contact[row * legs + leg]);
    }
    out << "\n";
  }
}

}  // namespace multicpg::sim
