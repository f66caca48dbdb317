// Faults on the wire, injected by the emulator, end the run on the real backends: the robot is
// commanded to its safe posture (or torque off) within 100 ms of the fault's detection, as the
// emulator sees the command arrive; the command ends with one line naming the cause and exit 1,
// no crash and no hang; a stopped learning run keeps what it recorded (docs/hardware.md
// "Safety"). Lock-step rehearsals, a few hundred control steps each.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_process.h"
#include "tests/cli_runner.h"
#include "tests/hw_rehearsal.h"

namespace multicpg::testing {
namespace {

// Wide enough that a busy machine's scheduling is no timeout, short enough that a fault is seen
// within a second.
constexpr int kTimeoutMs = 200;
// Safety requirement (docs/hardware.md "Safety"): the stop command goes out within this of the
// fault's detection.
constexpr double kStopLatencyS = 0.1;

struct Fault {
  std::string example;
  std::string injection;
  std::string cause;
};

void expect_safe_stop(const Fault& f, const std::string& command,
                      const std::vector<std::pair<std::string, std::string>>& edits = {},
                      const std::string& commanded = "robot commanded to its safe posture",
                      const std::string& event = "posture") {
  Rehearsal r(f.example, kTimeoutMs, {"--inject", f.injection}, edits);
  const CliResult host = run_cli(command + " --hardware " + r.file() + " --lock-step --json");
  ASSERT_TRUE(r.finish()) << "the emulator hangs";
  EXPECT_EQ(r.exit_code(), 0) << r.err();
  EXPECT_EQ(host.exit_code, 1) << f.injection << ": " << host.err;
  EXPECT_EQ(count_lines(host.err), 1) << host.err;
  EXPECT_NE(host.err.find(f.cause), std::string::npos) << host.err;
  EXPECT_NE(host.err.find(commanded), std::string::npos) << host.err;
  const nlohmann::json record = nlohmann::json::parse(host.out);
  EXPECT_EQ(record.at("status"), "stopped");
  const nlohmann::json& stop = record.at("hardware").at("stop");
  EXPECT_TRUE(stop.at("fault").get<bool>());
  const std::vector<nlohmann::json> seen = r.events(event);
  ASSERT_EQ(seen.size(), 1u) << f.injection << ": the emulator never saw the stop";
  const double latency = seen[0].at("t").get<double>() - stop.at("detected_s").get<double>();
  EXPECT_GE(latency, 0.0);
  EXPECT_LT(latency, kStopLatencyS) << f.injection;
  ::testing::Test::RecordProperty(f.example + " " + f.injection + " stop latency (ms)",
                                  std::to_string(1e3 * latency));
}

TEST(HardwareFaults, DynamixelFaultsStopTheRobotInItsSafePosture) {
  const Fault faults[] = {
      {"dynamixel-hexapod.toml", "silent=5@30", "servo R2.CTr (ID 5) stopped answering"},
      {"dynamixel-hexapod.toml", "corrupt=1@30", "repeated checksum errors"},
      {"dynamixel-hexapod.toml", "drop=1@30", "bus timeout: no answer in 3 control steps"},
      {"dynamixel-hexapod.toml", "latency=5000@30", "bus timeout: no answer in 3 control steps"},
      {"dynamixel-hexapod.toml", "silent-yaw@30", "yaw sensor silent"},
  };
  for (const Fault& f : faults) expect_safe_stop(f, "walk --steps 200");
}

TEST(HardwareFaults, AmosiiBoardFaultsStopTheRobotInItsSafePosture) {
  const Fault faults[] = {
      {"amosii.toml", "silent=0@30", "bus timeout: no answer in 3 control steps"},
      {"amosii.toml", "drop=1@30", "bus timeout: no answer in 3 control steps"},
      {"amosii.toml", "latency=5000@30", "bus timeout: no answer in 3 control steps"},
      {"amosii.toml", "silent-yaw@30", "yaw sensor silent: no reading in 3 control steps"},
  };
  for (const Fault& f : faults) expect_safe_stop(f, "walk --steps 200");
}

TEST(HardwareFaults, ATorqueOffStopTurnsEveryServoOff) {
  expect_safe_stop({"dynamixel-hexapod.toml", "silent=5@30", "stopped answering"},
                   "walk --steps 200", {{"action = \"posture\"", "action = \"torque_off\""}},
                   "every servo's torque off", "torque_off");
}

TEST(HardwareFaults, IsolatedBadAnswersAreCountedNotAStop) {
  // About one step in twenty loses a byte: each is counted, none three steps in a row.
  Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs, {"--inject", "drop=0.0002@0", "--seed", "3"});
  const CliResult host = run_cli("walk --steps 200 --hardware " + r.file() + " --lock-step --json");
  ASSERT_TRUE(r.finish());
  ASSERT_EQ(host.exit_code, 0) << host.err;
  const nlohmann::json h = nlohmann::json::parse(host.out).at("hardware");
  long bus = 0;
  for (const auto& [kind, n] : h.at("errors").at("bus").items()) bus += n.get<long>();
  long yaw = 0;
  for (const auto& [kind, n] : h.at("errors").at("yaw").items()) yaw += n.get<long>();
  EXPECT_GT(bus + yaw, 0);
  EXPECT_FALSE(h.at("stop").at("fault").get<bool>());
  EXPECT_EQ(r.events("posture").size(), 1u);  // the end of the walk stops the robot as well
}

TEST(HardwareFaults, ADriftingYawMisleadsAndIsNoStop) {
  // A drift is a plausible yaw: nothing on the wire tells it. 5 deg/s over 400 steps of 0.037 s.
  const auto final_yaw = [](const std::vector<std::string>& inject) {
    Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs, inject);
    const CliResult host =
        run_cli("walk --steps 400 --hardware " + r.file() + " --lock-step --json");
    EXPECT_TRUE(r.finish());
    EXPECT_EQ(host.exit_code, 0) << host.err;
    return nlohmann::json::parse(host.out).at("final_yaw_deg").get<double>();
  };
  const double plain = final_yaw({});
  const double drifting = final_yaw({"--inject", "drift=5@0"});
  EXPECT_NEAR(drifting - plain, 5.0 * 400 * 0.037, 0.1);
}

TEST(HardwareFaults, AmosiiFramesCarryNoChecksum) {
  // The board's only check is its end byte: a changed reading goes unnoticed, a changed end byte
  // is counted (docs/hardware.md "The AMOSII board").
  Rehearsal r("amosii.toml", kTimeoutMs, {"--inject", "corrupt=0.2@0", "--seed", "5"});
  const CliResult host = run_cli("walk --steps 400 --hardware " + r.file() + " --lock-step --json");
  ASSERT_TRUE(r.finish());
  ASSERT_EQ(host.exit_code, 0) << host.err;
  const nlohmann::json run = nlohmann::json::parse(host.out);
  const nlohmann::json& bus = run.at("hardware").at("errors").at("bus");
  EXPECT_GT(bus.at("bad_checksum").get<long>(), 0);
  EXPECT_LT(bus.at("bad_checksum").get<long>(), 20);  // about 80 frames changed, 1 in 33 at the end
}

TEST(HardwareFaults, SigintStopsTheRobotInItsSafePosture) {
  Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs, {"--inject", Rehearsal::kWalkingMark});
  CliProcess host({"walk", "--steps", "1000000", "--hardware", r.file(), "--lock-step", "--json"});
  ASSERT_TRUE(r.wait_walking(std::chrono::seconds(60))) << host.err();
  host.signal(SIGINT);
  ASSERT_TRUE(host.wait(std::chrono::seconds(30)));
  ASSERT_TRUE(r.finish());
  EXPECT_EQ(host.exit_code(), 130);
  EXPECT_EQ(count_lines(host.err()), 1) << host.err();
  EXPECT_NE(host.err().find("interrupted by SIGINT"), std::string::npos) << host.err();
  const nlohmann::json stop = nlohmann::json::parse(host.out()).at("hardware").at("stop");
  const std::vector<nlohmann::json> posture = r.events("posture");
  ASSERT_EQ(posture.size(), 1u);
  EXPECT_LT(posture[0].at("t").get<double>() - stop.at("detected_s").get<double>(), kStopLatencyS);
}

TEST(HardwareFaults, AStoppedLearningRunKeepsItsRecord) {
  // R1 and R3 fail: detection after 737 steps, then one trial every 737 (paper mode's settle and
  // window), so 3 trials are decided when servo 5 falls silent at step 3000.
  Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs, {"--inject", "silent=5@3000"});
  const std::string out = r.dir() + "/run";
  const CliResult host = run_cli("learn --mode paper --disable R1,R3 --hardware " + r.file() +
                                 " --lock-step --out " + out);
  ASSERT_TRUE(r.finish());
  EXPECT_EQ(host.exit_code, 1) << host.err;
  EXPECT_EQ(count_lines(host.err), 1) << host.err;
  EXPECT_NE(host.err.find("stopped answering"), std::string::npos);
  const nlohmann::json record = nlohmann::json::parse(read_file(out + "/learning.json"));
  EXPECT_EQ(record.at("status"), "stopped");
  EXPECT_EQ(record.at("trace").size(), 3u) << record.dump(2);
  EXPECT_EQ(record.at("trace")[0].at("periods").size(), 6u);
  EXPECT_GE(record.at("steps_walked").get<long>(), 3000);
  const std::string steps = read_file(out + "/hardware.csv");
  EXPECT_GE(count_lines(steps), 3000);  // every step walked, and its header
}

}  // namespace
}  // namespace multicpg::testing
