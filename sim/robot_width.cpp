#include "sim/robot_width.h"

#include <algorithm>
#include <limits>
#include <memory>

#include "common/errors.h"

namespace multicpg::sim {

double foot_span(const SimModel& model) {
  const mjModel* m = model.mj.get();
  const std::unique_ptr<mjData, MjDataDeleter> d(mj_makeData(m));
  if (!d) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  reset_to_start(model, d.get());
  mj_kinematics(m, d.get());
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const LegSlots& leg : model.legs) {
    const double y = d->geom_xpos[3 * leg.foot_geom + 1];
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return hi - lo;
}

}  // namespace multicpg::sim
