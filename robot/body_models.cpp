#include "robot/body_models.h"

#include <string>

#include "common/errors.h"

namespace multicpg::robot {
namespace {

// --- The real AMOSII (paper §5), documented values only; calibration replaces them ---
// Reference §6.1 "Mass budget": lpzrobots scales the real robot's 5.758 kg with its 2.2 kg trunk.
constexpr double kRealTotalMass = 5.758;  // kg
constexpr double kRealTrunkMass = 2.2;    // kg
// Reference §4.4: the real-robot controller S2 lifts the body by 5 deg (lift_body_up).
constexpr double kRealLiftBody = 5.0;  // deg
// Reference §6.1 "Materials": lpzrobots' force-dependent slip of the ground, 0.01 m/s per N.
constexpr double kRealSlip = 0.01;  // m/s per N

struct Source {
  std::string_view key;
  std::string_view unit;
  std::string_view paper_sim;
  std::string_view real;
};

constexpr std::string_view kAsPaperSim = "as paper-sim (not calibrated yet)";

constexpr Source kSources[] = {
    {"disabled_posture", "TC,CTr,FTi", "reference §4.4 (disabled leg: TC 0, CTr 0.7, FTi -0.7)",
     kAsPaperSim},
    {"leg_postures", "", "reference §4.4 (every leg alike)", kAsPaperSim},
    {"lift_body", "deg", "reference §4.4 (the simulation controller S1 does not lift)",
     "reference §4.4 (real-robot controller S2: lift_body_up 5 deg)"},
    {"total_mass", "kg", "reference §6.1 Mass budget (5.758 / 2.2 x 3.0 kg)",
     "reference §6.1 Mass budget (the real robot: 5.758 kg)"},
    {"trunk_mass", "kg", "reference §6.1 Trunk (3.0 kg)",
     "reference §6.1 Mass budget (the real robot's trunk: 2.2 kg)"},
    {"foot_friction", "", "reference §6.1 Materials (roughness 3.0 x 0.8)", kAsPaperSim},
    {"trunk_friction", "", "reference §6.1 Materials (roughness 3.0 x 0.8)", kAsPaperSim},
    {"slip", "m/s/N", "docs/robots.md Body parameters (MuJoCo's own creep at a foot)",
     "reference §6.1 Materials (lpzrobots slip 0.01 m/s per N)"},
    {"joint_compliance", "rad/Nm", "reference §6.1 (rigid ODE hinges)", kAsPaperSim},
    {"torsional_friction", "m", "reference §6.1 Materials (dContactApprox1: none)", kAsPaperSim},
    {"rolling_friction", "m", "reference §6.1 Materials (dContactApprox1: none)", kAsPaperSim},
    {"servo_torque", "N m", "reference §6.1 Servos (coxaPower 26.75 N m)", kAsPaperSim},
    {"servo_speed", "rad/s", "reference §6.1 Servos (maxVel 10.47 rad/s)", kAsPaperSim},
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
    p.slip = kRealSlip;
  }
  return p;
}

std::string_view describe(BodyModel model) {
  switch (model) {
    case BodyModel::paper_sim:
      return "the paper's simulator, lpzrobots AMOSII v2 (reference §6.1); the default";
    case BodyModel::real:
      return "the real AMOSII of paper §5: its documented values only, the starting point that "
             "calibration against Table 1 will replace";
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
