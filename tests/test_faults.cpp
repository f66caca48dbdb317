// Every fault kind on the real simulation (docs/faults.md): each changes what the physics does as
// its kind says, and its recovery undoes it exactly. Also the fault text and JSON round trips and
// the timeline's refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>

#include "body/course_json.h"
#include "body/fault_spec.h"
#include "common/errors.h"
#include "robot/terrain.h"
#include "sim/fault_effects.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace {

using namespace multicpg;
using robot::Joint;
using robot::RobotKind;

constexpr double kDeg = 180.0 / std::numbers::pi;

const sim::SimModel& hexapod() {
  static const sim::SimModel model = sim::make_sim_model(RobotKind::hexapod);
  return model;
}
const robot::Morphology& morph() {
  return hexapod().controller.morphology;
}

body::Fault fault(const std::string& text, bool recover = false) {
  return body::parse_fault(morph(), text, recover);
}

double actuator_force(const sim::Stepper& s, std::size_t leg, Joint joint) {
  const sim::JointSlot& slot = hexapod().legs[leg].joints[static_cast<std::size_t>(joint)];
  return s.state().data->actuator_force[slot.actuator];
}

double angle(const sim::Stepper& s, std::size_t leg, Joint joint) {
  return sim::joint_angle(hexapod(), s.state(), leg, joint);
}

TEST(Faults, ALockedJointStaysWithinADegreeOfItsLock) {
  const std::size_t r2 = robot::leg_index(morph(), "R2");
  sim::Stepper s(hexapod(), {}, {fault("R2.CTr:locked@100")});
  s.steps(100);
  s.step();  // the lock takes the angle the joint had before this step
  const double lock = angle(s, r2, Joint::CTr);
  double worst = 0.0;
  for (int i = 0; i < 1200; ++i) {
    s.step();
    worst = std::max(worst, std::abs(angle(s, r2, Joint::CTr) - lock));
    EXPECT_EQ(actuator_force(s, r2, Joint::CTr), 0.0) << "a seized servo drives nothing";
  }
  EXPECT_LT(worst * kDeg, 1.0);
  // The other joints of the leg still follow the controller.
  EXPECT_NE(actuator_force(s, r2, Joint::TC), 0.0);
}

TEST(Faults, ALockAtAGivenAngleHoldsThere) {
  const std::size_t r1 = robot::leg_index(morph(), "R1");
  sim::Stepper s(hexapod(), {}, {fault("R1.TC:locked=30@0")});
  s.steps(400);
  EXPECT_NEAR(angle(s, r1, Joint::TC) * kDeg, 30.0, 1.0);
  EXPECT_THROW(body::validate(morph(), {fault("R1.TC:locked=100@0")}), BadInput);  // past +-70
}

TEST(Faults, APassiveJointsMotorAppliesNoTorqueAndRecoveryRestoresIt) {
  const std::size_t r3 = robot::leg_index(morph(), "R3");
  sim::Stepper s(hexapod(), {}, {fault("R3.FTi:passive@0"), fault("R3.FTi:passive@400", true)});
  double moved = 0.0;
  const double start = angle(s, r3, Joint::FTi);
  for (int i = 0; i < 400; ++i) {
    s.step();
    EXPECT_EQ(actuator_force(s, r3, Joint::FTi), 0.0);
    moved = std::max(moved, std::abs(angle(s, r3, Joint::FTi) - start));
  }
  EXPECT_GT(moved * kDeg, 1.0) << "a free joint swings under the body's weight";
  s.step();
  EXPECT_NE(actuator_force(s, r3, Joint::FTi), 0.0);
}

TEST(Faults, AWeakMotorNeverExceedsItsScaledLimit) {
  const std::size_t l1 = robot::leg_index(morph(), "L1");
  // A motor at 5 %: walking asks the healthy one for more (its peak below), so the cap shows.
  constexpr double kFactor = 0.05;
  sim::Stepper weak(hexapod(), {}, {fault("L1:weak=0.05@0")});
  sim::Stepper strong(hexapod(), {}, {});
  const double limit = hexapod().legs[l1].joints[1].servo.spec.power;
  double weak_peak = 0.0;
  double strong_peak = 0.0;
  for (int i = 0; i < 800; ++i) {
    weak.step();
    strong.step();
    for (Joint j : robot::kJoints) {
      weak_peak = std::max(weak_peak, std::abs(actuator_force(weak, l1, j)));
      strong_peak = std::max(strong_peak, std::abs(actuator_force(strong, l1, j)));
    }
  }
  EXPECT_LE(weak_peak, kFactor * limit + 1e-12);
  EXPECT_GT(strong_peak, kFactor * limit)
      << "the test must reach the scaled limit to mean anything";
}

TEST(Faults, AShortTibiasFootIsWhereItsLengthSays) {
  const std::size_t r1 = robot::leg_index(morph(), "R1");
  const sim::LegSlots& slots = hexapod().legs[r1];
  const mjModel* shared = hexapod().mj.get();
  const double tibia = 2.0 * shared->geom_size[3 * slots.tibia_geom + 1];
  const auto foot_distance = [&](const mjModel* m) {  // FTi joint to the foot body, m
    return std::hypot(m->body_pos[3 * slots.foot_body], m->body_pos[3 * slots.foot_body + 1],
                      m->body_pos[3 * slots.foot_body + 2]);
  };
  sim::Stepper s(hexapod(), {}, {fault("R1:short=0.5@0"), fault("R1:short@200", true)});
  s.step();
  const mjModel* own = sim::physics_model(hexapod(), s.state());
  ASSERT_NE(own, shared);
  EXPECT_NEAR(foot_distance(shared) - foot_distance(own), 0.5 * tibia, 1e-12);
  EXPECT_NEAR(2.0 * own->geom_size[3 * slots.tibia_geom + 1], 0.5 * tibia, 1e-12);
  EXPECT_LT(own->body_mass[slots.tibia_body], shared->body_mass[slots.tibia_body]);
  // In the world: the foot's centre is as far from the FTi joint as the shortened tibia and the
  // foot's slide say (positions of this state, computed anew: mjData's are one physics step old).
  const std::unique_ptr<mjData, sim::MjDataDeleter> d(mj_makeData(own));
  mj_copyData(d.get(), own, s.state().data.get());
  mj_kinematics(own, d.get());
  const int fti = slots.joints[2].joint;
  const double* joint = d->xanchor + 3 * fti;
  const double* foot = d->xpos + 3 * slots.foot_body;
  const double slide = d->qpos[own->jnt_qposadr[fti] + 1];  // the foot's spring, + inward
  EXPECT_NEAR(std::hypot(foot[0] - joint[0], foot[1] - joint[1], foot[2] - joint[2]),
              foot_distance(own) - slide, 1e-9);
  s.steps(200);
  s.step();
  EXPECT_EQ(sim::physics_model(hexapod(), s.state()), shared) << "recovery: the model itself";
}

TEST(Faults, ASlipperyFootHasItsFrictionScaled) {
  const std::size_t l2 = robot::leg_index(morph(), "L2");
  const sim::LegSlots& slots = hexapod().legs[l2];
  sim::Stepper s(hexapod(), {}, {fault("L2:slip=0.2@0")});
  s.step();
  const mjModel* own = sim::physics_model(hexapod(), s.state());
  const mjModel* shared = hexapod().mj.get();
  for (int t = 0; t < 2; ++t) {
    EXPECT_DOUBLE_EQ(own->pair_friction[5 * slots.foot_pair + t],
                     0.2 * shared->pair_friction[5 * slots.foot_pair + t]);
  }
  EXPECT_EQ(own->pair_friction[5 * hexapod().legs[0].foot_pair],
            shared->pair_friction[5 * hexapod().legs[0].foot_pair]);
}

TEST(Faults, ImuDriftBendsTheSensedYawNotTheTrueOne) {
  constexpr double kRate = 0.5;  // deg/s
  constexpr long kSteps = 1000;
  sim::Stepper drifting(hexapod(), {}, {fault("imu:drift=0.5@0")});
  sim::Stepper healthy(hexapod(), {}, {});
  drifting.steps(kSteps);
  healthy.steps(kSteps);
  EXPECT_EQ(drifting.pose().yaw_deg, healthy.pose().yaw_deg) << "the true yaw does not drift";
  EXPECT_NEAR(drifting.sensed_pose().yaw_deg - drifting.pose().yaw_deg,
              kRate * kSteps * hexapod().control_dt, 1e-9);
  EXPECT_EQ(healthy.sensed_pose().yaw_deg, healthy.pose().yaw_deg);
}

TEST(Faults, ImuNoiseIsSeededAndItsRecoveryEndsIt) {
  const body::FaultTimeline noisy{fault("imu:noise=1@0"), fault("imu:noise@300", true)};
  sim::Stepper a(hexapod(), {{}, body::kControllerWarmup, 7}, noisy);
  sim::Stepper b(hexapod(), {{}, body::kControllerWarmup, 7}, noisy);
  sim::Stepper c(hexapod(), {{}, body::kControllerWarmup, 8}, noisy);
  double spread = 0.0;
  for (int i = 0; i < 300; ++i) {
    a.step();
    b.step();
    c.step();
    EXPECT_EQ(a.sensed_pose().yaw_deg, b.sensed_pose().yaw_deg);
    spread += std::pow(a.sensed_pose().yaw_deg - a.pose().yaw_deg, 2);
  }
  EXPECT_NE(a.sensed_pose().yaw_deg, c.sensed_pose().yaw_deg) << "another seed, other draws";
  EXPECT_NEAR(std::sqrt(spread / 300.0), 1.0, 0.2);
  a.step();
  EXPECT_EQ(a.sensed_pose().yaw_deg, a.pose().yaw_deg);
}

TEST(Faults, RecoveryRestoresThePhysicsExactly) {
  // A run whose faults all recovered walks on exactly as the same robot that never had them,
  // once both start from the same state.
  sim::Stepper faulty(
      hexapod(), {},
      {fault("R2.CTr:locked@50"), fault("L1:weak=0.3@50"), fault("R1:short=0.5@50"),
       fault("L2:slip=0.2@50"), fault("R2.CTr:locked@150", true), fault("L1:weak@150", true),
       fault("R1:short@150", true), fault("L2:slip@150", true)});
  faulty.steps(151);
  EXPECT_TRUE(faulty.faults().in_force().empty());
  EXPECT_EQ(sim::physics_model(hexapod(), faulty.state()), hexapod().mj.get());
  sim::Stepper healthy(hexapod(), {}, {});
  healthy.restore(faulty.checkpoint());
  faulty.steps(300);
  healthy.steps(300);
  EXPECT_EQ(faulty.pose().x, healthy.pose().x);
  EXPECT_EQ(faulty.pose().yaw_deg, healthy.pose().yaw_deg);
}

TEST(FaultText, EveryKindReadsBackAsWritten) {
  for (const std::string text :
       {"R1@0", "R1+R3@6000", "R2.CTr:locked@0", "R2.CTr:locked=40@5", "R3.FTi:passive@0",
        "L1:weak=0.3@0", "L1.TC:weak=0.5@0", "R1:short=0.5@0", "L2:slip=0.2@0", "imu:drift=0.5@0",
        "imu:noise=1@0", "imu:drift=-2.5@10"}) {
    const body::Fault f = fault(text);
    EXPECT_EQ(body::fault_text(morph(), f), text);
    const nlohmann::json j = f;
    EXPECT_EQ(j.get<body::Fault>(), f) << text;
  }
  // A whole leg keeps the record it always had.
  EXPECT_EQ(nlohmann::json(fault("R1,R3@5")),
            nlohmann::json::parse(R"({"step": 5, "legs": [0, 2], "recover": false})"));
}

// The learning records' form of a run's faults (body::faults_record): the paper's one whole-leg
// failure as its legs and step, anything else as the timeline itself.
TEST(FaultJson, RecordsKeepOneLegFailureAsDisabledAndFailStep) {
  EXPECT_EQ(body::faults_record({fault("R1+R3@600")}),
            nlohmann::json::parse(R"({"disabled": [0, 2], "fail_step": 600, "faults": []})"));
  EXPECT_EQ(body::faults_record({}),
            nlohmann::json::parse(R"({"disabled": [], "fail_step": 0, "faults": []})"));
  const body::FaultTimeline other{fault("R2.CTr:locked@5")};
  EXPECT_EQ(
      body::faults_record(other),
      (nlohmann::json{{"disabled", nlohmann::json::array()}, {"fail_step", 0}, {"faults", other}}));
  const body::FaultTimeline twice{fault("R1@0"), fault("R1@90", true)};
  EXPECT_EQ(body::faults_record(twice).at("faults").get<body::FaultTimeline>(), twice);
}

TEST(FaultText, BadSpecsAreOneLineNamingWhatIsWrong) {
  const auto refused = [](const std::string& text, const std::string& mention) {
    try {
      body::validate(morph(), {fault(text)});
      ADD_FAILURE() << text << " accepted";
    } catch (const BadInput& e) {
      EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };
  refused("R2.CTr:melted@0", "unknown fault kind 'melted'");
  refused("R2.Knee:locked@0", "unknown joint 'Knee'");
  refused("R2:locked@0", "one joint");
  refused("R2.CTr:short=0.5@0", "whole legs");
  refused("L1:weak=0@0", "0.01..1");
  refused("L1:weak=1.5@0", "0.01..1");
  refused("L1:weak@0", "needs a value");
  refused("R1:short=0.05@0", "0.1..1");
  refused("L2:slip=x@0", "not a number");
  refused("imu:drift=11@0", "-10..10");
  refused("imu:noise@0", "needs a value");
  refused("R3.FTi:passive=2@0", "takes no value");
  refused("R9:weak=0.5@0", "R9");
  refused("R1:weak=0.5", "LEGS@STEP");
  refused("R1:weak=0.5@-1", "not a step");
  EXPECT_THROW(body::validate(morph(), {fault("L1:weak=0.3@0"), fault("L1.TC:weak=0.5@10")}),
               BadInput);  // one weak fault on a joint at a time
  EXPECT_THROW(body::validate(morph(), {fault("R2.CTr:locked@0", true)}), BadInput);
  EXPECT_THROW(body::validate(morph(), {fault("L1:weak=0.3@0"), fault("L1.TC:weak@10", true)}),
               BadInput);  // a recovery names what it ends
  EXPECT_NO_THROW(body::validate(morph(), {fault("L1:weak=0.3@0"), fault("L1:weak@10", true)}));
}

}  // namespace

namespace {

using namespace multicpg;

TEST(Terrain, SpecsReadBackAndBadOnesAreNamed) {
  for (const std::string text :
       {"flat", "slope:5:0", "slope:30:-90", "rough:0.01:1", "rough:0.05:7", "steps:0.02:0.2"}) {
    EXPECT_EQ(robot::terrain_text(robot::parse_terrain(text)), text);
  }
  EXPECT_EQ(robot::terrain_text(robot::parse_terrain("slope:5")), "slope:5:0");
  const auto refused = [](const std::string& text, const std::string& mention) {
    try {
      robot::parse_terrain(text);
      ADD_FAILURE() << text << " accepted";
    } catch (const BadInput& e) {
      EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
    }
  };
  refused("slope:31", "0..30");
  refused("slope:-1", "0..30");
  refused("slope:5:200", "-180..180");
  refused("rough:0.2", "0.001..0.05");
  refused("rough:0.01:x", "seed");
  refused("steps:0.02", "steps:HEIGHT_M:DEPTH_M");
  refused("steps:0.02:2", "0.05..1");
  refused("bumpy", "flat, slope");
  refused("", "flat, slope");
  refused("slope:nan", "not a number");
}

sim::SimModel terrain_model(const std::string& terrain, bool tunnel = false) {
  sim::SimOptions options;
  options.scene.terrain = robot::parse_terrain(terrain);
  options.scene.tunnel = tunnel;
  return sim::make_sim_model(robot::RobotKind::hexapod, options);
}

TEST(Terrain, ASlopeTiltsTheGroundTheRobotAndTheWalls) {
  const sim::SimModel m = terrain_model("slope:10", /*tunnel=*/true);
  const mjModel* mj = m.mj.get();
  sim::Stepper s(m, {}, {});
  // The robot starts standing on the slope, its trunk pitched up with it.
  const double* q = s.state().data->qpos + m.root_qpos + 3;
  const double pitch = 2.0 * std::asin(-q[2]) * kDeg;  // about y; up = negative about +y
  EXPECT_NEAR(std::abs(pitch), 10.0, 1e-9);
  // The walls stand on the ground: their centres 0.15 m above the plane, along its normal.
  const int wall = mj_name2id(mj, mjOBJ_GEOM, "wall_left");
  const double* p = mj->geom_pos + 3 * wall;
  const std::array<double, 3> in_ground =
      robot::to_ground_frame(m.scene.terrain, {p[0], p[1], p[2]});
  EXPECT_NEAR(in_ground[2], 0.15, 1e-9);
  // Uphill is slower than flat, and the yaw is still measured in the horizontal plane.
  s.steps(1200);
  sim::Stepper flat(hexapod(), {}, {});
  flat.steps(1200);
  EXPECT_LT(s.pose().x, flat.pose().x);
  EXPECT_GT(s.pose().x, 0.5) << "it still climbs";
  EXPECT_LT(std::abs(s.pose().yaw_deg), 10.0);
}

TEST(Terrain, RoughGroundIsAHeightfieldAndStepsAreBoxes) {
  const sim::SimModel rough = terrain_model("rough:0.02:3");
  ASSERT_EQ(rough.mj->nhfield, 1);
  const int n = robot::heightfield_samples_per_side();
  EXPECT_EQ(rough.mj->hfield_nrow[0], n);
  EXPECT_NEAR(rough.mj->hfield_size[2], 0.02, 1e-12);
  float lo = 1.0F;
  float hi = 0.0F;
  for (int i = 0; i < n * n; ++i) {
    lo = std::min(lo, rough.mj->hfield_data[i]);
    hi = std::max(hi, rough.mj->hfield_data[i]);
  }
  EXPECT_EQ(lo, 0.0F);
  EXPECT_EQ(hi, 1.0F);
  EXPECT_EQ(robot::heightfield_samples(robot::parse_terrain("rough:0.02:3")),
            robot::heightfield_samples(robot::parse_terrain("rough:0.01:3")))
      << "the seed, not the height, draws the bumps";
  EXPECT_NE(robot::heightfield_samples(robot::parse_terrain("rough:0.02:3")),
            robot::heightfield_samples(robot::parse_terrain("rough:0.02:4")));
  sim::Stepper walker(rough, {}, {});
  walker.steps(600);
  EXPECT_GT(walker.pose().x, 0.3) << "it walks over 2 cm bumps";

  // The first step begins 0.5 m ahead (robot/terrain.h): the tripod reaches it after about 250
  // steps, and by step 300 its trunk has risen 1.2 cm above the highest it reaches on flat ground
  // (measured).
  constexpr int kClimbSteps = 400;
  const sim::SimModel steps = terrain_model("steps:0.02:0.25");
  EXPECT_GE(mj_name2id(steps.mj.get(), mjOBJ_GEOM, "step_0"), 0);
  sim::Stepper climber(steps, {}, {});
  double highest = 0.0;
  for (int i = 0; i < kClimbSteps; ++i) {
    climber.step();
    highest = std::max(highest, sim::trunk_position(steps, climber.state()).z);
  }
  sim::Stepper level(hexapod(), {}, {});
  double level_highest = 0.0;
  for (int i = 0; i < kClimbSteps; ++i) {
    level.step();
    level_highest = std::max(level_highest, sim::trunk_position(hexapod(), level.state()).z);
  }
  EXPECT_GT(highest, level_highest + 0.01) << "the trunk rides up onto the steps";
}

}  // namespace
