// The robot descriptions, joint maps, servo law and MuJoCo models (docs/robots.md "Joint angles",
// "Servos", §6), and `multicpg model` accepted by MuJoCo's own compiler.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "common/errors.h"
#include "robot/body.h"
#include "robot/joint_map.h"
#include "sim/servo.h"
#include "sim/sim.h"
#include "tests/cli_runner.h"

namespace {

using namespace multicpg;
using robot::Joint;
using robot::LegType;
using robot::RobotKind;

constexpr double kDeg = std::numbers::pi / 180.0;

double model_mass(const mjModel* m) {
  return mj_getTotalmass(const_cast<mjModel*>(m));
}

TEST(RobotBody, MassesMatchReference) {
  // docs/robots.md "Mass budget": 7.8518 kg in all; the quadruped 5.397 kg.
  EXPECT_NEAR(robot::total_mass(robot::robot_body(RobotKind::hexapod)), 7.85, 0.01 * 7.85);
  EXPECT_NEAR(robot::total_mass(robot::robot_body(RobotKind::quadruped)), 5.40, 0.01 * 5.40);
  const robot::RobotBody& hex = robot::robot_body(RobotKind::hexapod);
  EXPECT_NEAR(hex.trunk[0].mass + hex.trunk[1].mass, 3.0, 1e-9);
  EXPECT_NEAR(hex.trunk[1].mass, 0.8372, 1e-4);
  // Octopod: two more legs and a trunk longer by one leg spacing, same densities.
  const double leg = (robot::total_mass(hex) - 3.0) / 6.0;
  const robot::RobotBody& oct = robot::robot_body(RobotKind::octopod);
  EXPECT_NEAR(robot::total_mass(oct), 3.0 * (0.43 + 0.15) / 0.43 + 8.0 * leg, 1e-9);
}

TEST(RobotBody, LegRoots) {
  const robot::RobotBody& hex = robot::robot_body(RobotKind::hexapod);
  const std::vector<double> x{0.175, 0.025, -0.165, 0.175, 0.025, -0.165};  // docs/robots.md
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(hex.mounts[i].x, x[i], 1e-12) << i;
    EXPECT_EQ(hex.mounts[i].side, i < 3 ? -1.0 : 1.0);
    EXPECT_EQ(hex.mounts[i].trunk_part, i % 3 == 0 ? 1u : 0u);  // front legs on the front box
  }
  const robot::RobotBody& quad = robot::robot_body(RobotKind::quadruped);
  ASSERT_EQ(quad.trunk.size(), 1u);
  EXPECT_NEAR(quad.mounts[0].x, 0.09, 1e-12);  // docs/robots.md "Leg roots"
  EXPECT_NEAR(quad.mounts[1].x, -0.10, 1e-12);
}

TEST(JointMap, ReferenceAngles) {
  // docs/robots.md "Joint angles", in the paper's convention: TC 70 deg m (front, hind), 60 deg m
  // (middle), CTr 75 deg m, FTi (55 m - 75) deg.
  EXPECT_NEAR(robot::joint_angle(LegType::front, Joint::TC, 0.5), 35.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_angle(LegType::hind, Joint::TC, -0.858), -60.06 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_angle(LegType::middle, Joint::TC, 0.334), 20.04 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_angle(LegType::front, Joint::CTr, 0.5985), 44.8875 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_angle(LegType::middle, Joint::FTi, -0.7), -113.5 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_angle(LegType::hind, Joint::FTi, 1.0), -20.0 * kDeg, 1e-12);
  // The servo clips its input to [-1, 1].
  EXPECT_NEAR(robot::joint_angle(LegType::front, Joint::CTr, 1.5), 75.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_angle(LegType::front, Joint::FTi, -1.0024), -130.0 * kDeg, 1e-12);
}

TEST(JointMap, Limits) {
  EXPECT_NEAR(robot::joint_limits(LegType::front, Joint::TC).hi, 70.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_limits(LegType::middle, Joint::TC).lo, -60.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_limits(LegType::hind, Joint::TC).lo, -70.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_limits(LegType::hind, Joint::CTr).hi, 75.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_limits(LegType::front, Joint::FTi).lo, -130.0 * kDeg, 1e-12);
  EXPECT_NEAR(robot::joint_limits(LegType::front, Joint::FTi).hi, -20.0 * kDeg, 1e-12);
}

TEST(Servo, CommandedVelocity) {
  const robot::ServoSpec& s = robot::robot_body(RobotKind::hexapod).ctr_servo;
  EXPECT_NEAR(s.max_velocity, 10.47, 0.01);  // docs/robots.md "Servos"
  EXPECT_NEAR(s.gain, 5.2366, 1e-4);
  EXPECT_NEAR(s.power, 26.75, 0.01);
  EXPECT_NEAR(sim::commanded_velocity(s, 0.1, 0.005), 0.52366, 1e-4);
  EXPECT_NEAR(sim::commanded_velocity(s, -3.0, 0.005), -s.max_velocity, 1e-12);  // capped
  EXPECT_NEAR(sim::commanded_velocity(s, 0.1, 1.0), 0.1, 1e-12);  // no overshoot in one step
}

TEST(Servo, TorqueLimitAndContinuity) {
  const robot::RobotBody& hex = robot::robot_body(RobotKind::hexapod);
  const sim::ServoModel ctr{hex.ctr_servo, 150.0 * kDeg};
  const sim::ServoModel fti{hex.fti_servo, 110.0 * kDeg};
  EXPECT_EQ(sim::torque_limit(ctr, 0.0), 0.0);  // compliant at the set point
  const double p = hex.ctr_servo.power;
  EXPECT_NEAR(sim::torque_limit(fti, 0.0), p * std::tanh(0.01), 1e-12);
  EXPECT_NEAR(sim::torque_limit(ctr, 2.0), p * std::tanh(4.0 / (150.0 * kDeg)), 1e-12);
  EXPECT_NEAR(hex.backbone_servo.power, 80.26, 0.01);
  // The velocity loop: Kv = P / maxVel, the torque clamped to fmax (docs/robots.md).
  const robot::ServoSpec& spec = hex.ctr_servo;
  EXPECT_NEAR(spec.loop_gain, p / spec.max_velocity, 1e-12);
  const double omega = sim::commanded_velocity(spec, 1.0, 0.005);
  EXPECT_NEAR(sim::servo_torque(ctr, 1.0, 0.0, omega, 0.005), 0.0, 1e-12);
  EXPECT_NEAR(sim::servo_torque(ctr, 1.0, 0.0, omega - 0.1, 0.005), 0.1 * spec.loop_gain, 1e-12);
  EXPECT_NEAR(sim::servo_torque(ctr, 1.0, 0.0, -5.0, 0.005), sim::torque_limit(ctr, 1.0), 1e-12);
  EXPECT_NEAR(sim::servo_torque(ctr, -1.0, 0.0, 5.0, 0.005), -sim::torque_limit(ctr, 1.0), 1e-12);
}

TEST(PhysicsStep, DefaultDividesControlStep) {
  EXPECT_DOUBLE_EQ(sim::default_physics_dt(0.037), 0.037 / 8);
  EXPECT_DOUBLE_EQ(sim::default_physics_dt(0.1), 0.005);
  EXPECT_DOUBLE_EQ(sim::default_physics_dt(0.002), 0.002);
  EXPECT_EQ(sim::physics_substeps(0.037, 0.004625), 8);
  EXPECT_EQ(sim::physics_substeps(0.1, 0.001), 100);
  EXPECT_THROW(sim::physics_substeps(0.037, 0.005), BadInput);
  EXPECT_THROW(sim::physics_substeps(0.037, 0.0), BadInput);
  EXPECT_THROW(sim::physics_substeps(0.0, 0.001), BadInput);
  EXPECT_THROW(sim::physics_substeps(0.001, 0.002), BadInput);
}

class Models : public ::testing::TestWithParam<RobotKind> {};

TEST_P(Models, CompilesWithMassLimitsAndSensors) {
  const sim::SimModel model = sim::make_sim_model(GetParam());
  const mjModel* m = model.mj.get();
  const robot::RobotBody& body = robot::robot_body(GetParam());
  EXPECT_NEAR(model_mass(m), robot::total_mass(body), 1e-6);
  const std::size_t legs = body.morphology.size();
  EXPECT_EQ(model.legs.size(), legs);
  EXPECT_EQ(model.backbone.size(), GetParam() == RobotKind::quadruped ? 0u : 1u);
  const std::size_t servos = 3 * legs + model.backbone.size();
  EXPECT_EQ(static_cast<std::size_t>(m->nu), servos);
  EXPECT_EQ(m->opt.integrator, mjINT_EULER);
  EXPECT_EQ(m->opt.timestep, 0.037 / 8);
  EXPECT_EQ(model.substeps, 8);
  for (std::size_t i = 0; i < legs; ++i) {
    const robot::Leg& leg = body.morphology.legs[i];
    for (Joint j : robot::kJoints) {
      const std::string name = leg.name + "_" + std::string(robot::to_string(j));
      const int id = mj_name2id(m, mjOBJ_JOINT, name.c_str());
      ASSERT_GE(id, 0) << name;
      EXPECT_TRUE(m->jnt_limited[id]) << name;
      EXPECT_NEAR(m->jnt_range[2 * id], robot::joint_limits(leg.type, j).lo, 1e-9) << name;
      EXPECT_NEAR(m->jnt_range[2 * id + 1], robot::joint_limits(leg.type, j).hi, 1e-9) << name;
    }
    for (const char* part : {"_coxa", "_femur", "_tibia", "_foot", "_shoulder"}) {
      EXPECT_GE(mj_name2id(m, mjOBJ_GEOM, (leg.name + part).c_str()), 0) << leg.name << part;
    }
    EXPECT_GE(model.legs[i].touch, 0);
  }
  EXPECT_GE(model.yaw_sensor, 0);
}

TEST_P(Models, StartsStandingOnItsFeet) {
  const sim::SimModel model = sim::make_sim_model(GetParam());
  const sim::SimState state = sim::make_sim_state(model);
  const mjModel* m = model.mj.get();
  const mjData* d = state.data.get();
  double lowest_foot = 1.0;
  for (const robot::Leg& leg : model.controller.morphology.legs) {
    const int site = mj_name2id(m, mjOBJ_SITE, (leg.name + "_foot").c_str());
    lowest_foot = std::min(lowest_foot, d->site_xpos[3 * site + 2]);
  }
  // The foot sphere (radius 15 mm) hangs at most the start clearance above the ground.
  EXPECT_NEAR(lowest_foot, 0.015, 0.0015);
  // The trunk clears the ground and faces +x.
  EXPECT_GT(sim::trunk_position(model, state).z, model.body.trunk_height / 2.0);
  EXPECT_NEAR(sim::trunk_yaw_deg(model, state), 0.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(AllRobots, Models,
                         ::testing::Values(RobotKind::hexapod, RobotKind::quadruped,
                                           RobotKind::octopod));

// Positive angles mean forward (TC), elevation (CTr) and extension (FTi) on both sides.
TEST(Model, JointSignsMatchThePaperOnBothSides) {
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod);
  const mjModel* m = model.mj.get();
  sim::SimState state = sim::make_sim_state(model);
  mjData* d = state.data.get();
  for (std::size_t leg : {0u, 3u}) {  // R1, L1
    const std::string name = model.controller.morphology.legs[leg].name;
    const int site = mj_name2id(m, mjOBJ_SITE, (name + "_foot").c_str());
    for (std::size_t j = 0; j < 3; ++j) {
      mj_resetDataKeyframe(m, d, model.start_key);
      mj_kinematics(m, d);
      const double x0 = d->site_xpos[3 * site];
      const double z0 = d->site_xpos[3 * site + 2];
      d->qpos[model.legs[leg].joints[j].qpos] += 0.1;
      mj_kinematics(m, d);
      if (j == 0) {
        EXPECT_GT(d->site_xpos[3 * site] - x0, 0.005) << name << " TC + moves the foot forward";
      } else {
        EXPECT_GT(d->site_xpos[3 * site + 2] - z0, 0.002) << name << " joint " << j << " + lifts";
      }
    }
  }
}

TEST(Model, TunnelHasWalls) {
  sim::SimOptions options;
  options.scene.tunnel = true;
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod, options);
  const mjModel* m = model.mj.get();
  const int left = mj_name2id(m, mjOBJ_GEOM, "wall_left");
  const int right = mj_name2id(m, mjOBJ_GEOM, "wall_right");
  ASSERT_GE(left, 0);
  ASSERT_GE(right, 0);
  // Inner faces 1.2 m apart, along x from 0 to 3 m (paper §5).
  const double inner = m->geom_pos[3 * left + 1] - m->geom_size[3 * left + 1];
  EXPECT_NEAR(inner, 0.6, 1e-9);
  EXPECT_NEAR(m->geom_pos[3 * right] + m->geom_size[3 * right], 3.0, 1e-9);
  EXPECT_LT(mj_name2id(sim::make_sim_model(RobotKind::hexapod).mj.get(), mjOBJ_GEOM, "wall_left"),
            0);
}

// The ground meets only its contact pairs (robot/mjcf.cpp), the walls any part of the robot: a
// femur pushed into the right wall touches it.
TEST(Model, WallsTouchAnyPartOfTheRobot) {
  sim::SimOptions options;
  options.scene.tunnel = true;
  const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod, options);
  const mjModel* m = model.mj.get();
  sim::SimState state = sim::make_sim_state(model);
  mjData* d = state.data.get();
  const int femur = mj_name2id(m, mjOBJ_GEOM, "R1_femur");
  const int wall = mj_name2id(m, mjOBJ_GEOM, "wall_right");
  ASSERT_GE(femur, 0);
  const double wall_face = m->geom_pos[3 * wall + 1] + m->geom_size[3 * wall + 1];
  d->qpos[model.root_qpos] = 1.0;  // inside the tunnel
  d->qpos[model.root_qpos + 1] += wall_face - d->geom_xpos[3 * femur + 1];
  mj_forward(m, d);
  bool touched = false;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    touched |= (c.geom1 == wall && c.geom2 == femur) || (c.geom1 == femur && c.geom2 == wall);
  }
  EXPECT_TRUE(touched);
}

TEST(CliModel, PrintsMjcfThatMujocoCompiles) {
  const std::string dir = multicpg::testing::make_temp_dir("model-");
  for (const std::string robot : {"hexapod", "quadruped", "octopod"}) {
    const std::string xml = dir + "/" + robot + ".xml";
    const std::string mjb = dir + "/" + robot + ".mjb";
    const auto r = multicpg::testing::run_cli("model --robot " + robot + " --out " + xml);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // mujoco-compile (libmujoco-samples) prints "Done" after saving, an error otherwise.
    const std::string cmd = "mujoco-compile " + xml + " " + mjb + " 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe) != nullptr) out += buf;
    ::pclose(pipe);
    EXPECT_NE(out.find("Done"), std::string::npos) << robot << ": " << out;
    EXPECT_EQ(out.find("rror"), std::string::npos) << robot << ": " << out;
    EXPECT_GT(std::filesystem::file_size(mjb), 0u) << robot;
  }
  const auto stdout_xml = multicpg::testing::run_cli("model --robot quadruped");
  ASSERT_EQ(stdout_xml.exit_code, 0);
  EXPECT_EQ(stdout_xml.out.rfind("<mujoco model=\"multicpg-quadruped\">", 0), 0u);
  std::filesystem::remove_all(dir);
}

}  // namespace
