#include "sim/robot_width.h"

#include <algorithm>
#include <cmath>
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

LateralReach lateral_reach(const SimModel& model, const SimState& state) {
  const mjModel* m = physics_model(model, state);
  const mjData* d = state.data.get();
  LateralReach reach{std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()};
  for (int g = 0; g < m->ngeom; ++g) {
    // The world (ground, walls) is body 0; a geom that collides with nothing cannot touch a wall.
    if (m->geom_bodyid[g] == 0 || (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0)) {
      continue;
    }
    const mjtNum* size = m->geom_size + 3 * g;
    const mjtNum* axis_y = d->geom_xmat + 9 * g + 3;  // world y of the geom's x, y, z axes
    double half = 0.0;
    switch (m->geom_type[g]) {
      case mjGEOM_SPHERE:
        half = size[0];
        break;
      case mjGEOM_CAPSULE:
      case mjGEOM_CYLINDER:  // radius all round: at most a little wide
        half = size[0] + std::abs(axis_y[2]) * size[1];
        break;
      case mjGEOM_BOX:
        half = std::abs(axis_y[0]) * size[0] + std::abs(axis_y[1]) * size[1] +
               std::abs(axis_y[2]) * size[2];
        break;
      case mjGEOM_ELLIPSOID:
        half = std::hypot(axis_y[0] * size[0], axis_y[1] * size[1], axis_y[2] * size[2]);
        break;
      default:  // meshes and the rest: the bounding sphere
        half = m->geom_rbound[g];
        break;
    }
    const double y = d->geom_xpos[3 * g + 1];
    reach.low = std::min(reach.low, y - half);
    reach.high = std::max(reach.high, y + half);
  }
  return reach;
}

}  // namespace multicpg::sim
