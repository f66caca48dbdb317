// The physical description of each robot (docs/robots.md "Geometry and masses"): trunk boxes, leg
// roots, segment capsules, masses, servos, feet and materials. One description per morphology; the
// MJCF (robot/mjcf.h) and the simulation (sim/) are made from it.
//
// Frame: x forward, y left, z up; origin at the trunk centre of the hexapod.
#pragma once

#include <string>
#include <vector>

#include "robot/body_params.h"
#include "robot/morphology.h"

namespace multicpg::robot {

// A box of the trunk. trunk[0] is the root body (free joint); trunk[1], if any, is the front
// box hinged to it by the backbone.
struct TrunkBox {
  std::string name;
  double x_centre;  // m, in the trunk frame
  double length;    // m, along x
  double mass;      // kg, without the shoulders fixed to it
};

// An lpzrobots capsule: radius and cylinder length (caps not included), and its mass.
struct Capsule {
  double radius;  // m
  double length;  // m
  double mass;    // kg
};

// The segments of one leg, trunk outward (docs/robots.md "Segments"). The shoulder is rigidly
// fixed to the trunk; the foot slides along the tibia on a spring.
struct LegSegments {
  Capsule shoulder, coxa, femur, tibia, foot;
};

// A compliant velocity servo (docs/robots.md "Servos"): commanded velocity
// gain * (target - angle), capped at max_velocity; torque capped at
// power * tanh(|2 error / (max - min)| + damp).
struct ServoSpec {
  double max_velocity;  // rad/s
  double gain;          // 1/s
  double power;         // N m
  double damp;          // added to the tanh argument
  double armature;      // kg m^2, rotor inertia reflected through the gearbox (docs/robots.md)
  // N m s/rad: the velocity loop's torque per unit velocity error, power / max_velocity (a DC
  // motor's stall torque over its no-load speed; sim/servo.h, docs/robots.md).
  double loop_gain;
};

// The sprung foot (docs/robots.md "Foot spring"): a slider along the tibia, pushed outward
// against its stop by a preloaded spring.
struct FootSpring {
  double stiffness;       // N/m
  double damping;         // N s/m
  double travel;          // m, from the outer stop inward
  double preload_length;  // m, spring compression at the outer stop (force = stiffness * this)
};

// Where a leg hangs on the trunk.
struct LegMount {
  std::size_t trunk_part;  // index into RobotBody::trunk
  double x;                // m, leg root in the trunk frame
  double side;             // +1 left (leg points +y), -1 right
};

struct RobotBody {
  Morphology morphology;
  double trunk_width;   // m
  double trunk_height;  // m
  std::vector<TrunkBox> trunk;
  std::size_t yaw_part;   // trunk box carrying the orientation (yaw) sensor: the front one
  double backbone_x;      // m, hinge between trunk[0] and trunk[1] (only with two boxes)
  double backbone_limit;  // rad, +- range of the backbone hinge
  ServoSpec backbone_servo;
  double leg_root_y;             // m, |y| of every leg root (the trunk side)
  double leg_root_z;             // m, z of every leg root (the trunk top)
  std::vector<LegMount> mounts;  // one per leg, in morphology order
  LegSegments segments;
  ServoSpec tc_servo, ctr_servo, fti_servo;
  FootSpring foot;
  double contact_sensor_radius;  // m, foot contact sensor sphere
  // Ground contacts (BodyParams; docs/robots.md "Body parameters").
  double foot_friction;       // Coulomb friction of the feet and tibiae against the ground
  double trunk_friction;      // and of the trunk boxes
  double slip;                // m/s per N of tangential force on one contact
  double torsional_friction;  // m; 0 = none
  double rolling_friction;    // m; 0 = none
  // Passive coupling between each leg servo and its segment: rad per N m (0 = rigid), and its
  // damping (N m s/rad).
  double joint_compliance;
  double coupling_damping;
};

// The description of a robot as the paper's simulator has it: the hexapod AMOSII v2, the quadruped
// AmosFour (docs/robots.md "Geometry and masses") or the octopod (the hexapod's leg design, four
// legs a side).
const RobotBody& robot_body(RobotKind kind);

// The same robot with the physical parameters `params` (validate()d): masses, friction, slip,
// joint compliance and leg servos. Only the hexapod's trunk is `params.trunk_mass`; the other
// trunks keep its density, and every leg weighs (total_mass - trunk_mass) / 6.
RobotBody robot_body(RobotKind kind, const BodyParams& params);

// Sum of every part's mass, kg.
double total_mass(const RobotBody& body);

}  // namespace multicpg::robot
