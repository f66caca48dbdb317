// Checkpoints as sealed documents (sim/checkpoint.h, common/sealed_cbor.h): a run restored from
// a document into a fresh stepper continues bit for bit; a damaged, foreign or forged document is
// refused with BadInput; a fault schedule resumes part-way through its timeline; MuJoCo's fatal
// errors become exceptions inside mujoco_call where the process asks for it.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "body/fault_spec.h"
#include "common/checksum.h"
#include "common/errors.h"
#include "common/sealed_cbor.h"
#include "sim/checkpoint.h"
#include "sim/mujoco_guard.h"
#include "sim/stepper.h"

namespace {

using namespace multicpg;
using nlohmann::json;

const sim::SimModel& hexapod() {
  static const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  return model;
}

// Everything a run's checkpoint holds, as bytes to compare.
std::string sealed(const sim::Stepper& stepper) {
  return seal_cbor(sim::checkpoint_json(stepper.model(), stepper.checkpoint()));
}

TEST(SealedCbor, RoundTripsAndRefusesDamageAndDepth) {
  const json doc{{"x", 0.1}, {"blob", json::binary({1, 2, 3})}, {"list", {1, 2, {{"a", true}}}}};
  const std::string bytes = seal_cbor(doc);
  EXPECT_EQ(unseal_cbor(bytes), doc);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string damaged = bytes;
    damaged[i] = static_cast<char>(damaged[i] ^ 0x10);
    EXPECT_THROW(unseal_cbor(damaged), BadInput) << "byte " << i;
  }
  EXPECT_THROW(unseal_cbor(bytes.substr(0, 4)), BadInput);
  // A forged document nesting 10^5 arrays, with a right checksum: refused, no stack overflow.
  std::string forged = std::string(100'000, '\x81') + '\x00';
  const std::uint64_t sum = fnv1a64(forged);
  for (std::size_t i = 0; i < sizeof sum; ++i)
    forged += static_cast<char>((sum >> (8 * i)) & 0xffU);
  try {
    unseal_cbor(forged);
    ADD_FAILURE() << "a forged deep document was read";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("deeper"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, ARestoredRunContinuesBitForBit) {
  const sim::SimModel& m = hexapod();
  body::FaultTimeline faults{{40, {1}, false}, {90, {1}, true}, {90, {4}, false}};
  sim::Stepper original(m, {{5, 4, 4, 4, 4, 6}, 0}, faults);
  original.steps(60);
  original.apply_now(body::Fault{0, {2}, false});
  const json doc = unseal_cbor(seal_cbor(sim::checkpoint_json(m, original.checkpoint())));
  sim::Stepper restored(m, {{}, 0});
  restored.restore(sim::checkpoint_from_json(m, doc));
  EXPECT_EQ(sealed(restored), sealed(original));
  original.steps(120);
  restored.steps(120);
  EXPECT_EQ(sealed(restored), sealed(original));
  EXPECT_EQ(restored.faults().failed_legs(), (std::vector<std::size_t>{2, 4}));
}

// Every kind of fault in force (a locked joint's own model, a short tibia's masses, a slippery
// foot, a weak and a passive joint, the yaw sensor's drift and its seeded noise) goes into the
// document and comes back: the restored run continues bit for bit, through a recovery too.
TEST(Checkpoint, EveryFaultKindInForceContinuesBitForBit) {
  const sim::SimModel& m = hexapod();
  const robot::Morphology& morph = m.controller.morphology;
  body::FaultTimeline faults;
  for (const char* text :
       {"R2.CTr:locked@10", "L1:weak=0.3@10", "R1:short=0.5@20", "L2:slip=0.2@20",
        "R3.FTi:passive@30", "imu:drift=0.5@30", "imu:noise=1@30"}) {
    faults.push_back(body::parse_fault(morph, text, false));
  }
  faults.push_back(body::parse_fault(morph, "R1:short=0.5@90", true));
  body::StartSpec start{{}, 0};
  start.seed = 7;
  sim::Stepper original(m, start, faults);
  original.steps(60);
  ASSERT_NE(original.state().faults.model, nullptr);
  const json doc = unseal_cbor(seal_cbor(sim::checkpoint_json(m, original.checkpoint())));
  sim::Stepper restored(m, {{}, 0});
  restored.restore(sim::checkpoint_from_json(m, doc));
  EXPECT_EQ(sealed(restored), sealed(original));
  original.steps(60);
  restored.steps(60);
  EXPECT_EQ(sealed(restored), sealed(original));
  EXPECT_EQ(restored.state().faults.sensor.noise_deg, original.state().faults.sensor.noise_deg);

  const auto refused = [&](const char* what, const auto& edit) {
    json bad = doc;
    edit(bad);
    EXPECT_THROW(sim::checkpoint_from_json(m, bad), BadInput) << what;
  };
  refused("in force", [](json& j) { j["faults"]["applied"] = json::array(); });
  refused("torque", [](json& j) { j["effects"]["joints"][0][0][1] = 2.0; });
  refused("servo", [](json& j) { j["effects"]["joints"][0][0][0] = 7; });
  refused("random", [](json& j) { j["effects"]["sensor"]["random"] = "x"; });
  refused("array", [](json& j) { j["effects"]["model"]["arrays"]["no_such"] = json::binary({1}); });
  refused("array size",
          [](json& j) { j["effects"]["model"]["arrays"]["jnt_range"] = json::binary({1}); });
}

TEST(Checkpoint, RefusesAnotherModelAndImpossibleStates) {
  const sim::SimModel& m = hexapod();
  sim::Stepper stepper(m, {{}, 0});
  stepper.steps(3);
  const json good = sim::checkpoint_json(m, stepper.checkpoint());
  EXPECT_NO_THROW(sim::checkpoint_from_json(m, good));

  sim::SimOptions slower;
  slower.control_dt = 0.05;
  const sim::SimModel other = sim::make_sim_model(robot::RobotKind::hexapod, slower);
  EXPECT_THROW(sim::checkpoint_from_json(other, good), BadInput);
  const sim::SimModel quadruped = sim::make_sim_model(robot::RobotKind::quadruped);
  EXPECT_THROW(sim::checkpoint_from_json(quadruped, good), BadInput);

  const auto refused = [&](const char* what, const auto& edit) {
    json bad = good;
    edit(bad);
    EXPECT_THROW(sim::checkpoint_from_json(m, bad), BadInput) << what;
  };
  refused("format", [](json& j) { j["format"] = "other"; });
  refused("version", [](json& j) { j["version"] = 99; });
  refused("qpos size", [](json& j) { j["mjdata"]["qpos"] = json::binary({1, 2, 3}); });
  refused("missing key", [](json& j) { j.erase("controller"); });
  refused("period", [](json& j) { j["controller"]["legs"][0]["cpg"]["period"] = 12; });
  refused("counter", [](json& j) { j["controller"]["legs"][0]["cpg"]["counter"] = 9; });
  refused("delay line", [](json& j) { j["controller"]["legs"][1]["delay"]["head"] = 100000; });
  refused("ring", [](json& j) { j["controller"]["legs"][1]["delay"]["ring"] = json::array(); });
  refused("leg count", [](json& j) { j["controller"]["legs"].erase(0); });
  refused("disabled", [](json& j) { j["controller"]["legs"][3]["disabled"] = true; });
  refused("fault leg", [](json& j) { j["faults"]["applied"] = {{{"step", 0}, {"legs", {9}}}}; });
  refused("come", [](json& j) { j["faults"]["come"] = 3; });
  refused("walked", [](json& j) { j["walked"] = -1; });
  refused("type", [](json& j) { j["step"] = "three"; });
}

TEST(FaultSchedule, ResumesPartWayThroughItsTimeline) {
  const robot::Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  const body::FaultTimeline timeline{{10, {0}, false}, {20, {0}, true}};
  const body::FaultSchedule resumed(morph, timeline, 1, {{5, {3}, false}, {10, {0}, false}});
  EXPECT_EQ(resumed.come(), 1U);
  EXPECT_EQ(resumed.failed_legs(), (std::vector<std::size_t>{0, 3}));
  EXPECT_TRUE(resumed.pending());
  // The applied faults must hold the first `come` of the timeline, and could have happened.
  EXPECT_THROW(body::FaultSchedule(morph, timeline, 1, {{5, {3}, false}}), BadInput);
  EXPECT_THROW(body::FaultSchedule(morph, timeline, 0, {{5, {3}, true}}), BadInput);
  EXPECT_THROW(body::FaultSchedule(morph, timeline, 3, {}), BadInput);
}

TEST(MujocoGuard, AFatalErrorBecomesAnExceptionAndSimulationGoesOn) {
  sim::recover_mujoco_errors();
  EXPECT_THROW(sim::mujoco_call([] { mju_error("a test of the guard"); }), RuntimeFailure);
  try {
    sim::mujoco_call([] { mju_error("named"); });
  } catch (const RuntimeFailure& e) {
    EXPECT_STREQ(e.what(), "MuJoCo error: named");
  }
  sim::Stepper stepper(hexapod(), {{}, 0});
  stepper.steps(5);
  EXPECT_EQ(stepper.step_count(), 5);
}

}  // namespace
