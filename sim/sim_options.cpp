#include "sim/sim_options.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "common/errors.h"
#include "neural/validate.h"

namespace multicpg::sim {

double resolved_physics_dt(const SimOptions& options) {
  return options.physics_dt == 0.0 ? default_physics_dt(options.control_dt) : options.physics_dt;
}

double default_physics_dt(double control_dt) {
  if (!(control_dt > 0.0)) throw OptionError("control_dt", "must be positive");
  // Tolerance so that 0.037 / 0.004625 = 8 exactly is not rounded up to 9.
  const double n = std::ceil(control_dt / kMaxDefaultPhysicsDt - kStepRatioTolerance);
  return control_dt / n;
}

int physics_substeps(double control_dt, double physics_dt) {
  if (!(control_dt > 0.0)) throw OptionError("control_dt", "must be positive");
  if (!(physics_dt > 0.0)) throw OptionError("physics_dt", "must be positive");
  const double ratio = control_dt / physics_dt;
  const double whole = std::round(ratio);
  if (!(whole <= static_cast<double>(kMaxSubsteps))) {
    std::ostringstream msg;
    msg << "gives " << ratio << " physics steps per control step of " << control_dt
        << " s; at most " << kMaxSubsteps;
    throw OptionError("physics_dt", msg.str());
  }
  if (whole < 1.0 || std::abs(ratio - whole) > kStepRatioTolerance * ratio) {
    std::ostringstream msg;
    msg << "must divide the control step " << control_dt << " s a whole number of times, got "
        << physics_dt << " s (ratio " << ratio << ")";
    throw OptionError("physics_dt", msg.str());
  }
  return static_cast<int>(whole);
}

void validate(const SimOptions& options) {
  require_in("control_dt", options.control_dt, kControlDtLimits);
  require_in("physics_dt", options.physics_dt, kPhysicsDtLimits);
  if (options.physics_dt != 0.0 && options.physics_dt < kMinPhysicsDt) {
    throw OptionError("physics_dt", fmt::format("must be 0 (default) or at least {}, got {}",
                                                kMinPhysicsDt, options.physics_dt));
  }
  require_in("servo_gain", options.servo_gain, kServoGainLimits);
  require_in("scene.tunnel_length", options.scene.tunnel_length, kTunnelLengthLimits);
  require_in("scene.tunnel_width", options.scene.tunnel_width, kTunnelWidthLimits);
  within("scene.terrain", [&] { robot::validate(options.scene.terrain); });
  within("controller", [&] { neural::validate(options.controller); });
  within("body", [&] { robot::validate(options.body); });
  physics_substeps(options.control_dt, resolved_physics_dt(options));
}

void validate(const SimOptions& options, robot::RobotKind kind) {
  validate(options);
  within("body", [&] { robot::disabled_postures(options.body, robot::morphology(kind)); });
}

}  // namespace multicpg::sim
