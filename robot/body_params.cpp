#include "robot/body_params.h"

#include <fmt/format.h>

#include <set>

#include "common/errors.h"
#include "robot/leg_sets.h"

namespace multicpg::robot {
namespace {

std::string indexed(const std::string& key, std::size_t i) {
  return fmt::format("leg_postures[{}].{}", i, key);
}

void require_posture(const std::string& prefix, const LegPosture& p) {
  require_in(prefix + "tc", p.tc, kPostureLimits);
  require_in(prefix + "ctr", p.ctr, kPostureLimits);
  require_in(prefix + "fti", p.fti, kPostureLimits);
}

}  // namespace

void validate(const BodyParams& p) {
  require_posture("disabled_posture.", p.disabled_posture);
  for (std::size_t i = 0; i < p.leg_postures.size(); ++i) {
    const LegPostureOverride& o = p.leg_postures[i];
    if (o.leg.empty()) throw OptionError(indexed("leg", i), "must name a leg, e.g. \"R3\"");
    if (o.tc) require_in(indexed("tc", i), *o.tc, kPostureLimits);
    if (o.ctr) require_in(indexed("ctr", i), *o.ctr, kPostureLimits);
    if (o.fti) require_in(indexed("fti", i), *o.fti, kPostureLimits);
  }
  require_in("lift_body", p.lift_body, kLiftBodyLimits);
  require_in("total_mass", p.total_mass, kTotalMassLimits);
  require_in("trunk_mass", p.trunk_mass, kTrunkMassLimits);
  if (p.total_mass - p.trunk_mass < kMinLegsMass) {
    throw OptionError("trunk_mass",
                      fmt::format("must leave the legs at least {} kg of total_mass {}, got {}",
                                  kMinLegsMass, p.total_mass, p.trunk_mass));
  }
  require_in("foot_friction", p.foot_friction, kFrictionLimits);
  require_in("trunk_friction", p.trunk_friction, kFrictionLimits);
  require_in("slip", p.slip, kSlipLimits);
  require_in("joint_compliance", p.joint_compliance, kJointComplianceLimits);
  require_in("torsional_friction", p.torsional_friction, kTorsionalFrictionLimits);
  require_in("rolling_friction", p.rolling_friction, kRollingFrictionLimits);
  require_in("servo_torque", p.servo_torque, kServoTorqueLimits);
  require_in("servo_speed", p.servo_speed, kServoSpeedLimits);
}

namespace {

template <double BodyParams::*M>
constexpr NumberParam top_level(std::string_view key, Limits<double> limits) {
  return {key, limits, [](const BodyParams& p) { return p.*M; },
          [](BodyParams& p, double v) { p.*M = v; }};
}

template <double LegPosture::*M>
constexpr NumberParam posture_joint(std::string_view key) {
  return {key, kPostureLimits, [](const BodyParams& p) { return p.disabled_posture.*M; },
          [](BodyParams& p, double v) { p.disabled_posture.*M = v; }};
}

constexpr NumberParam kNumberParams[] = {
    posture_joint<&LegPosture::tc>("disabled_posture.tc"),
    posture_joint<&LegPosture::ctr>("disabled_posture.ctr"),
    posture_joint<&LegPosture::fti>("disabled_posture.fti"),
    top_level<&BodyParams::lift_body>("lift_body", kLiftBodyLimits),
    top_level<&BodyParams::total_mass>("total_mass", kTotalMassLimits),
    top_level<&BodyParams::trunk_mass>("trunk_mass", kTrunkMassLimits),
    top_level<&BodyParams::foot_friction>("foot_friction", kFrictionLimits),
    top_level<&BodyParams::trunk_friction>("trunk_friction", kFrictionLimits),
    top_level<&BodyParams::slip>("slip", kSlipLimits),
    top_level<&BodyParams::joint_compliance>("joint_compliance", kJointComplianceLimits),
    top_level<&BodyParams::torsional_friction>("torsional_friction", kTorsionalFrictionLimits),
    top_level<&BodyParams::rolling_friction>("rolling_friction", kRollingFrictionLimits),
    top_level<&BodyParams::servo_torque>("servo_torque", kServoTorqueLimits),
    top_level<&BodyParams::servo_speed>("servo_speed", kServoSpeedLimits),
};

}  // namespace

std::span<const NumberParam> number_params() {
  return kNumberParams;
}

const NumberParam& number_param(std::string_view key) {
  std::string known;
  for (const NumberParam& p : number_params()) {
    if (p.key == key) return p;
    known += (known.empty() ? "" : ", ") + std::string(p.key);
  }
  throw BadInput("no body parameter '" + std::string(key) + "' (known: " + known + ")");
}

std::vector<LegPosture> disabled_postures(const BodyParams& params, const Morphology& morph) {
  std::vector<LegPosture> out(morph.size(), params.disabled_posture);
  std::set<std::size_t> seen;
  for (std::size_t i = 0; i < params.leg_postures.size(); ++i) {
    const LegPostureOverride& o = params.leg_postures[i];
    std::size_t leg = 0;
    try {
      leg = parse_leg(morph, o.leg);
    } catch (const BadInput& e) {
      throw OptionError(indexed("leg", i), e.what());
    }
    if (!seen.insert(leg).second) {
      throw OptionError(indexed("leg", i), "names " + o.leg + " a second time");
    }
    LegPosture& p = out[leg];
    p.tc = o.tc.value_or(p.tc);
    p.ctr = o.ctr.value_or(p.ctr);
    p.fti = o.fti.value_or(p.fti);
  }
  return out;
}

}  // namespace multicpg::robot
