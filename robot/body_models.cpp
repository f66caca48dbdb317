#include "robot/body_models.h"

#include <string>

#include "common/errors.h"

namespace multicpg::robot {
namespace {

// --- The real AMOSII (paper §5): its documented values, and the calibrated ones ---
// docs/robots.md "Mass budget": lpzrobots scales the real robot's 5.758 kg with its 2.2 kg trunk.
constexpr double kRealTotalMass = 5.758;  // kg
constexpr double kRealTrunkMass = 2.2;    // kg
// docs/controller.md "Motor mapping and joint windows": the authors' real-robot controller lifts
// the body by 5 deg (lift_body_up).
constexpr double kRealLiftBody = 5.0;  // deg
// Calibrated against paper §5 Table 1 before learning (`multicpg calibrate --budget 160`, the
// best of its 160 candidates whose fitted runs all ended at a wall, d0038; docs/fidelity.md
// "Calibration", docs/calibration/): the dead leg's commands, slip, foot friction, joint
// compliance and servo torque at the search's full precision, so its numbers are the model's.
constexpr LegPosture kRealDisabledPosture{-0.12907492042850777, 0.8942978086273929,
                                          -0.7515736633945004};
constexpr double kRealSlip = 0.020854414883038293;             // m/s per N
constexpr double kRealFootFriction = 0.7884815173552293;       // Coulomb
constexpr double kRealJointCompliance = 0.027727792409375836;  // rad per N m
constexpr double kRealServoTorque = 20.039045316913104;        // N m

struct Source {
  std::string_view key;
  std::string_view unit;
  std::string_view paper_sim;
  std::string_view real;
};

constexpr std::string_view kAsPaperSim = "as paper-sim (not searched by the calibration)";
constexpr std::string_view kCalibrated = "calibrated on Table 1 (docs/fidelity.md Calibration)";

constexpr Source kSources[] = {
    {"disabled_posture", "TC,CTr,FTi",
     "docs/robots.md Body parameters (disabled leg: TC 0, CTr 0.7, FTi -0.7)", kCalibrated},
    {"leg_postures", "", "docs/robots.md Body parameters (every leg alike)", kAsPaperSim},
    {"lift_body", "deg",
     "docs/robots.md Body parameters (the authors' simulation controller does not lift)",
     "docs/robots.md Body parameters (the authors' real-robot controller: lift_body_up 5 deg)"},
    {"total_mass", "kg", "docs/robots.md Geometry and masses (5.758 / 2.2 x 3.0 kg)",
     "docs/robots.md Geometry and masses (the real robot: 5.758 kg)"},
    {"trunk_mass", "kg", "docs/robots.md Geometry and masses (3.0 kg)",
     "docs/robots.md Geometry and masses (the real robot's trunk: 2.2 kg)"},
    {"foot_friction", "", "docs/robots.md Contacts and materials (roughness 3.0 x 0.8)",
     kCalibrated},
    {"trunk_friction", "", "docs/robots.md Contacts and materials (roughness 3.0 x 0.8)",
     kAsPaperSim},
    {"slip", "m/s/N", "docs/robots.md Body parameters (MuJoCo's own creep at a foot)", kCalibrated},
    {"joint_compliance", "rad/Nm", "docs/robots.md (rigid ODE hinges)", kCalibrated},
    {"torsional_friction", "m", "docs/robots.md Contacts and materials (dContactApprox1: none)",
     kAsPaperSim},
    {"rolling_friction", "m", "docs/robots.md Contacts and materials (dContactApprox1: none)",
     kAsPaperSim},
    {"servo_torque", "N m", "docs/robots.md Servos (coxaPower 26.75 N m)", kCalibrated},
    {"servo_speed", "rad/s", "docs/robots.md Servos (maxVel 10.47 rad/s)", kAsPaperSim},
};

}  // namespace

std::string_view to_string(BodyModel model) {
  switch (model) {
    case BodyModel::paper_sim:
      return "paper-sim";
    case BodyModel::real:
      return "real";
  }
  return "paper-sim";
}

BodyModel parse_body_model(std::string_view name) {
  std::string known;
  for (BodyModel m : kBodyModels) {
    if (to_string(m) == name) return m;
    known += (known.empty() ? "" : ", ") + std::string(to_string(m));
  }
  throw BadInput("no body model '" + std::string(name) + "' (known: " + known + ")");
}

BodyParams body_params(BodyModel model) {
  BodyParams p;
  if (model == BodyModel::real) {
    p.total_mass = kRealTotalMass;
    p.trunk_mass = kRealTrunkMass;
    p.lift_body = kRealLiftBody;
    p.disabled_posture = kRealDisabledPosture;
    p.slip = kRealSlip;
    p.foot_friction = kRealFootFriction;
    p.joint_compliance = kRealJointCompliance;
    p.servo_torque = kRealServoTorque;
  }
  return p;
}

std::string_view describe(BodyModel model) {
  switch (model) {
    case BodyModel::paper_sim:
      return "the paper's simulator, lpzrobots AMOSII v2 (docs/robots.md); the default";
    case BodyModel::real:
      return "the real AMOSII of paper §5: its documented masses and body lift, the rest "
             "calibrated against its Table 1 before learning (docs/fidelity.md)";
  }
  return "";
}

std::vector<std::string_view> parameter_keys() {
  std::vector<std::string_view> keys;
  for (const Source& s : kSources) keys.push_back(s.key);
  return keys;
}

std::string_view value_unit(std::string_view key) {
  for (const Source& s : kSources) {
    if (s.key == key) return s.unit;
  }
  return "";
}

std::string_view value_source(BodyModel model, std::string_view key) {
  for (const Source& s : kSources) {
    if (s.key == key) return model == BodyModel::real ? s.real : s.paper_sim;
  }
  return "";
}

}  // namespace multicpg::robot
