// The physical parameters of the body (robot/body_params.h) and the named models
// (robot/body_models.h) on the real MuJoCo model: masses, the slip measured as lpzrobots
// states it (m/s per N on one contact), compliant joints, torsional and rolling friction, ranges.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/errors.h"
#include "neural/controller.h"
#include "robot/body_models.h"
#include "sim/sim.h"
#include "sim/walk.h"

namespace {

using namespace multicpg;
using robot::RobotKind;

double model_mass(const sim::SimModel& model) {
  return mj_getTotalmass(model.mj.get());
}

sim::SimOptions with_body(const robot::BodyParams& body) {
  sim::SimOptions o;
  o.body = body;
  return o;
}

TEST(BodyParams, DefaultsAreThePaperSimulatorsBody) {
  const sim::SimOptions defaults;
  EXPECT_EQ(defaults.model, robot::BodyModel::paper_sim);
  EXPECT_EQ(sim::model_xml(RobotKind::hexapod, defaults),
            sim::model_xml(RobotKind::hexapod,
                           with_body(robot::body_params(robot::BodyModel::paper_sim))));
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod);
  EXPECT_NEAR(model_mass(model), 7.8518, 1e-4);  // docs/robots.md
  EXPECT_EQ(model.mj->opt.impratio, 1.0);        // MuJoCo's own contact, unchanged
  EXPECT_EQ(model.mj->pair_dim[0], 3);
}

TEST(BodyParams, MassesGoToTrunkAndLegs) {
  const robot::BodyParams real = robot::body_params(robot::BodyModel::real);
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod, with_body(real));
  EXPECT_NEAR(model_mass(model), 5.758, 1e-9);
  const robot::RobotBody& b = model.body;
  EXPECT_NEAR(b.trunk[0].mass + b.trunk[1].mass, 2.2, 1e-12);
  // The legs share the rest as the simulator does: four equal segments and a lighter foot.
  const robot::LegSegments& s = b.segments;
  EXPECT_NEAR(6.0 * (s.shoulder.mass + s.coxa.mass + s.femur.mass + s.tibia.mass + s.foot.mass),
              5.758 - 2.2, 1e-12);
  EXPECT_NEAR(s.foot.mass / s.tibia.mass, 0.040432 / 0.19205, 1e-12);
}

// The hexapod standing still on all six feet (every leg "disabled" in the stance posture of its
// start pose, legs straight out) pushed sideways at its trunk: after the legs have given, every
// foot creeps at the same speed, each carrying a sixth of the push, so the slip per contact is
// 6 v / F.
double measured_slip(robot::BodyParams body, double push_n) {
  body.disabled_posture = {0.0, 0.5985, -0.9114};  // CTr and FTi of the start pose
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod, with_body(body));
  sim::SimState state = sim::make_sim_state(model);
  for (std::size_t leg = 0; leg < 6; ++leg) neural::set_disabled(state.controller, leg, true);
  constexpr long kStand = 100;  // the robot settles on its feet
  constexpr long kGive = 100;   // the legs give under the push
  constexpr long kMeasure = 200;
  for (long t = 0; t < kStand; ++t) sim::sim_step(model, state);
  const int trunk = mj_name2id(model.mj.get(), mjOBJ_BODY, "trunk");
  state.data->xfrc_applied[6 * trunk + 1] = push_n;
  for (long t = 0; t < kGive; ++t) sim::sim_step(model, state);
  const double y0 = sim::trunk_position(model, state).y;
  const double t0 = state.data->time;
  for (long t = 0; t < kMeasure; ++t) sim::sim_step(model, state);
  const double speed = (sim::trunk_position(model, state).y - y0) / (state.data->time - t0);
  for (std::size_t leg = 0; leg < 6; ++leg) EXPECT_TRUE(sim::foot_contact(model, state, leg));
  return 6.0 * speed / push_n;
}

// docs/robots.md "Body parameters": MuJoCo's creep is proportional to 1 / impratio, and the slip
// parameter is that creep, in m/s per N on one contact as lpzrobots states it.
TEST(BodyParams, SlipIsTheCreepPerNewtonOfOneFoot) {
  constexpr double kPush = 6.0;  // N: 1 N per foot, far inside the friction cone (mu 2.4)
  for (double slip : {robot::kMujocoFootSlip, 0.01, 0.03}) {
    robot::BodyParams body;
    body.slip = slip;
    const double measured = measured_slip(body, kPush);
    EXPECT_NEAR(measured, slip, 0.1 * slip) << "slip " << slip;
  }
}

TEST(BodyParams, CompliantJointsGiveUnderLoadAndStayStable) {
  robot::BodyParams body;
  body.joint_compliance = robot::kJointComplianceLimits.hi;
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod, with_body(body));
  ASSERT_GE(mj_name2id(model.mj.get(), mjOBJ_JOINT, "R1_CTr_coupling"), 0);
  EXPECT_EQ(model.mj->nq, sim::make_sim_model(RobotKind::hexapod).mj->nq + 18);
  sim::WalkSpec spec;
  spec.steps = 400;
  const sim::WalkResult r = sim::walk(model, spec);  // throws if the physics blew up
  EXPECT_GT(r.distance_m, 0.05);
  // A standing leg's segment sags below its servo's angle: the coupling gives under the weight.
  const sim::JointSlot& ctr = model.legs[1].joints[1];
  const double give = r.final_state.data->qpos[ctr.coupling_qpos];
  EXPECT_NE(give, 0.0);
  EXPECT_EQ(sim::joint_angle(model, r.final_state, 1, robot::Joint::CTr),
            r.final_state.data->qpos[ctr.qpos] + give);
  // The stiffest coupling in range walks too.
  body.joint_compliance = 0.005;
  EXPECT_NO_THROW(sim::walk(sim::make_sim_model(RobotKind::hexapod, with_body(body)), spec));
}

TEST(BodyParams, TorsionalAndRollingFrictionActivateTheirContactDimensions) {
  robot::BodyParams body;
  body.torsional_friction = 0.005;
  const sim::SimModel torsional = sim::make_sim_model(RobotKind::hexapod, with_body(body));
  EXPECT_EQ(torsional.mj->pair_dim[0], 4);
  EXPECT_EQ(torsional.mj->pair_friction[2], 0.005);
  body.rolling_friction = 0.001;
  const sim::SimModel rolling = sim::make_sim_model(RobotKind::hexapod, with_body(body));
  EXPECT_EQ(rolling.mj->pair_dim[0], 6);
  EXPECT_EQ(rolling.mj->pair_friction[3], 0.001);
}

TEST(BodyParams, FrictionOfFeetAndTrunkAndTheServos) {
  robot::BodyParams body;
  body.foot_friction = 0.8;
  body.trunk_friction = 0.5;
  body.servo_torque = 5.0;
  body.servo_speed = 7.0;
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod, with_body(body));
  const mjModel* m = model.mj.get();
  for (int p = 0; p < m->npair; ++p) {
    const std::string geom = mj_id2name(m, mjOBJ_GEOM, m->pair_geom2[p]);
    const bool trunk = geom == "trunk" || geom == "front_trunk";
    EXPECT_EQ(m->pair_friction[5 * p], trunk ? 0.5 : 0.8) << geom;
  }
  const sim::ServoModel& s = model.legs[0].joints[0].servo;
  EXPECT_EQ(s.spec.power, 5.0);
  EXPECT_EQ(s.spec.max_velocity, 7.0);
  EXPECT_EQ(s.spec.loop_gain, 5.0 / 7.0);
  EXPECT_EQ(m->actuator_ctrlrange[1], 5.0);
  EXPECT_EQ(model.backbone.front().servo.spec.power, 3.0 * robot::kSimServoTorque);
}

// Every parameter refuses a value outside its range, naming its key.
TEST(BodyParams, OutOfRangeValuesAreRefusedNamingTheKey) {
  struct Case {
    std::string key;
    void (*set)(robot::BodyParams&);
  };
  const std::vector<Case> cases{
      {"body.disabled_posture.ctr", [](robot::BodyParams& b) { b.disabled_posture.ctr = 1.2; }},
      {"body.leg_postures[0].fti",
       [](robot::BodyParams& b) {
         b.leg_postures = {{"R3", std::nullopt, std::nullopt, -1.5}};
       }},
      {"body.lift_body", [](robot::BodyParams& b) { b.lift_body = 30.0; }},
      {"body.total_mass", [](robot::BodyParams& b) { b.total_mass = 20.0; }},
      {"body.trunk_mass", [](robot::BodyParams& b) { b.trunk_mass = 0.5; }},
      {"body.trunk_mass",
       [](robot::BodyParams& b) {
         b.total_mass = 5.0;
         b.trunk_mass = 4.0;
       }},
      {"body.foot_friction", [](robot::BodyParams& b) { b.foot_friction = 0.0; }},
      {"body.trunk_friction", [](robot::BodyParams& b) { b.trunk_friction = 5.0; }},
      {"body.slip", [](robot::BodyParams& b) { b.slip = 0.0; }},
      {"body.joint_compliance", [](robot::BodyParams& b) { b.joint_compliance = -0.1; }},
      {"body.torsional_friction", [](robot::BodyParams& b) { b.torsional_friction = 0.1; }},
      {"body.rolling_friction", [](robot::BodyParams& b) { b.rolling_friction = -1.0; }},
      {"body.servo_torque", [](robot::BodyParams& b) { b.servo_torque = 100.0; }},
      {"body.servo_speed", [](robot::BodyParams& b) { b.servo_speed = NAN; }},
  };
  for (const Case& c : cases) {
    robot::BodyParams body;
    c.set(body);
    try {
      sim::validate(with_body(body));
      ADD_FAILURE() << c.key << " was taken";
    } catch (const OptionError& e) {
      EXPECT_EQ(e.key(), c.key);
    }
  }
  robot::BodyParams body;
  body.leg_postures = {{"R4", std::nullopt, 0.5, std::nullopt}};
  EXPECT_NO_THROW(sim::validate(with_body(body)));  // R4 is an octopod leg
  EXPECT_NO_THROW(sim::validate(with_body(body), RobotKind::octopod));
  try {
    sim::make_sim_model(RobotKind::hexapod, with_body(body));
    ADD_FAILURE() << "R4 taken on the hexapod";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "body.leg_postures[0].leg");
  }
}

}  // namespace
