#include "apps/sim_flags.h"

#include <algorithm>
#include <array>

#include "apps/flag_checks.h"
#include "common/errors.h"

namespace multicpg::apps {
namespace {

// One numeric body flag: its BodyParams member, range and help.
struct NumberFlag {
  const char* flag;
  const char* key;  // the BodyParams key it sets
  std::optional<double> BodyFlags::*given;
  double robot::BodyParams::*param;
  Limits<double> limits;
  const char* help;
};

const std::array<NumberFlag, 11> kNumberFlags{{
    {"--lift-body", "lift_body", &BodyFlags::lift_body, &robot::BodyParams::lift_body,
     robot::kLiftBodyLimits,
     "degrees taken off the CTr window and added to the FTi window, so the legs hold the body "
     "higher (docs/robots.md Body parameters, the real-robot controller: 5; paper-sim 0)"},
    {"--total-mass", "total_mass", &BodyFlags::total_mass, &robot::BodyParams::total_mass,
     robot::kTotalMassLimits,
     "hexapod mass in kg; the legs share what the trunk leaves (paper-sim 7.85, real 5.758)"},
    {"--trunk-mass", "trunk_mass", &BodyFlags::trunk_mass, &robot::BodyParams::trunk_mass,
     robot::kTrunkMassLimits, "hexapod trunk mass in kg (paper-sim 3.0, real 2.2)"},
    {"--foot-friction", "foot_friction", &BodyFlags::foot_friction,
     &robot::BodyParams::foot_friction, robot::kFrictionLimits,
     "Coulomb friction of the feet and tibiae on the ground (docs/robots.md Contacts and "
     "materials: 2.4)"},
    {"--trunk-friction", "trunk_friction", &BodyFlags::trunk_friction,
     &robot::BodyParams::trunk_friction, robot::kFrictionLimits,
     "Coulomb friction of the trunk on the ground (docs/robots.md Contacts and materials: 2.4)"},
    {"--slip", "slip", &BodyFlags::slip, &robot::BodyParams::slip, robot::kSlipLimits,
     "tangential slip of every contact in m/s per N (paper-sim: MuJoCo's own at a foot, 0.0051; "
     "lpzrobots and real: 0.01)"},
    {"--joint-compliance", "joint_compliance", &BodyFlags::joint_compliance,
     &robot::BodyParams::joint_compliance, robot::kJointComplianceLimits,
     "give of each joint's passive coupling in rad per N m (0: rigid, paper-sim)"},
    {"--torsional-friction", "torsional_friction", &BodyFlags::torsional_friction,
     &robot::BodyParams::torsional_friction, robot::kTorsionalFrictionLimits,
     "torsional friction of the ground contacts in m (0: none, paper-sim)"},
    {"--rolling-friction", "rolling_friction", &BodyFlags::rolling_friction,
     &robot::BodyParams::rolling_friction, robot::kRollingFrictionLimits,
     "rolling friction of the ground contacts in m (0: none, paper-sim)"},
    {"--servo-torque", "servo_torque", &BodyFlags::servo_torque, &robot::BodyParams::servo_torque,
     robot::kServoTorqueLimits,
     "stall torque of every leg servo in N m (docs/robots.md Servos: 26.75)"},
    {"--servo-speed", "servo_speed", &BodyFlags::servo_speed, &robot::BodyParams::servo_speed,
     robot::kServoSpeedLimits,
     "no-load speed of every leg servo in rad/s (docs/robots.md Servos: 10.47)"},
}};

constexpr const char* kDisabledPostureFlag = "--disabled-posture";
constexpr const char* kLegPostureFlag = "--leg-posture";

// "0,0.7,-0.7": three commands in [-1, 1]; an empty field is unset when `partial`.
std::optional<std::array<std::optional<double>, 3>> parse_triple(const std::string& text,
                                                                 bool partial, std::string& error) {
  std::vector<std::string> fields{""};
  for (char c : text) {
    if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  std::array<std::optional<double>, 3> out;
  if (fields.size() != out.size()) {
    error = "takes three commands TC,CTr,FTi in " + robot::kPostureLimits.text() + ", got '" +
            text + "'";
    return std::nullopt;
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (fields[i].empty()) {
      if (partial) continue;
      error = "needs all three commands TC,CTr,FTi, got '" + text + "'";
      return std::nullopt;
    }
    double v = 0.0;
    if (!CLI::detail::lexical_cast(fields[i], v) || !robot::kPostureLimits.contains(v)) {
      error = "'" + fields[i] + "' is not a command in " + robot::kPostureLimits.text();
      return std::nullopt;
    }
    out[i] = v;
  }
  return out;
}

// "R3=,,-0.55" -> leg and the joints it sets.
std::optional<robot::LegPostureOverride> parse_leg_posture(const std::string& text,
                                                           std::string& error) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    error =
        "takes LEG=TC,CTr,FTi (an empty command keeps the --disabled-posture one), e.g. "
        "R3=,,-0.55; got '" +
        text + "'";
    return std::nullopt;
  }
  const auto triple = parse_triple(text.substr(eq + 1), /*partial=*/true, error);
  if (!triple) return std::nullopt;
  return robot::LegPostureOverride{text.substr(0, eq), (*triple)[0], (*triple)[1], (*triple)[2]};
}

CLI::Validator posture_value(bool per_leg) {
  return CLI::Validator(
      [per_leg](std::string& text) -> std::string {
        std::string error;
        if (per_leg) {
          parse_leg_posture(text, error);
        } else {
          parse_triple(text, /*partial=*/false, error);
        }
        return error;
      },
      per_leg ? "LEG=TC,CTr,FTi" : "TC,CTr,FTi");
}

CLI::Validator terrain_value() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          robot::parse_terrain(text);
        } catch (const BadInput& e) {
          return e.what();
        }
        return {};
      },
      "TERRAIN");
}

}  // namespace

std::string sim_flag(const std::string& key) {
  const std::string body = "body.";
  if (key.rfind(body, 0) == 0) {
    const std::string rest = key.substr(body.size());
    if (rest.rfind("disabled_posture", 0) == 0) return kDisabledPostureFlag;
    if (rest.rfind("leg_postures", 0) == 0) return kLegPostureFlag;
    for (const NumberFlag& f : kNumberFlags) {
      if (rest == f.key) return f.flag;
    }
  }
  std::string flag = "--" + key;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

void add_sim_flags(CLI::App& cmd, sim::SimOptions& o, BodyFlags& body, bool with_servo) {
  cmd.add_option("--control-dt", o.control_dt,
                 "simulated seconds per controller step (paper: 0.037 s, 27 Hz)")
      ->check(in(sim::kControlDtLimits))
      ->capture_default_str();
  cmd.add_option("--physics-dt", o.physics_dt,
                 "MuJoCo time step in seconds (0, the default: the largest step <= 0.005 s that "
                 "divides --control-dt, 0.004625 s for 0.037 s); --control-dt must be a whole "
                 "multiple of it (relative tolerance 1e-6)")
      ->check(in(sim::kPhysicsDtLimits));
  cmd.add_option_function<std::string>(
         "--terrain",
         [&o](const std::string& text) { o.scene.terrain = robot::parse_terrain(text); },
         "the ground: flat, slope:DEG[:HEADING_DEG] (0..30 deg, heading 0 = uphill ahead), "
         "rough:HEIGHT_M[:SEED] (bumps up to 0.001..0.05 m), steps:HEIGHT_M:DEPTH_M; the tunnel "
         "stands on it (docs/faults.md)")
      ->check(terrain_value())
      ->default_str("flat");
  if (with_servo) {
    cmd.add_option("--servo-gain", o.servo_gain,
                   "servo gain K in 1/s (0, the default: lpzrobots' 5.24 1/s at its 0.1 s "
                   "step, scaled to --control-dt: 14.15 1/s at 0.037 s)")
        ->check(in(sim::kServoGainLimits));
  }
  add_body_flags(cmd, body);
}

void add_body_flags(CLI::App& cmd, BodyFlags& body) {
  std::string models;
  for (robot::BodyModel m : robot::kBodyModels) {
    models += (models.empty() ? "" : ", ") + std::string(robot::to_string(m));
  }
  cmd.add_option("--model", body.model,
                 "body model: " + models +
                     " (multicpg model --list shows their values); the Body flags override it")
      ->check(one_of(robot::kBodyModelNames.names(), "body model"))
      ->capture_default_str();
  CLI::Option_group* group = cmd.add_option_group(
      "Body", "physical parameters, each over the --model's value (docs/robots.md)");
  group
      ->add_option(kDisabledPostureFlag, body.disabled_posture,
                   "TC,CTr,FTi commands a disabled leg holds, each in -1..1 (docs/robots.md Body "
                   "parameters: "
                   "0,0.7,-0.7)")
      ->check(posture_value(/*per_leg=*/false));
  group
      ->add_option(kLegPostureFlag, body.leg_postures,
                   "LEG=TC,CTr,FTi: one disabled leg's own posture, an empty command keeping "
                   "--disabled-posture's (docs/robots.md Body parameters, the real robot: "
                   "R3=,,-0.55); repeatable")
      ->check(posture_value(/*per_leg=*/true));
  for (const NumberFlag& f : kNumberFlags) {
    group->add_option(f.flag, body.*f.given, f.help)->check(in(f.limits));
  }
}

sim::SimOptions with_body(const sim::SimOptions& options, const BodyFlags& body) {
  sim::SimOptions out = options;
  out.model = robot::parse_body_model(body.model);
  out.body = robot::body_params(out.model);
  std::string error;
  if (body.disabled_posture) {
    const auto triple = parse_triple(*body.disabled_posture, /*partial=*/false, error);
    if (!triple) throw BadInput(std::string(kDisabledPostureFlag) + " " + error);
    out.body.disabled_posture = {*(*triple)[0], *(*triple)[1], *(*triple)[2]};
  }
  if (!body.leg_postures.empty()) out.body.leg_postures.clear();
  for (const std::string& text : body.leg_postures) {
    const auto posture = parse_leg_posture(text, error);
    if (!posture) throw BadInput(std::string(kLegPostureFlag) + " " + error);
    out.body.leg_postures.push_back(*posture);
  }
  for (const NumberFlag& f : kNumberFlags) {
    if (body.*f.given) out.body.*f.param = *(body.*f.given);
  }
  return out;
}

sim::SimOptions sim_options(const sim::SimOptions& options, const BodyFlags& body,
                            robot::RobotKind kind) {
  sim::SimOptions out = with_body(options, body);
  try {
    sim::validate(out, kind);
  } catch (const OptionError& e) {
    throw BadInput(sim_flag(e.key()) + " " + e.what());
  }
  return out;
}

sim::SimOptions sim_options(const sim::SimOptions& options) {
  try {
    sim::validate(options);
  } catch (const OptionError& e) {
    // The flag bound to the key, so the message names what the user typed.
    throw BadInput(sim_flag(e.key()) + " " + e.what());
  }
  return options;
}

}  // namespace multicpg::apps
