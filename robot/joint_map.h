// Motor commands m in [-1, 1] to joint angles, and the joint limits (docs/robots.md "Joint angles",
// §6.1). Angles are radians in the paper's sign convention: TC + = forward, CTr + = elevation,
// FTi + = extension (so the FTi angle is minus the flexion). The MJCF joint axes are chosen so that
// a positive qpos means exactly this on both sides (robot/mjcf.cpp).
#pragma once

#include "robot/morphology.h"

namespace multicpg::robot {

struct AngleRange {
  double lo;  // rad
  double hi;  // rad
};

// Joint limits of docs/robots.md "Joint limits": TC front and hind +-70 deg, middle +-60 deg; CTr
// +-75 deg; FTi flexion 20..130 deg, i.e. -130..-20 deg in the extension-positive convention.
AngleRange joint_limits(LegType type, Joint joint);

// Angle a command m asks for (docs/robots.md "Joint angles"): TC = 70 deg m (front, hind) or 60 deg
// m (middle), CTr = 75 deg m, FTi = (55 m - 75) deg. m is clipped to [-1, 1] first, as the
// lpzrobots servo clips its input.
double joint_angle(LegType type, Joint joint, double command);
// The same for a joint whose window a robot file gives (robot/robot_file.h).
double joint_angle(const AngleRange& window, double command);

// The change of command that turns `joint` by `radians` (the inverse slope of joint_angle).
double command_change(LegType type, Joint joint, double radians);

}  // namespace multicpg::robot
