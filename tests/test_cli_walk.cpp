// The real multicpg binary: walk's summary, --json and --csv, and its bad-input handling.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli_runner.h"

namespace {

using namespace multicpg::testing;

TEST(CliWalk, BadInput) {
  expect_bad_input("walk --robot spider", "spider");
  expect_bad_input("walk --robot quadruped --disable R3", "R3");
  expect_bad_input("walk --robot hexapod --disable R4", "R4");
  expect_bad_input("walk --periods 7", "1, 4, 5, 6, 8, 9");
  expect_bad_input("walk --periods 2", "1, 4, 5, 6, 8, 9");
  expect_bad_input("walk --periods R1=3", "1, 4, 5, 6, 8, 9");
  expect_bad_input("walk --robot quadruped --periods R3=5", "R3");
  expect_bad_input("walk --robot quadruped --disable R1,R2,L1,L2", "every leg");
  expect_bad_input("walk --disable R1,R2,R3,L1,L2,L3", "every leg");
  expect_bad_input("walk --control-dt 0", "--control-dt");
  expect_bad_input("walk --control-dt -0.037", "--control-dt");
  expect_bad_input("walk --physics-dt -0.001", "--physics-dt");
  expect_bad_input("walk --physics-dt 0.005", "whole number of times");
  expect_bad_input("walk --control-dt 0.037 --physics-dt 0.0037001", "whole number of times");
  expect_bad_input("walk --control-dt 0.001 --physics-dt 0.002", "whole number of times");
  expect_bad_input("walk --steps 0", "--steps");
  expect_bad_input("walk --steps -5", "--steps");
  expect_bad_input("walk --window 0", "--window");
  expect_bad_input("walk --settle -1", "--settle");
  expect_bad_input("walk --disable R1 --disable-at -1", "--disable-at");
  expect_bad_input("walk --disable R1 --disable-at 10 --steps 10", "--disable-at");
  expect_bad_input("walk --steps ten", "steps");
  expect_bad_input("model --robot spider", "spider");
  expect_bad_input("model --physics-dt 0.005", "whole number of times");
}

TEST(CliWalk, UnwritableCsvFailsBeforeTheRun) {
  const auto r = run_cli("walk --steps 100000 --csv /nonexistent-dir/x.csv");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
}

TEST(CliWalk, PhysicsBlowUpIsARuntimeFailure) {
  const auto r = run_cli("walk --steps 50 --physics-dt 0.037");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("unstable at step"), std::string::npos) << r.err;
}

TEST(CliWalk, SummaryNamesTheRun) {
  const auto r = run_cli("walk --steps 40 --window 20 --disable L2 --periods R1=4,L3=5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("hexapod"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R1 4  R2 4  R3 4  L1 4  L2 4  L3 5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("faults: L2 fail at step 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(warmed-up controller)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("steps      0-20"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("steps     20-40"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("final yaw"), std::string::npos) << r.out;
}

TEST(CliWalk, JsonHasTheMeasurements) {
  const auto r = run_cli("walk --robot quadruped --steps 60 --window 20 --settle 10 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"distance_m", "speed_m_s", "window_deviations_deg", "final_yaw_deg", "forward_m",
        "lateral_m", "periods", "faults", "warmup", "windows", "physics_dt_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["window_deviations_deg"].size(), 3u);
  EXPECT_EQ(j["windows"].size(), 3u);
  EXPECT_EQ(j["warmup"], 1000);  // a running controller unless --cold
  EXPECT_EQ(j["robot"], "quadruped");
  EXPECT_EQ(j["periods"]["L2"], 4);
  EXPECT_DOUBLE_EQ(j["physics_dt_s"].get<double>(), 0.037 / 8);
  EXPECT_NEAR(j["speed_m_s"].get<double>(), j["distance_m"].get<double>() / (60 * 0.037), 1e-12);
}

TEST(CliWalk, CsvHasEveryStepAndColumn) {
  const std::string dir = make_temp_dir("walk-");
  const auto r = run_cli("walk --robot quadruped --steps 30 --settle 5 --csv " + dir + "/w.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_file(dir + "/w.csv");
  std::string header = "step,time_s,x_m,y_m,z_m,yaw_deg,sensed_yaw_deg";
  for (const char* leg : {"R1", "R2", "L1", "L2"}) {
    for (const char* joint : {"TC", "CTr", "FTi"}) {
      const std::string n = std::string(leg) + "_" + joint;
      for (const char* column : {"_command", "_target_rad", "_actual_rad"})
        header += "," + n + column;
    }
    header += ',';
    header += leg;
    header += "_contact";
  }
  EXPECT_EQ(first_line(csv), header);
  EXPECT_EQ(count_lines(csv), 1 + 36);  // header, then the start and 35 steps
  std::filesystem::remove_all(dir);
}

// Every physical parameter of the body (robot/body_params.h) changes the walk; --model paper-sim
// is the default to the byte.
TEST(CliWalk, EveryBodyParameterChangesTheWalkAndPaperSimIsTheDefault) {
  const std::string base = "walk --disable R1,R3 --steps 300 --json";
  const auto plain = run_cli(base);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto paper_sim = run_cli(base + " --model paper-sim");
  ASSERT_EQ(paper_sim.exit_code, 0) << paper_sim.err;
  EXPECT_EQ(paper_sim.out, plain.out);
  for (const char* flags :
       {"--model real", "--disabled-posture 0,0.9,-0.9", "--leg-posture R3=,,-0.5", "--lift-body 5",
        "--total-mass 6", "--trunk-mass 2.2", "--foot-friction 1", "--trunk-friction 1",
        "--slip 0.03", "--joint-compliance 0.05", "--torsional-friction 0.005",
        "--rolling-friction 0.001", "--servo-torque 10", "--servo-speed 6"}) {
    const auto r = run_cli(base + " " + flags);
    ASSERT_EQ(r.exit_code, 0) << flags << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_NE(j["distance_m"], nlohmann::json::parse(plain.out)["distance_m"]) << flags;
  }
}

// The learning and the tunnel too: --model paper-sim is the default to the byte.
TEST(CliWalk, PaperSimIsTheDefaultBodyOfLearnAndTunnel) {
  for (const auto& [command, exit_code] : std::vector<std::pair<std::string, int>>{
           {"learn --mode paper --disable R1 --max-trials 2 --json", 0},
           {"tunnel --disable R1,R3 --max-steps 200 --json", 0}}) {
    const auto plain = run_cli(command);
    ASSERT_EQ(plain.exit_code, exit_code) << command << ": " << plain.err;
    const auto paper_sim = run_cli(command + " --model paper-sim");
    ASSERT_EQ(paper_sim.exit_code, exit_code) << command << ": " << paper_sim.err;
    EXPECT_EQ(paper_sim.out, plain.out) << command;
    const auto real = run_cli(command + " --model real");
    // The real body need not converge in two trials (exit 3): its output is whole either way.
    ASSERT_TRUE(real.exit_code == 0 || real.exit_code == 3) << command << ": " << real.err;
    EXPECT_NE(real.out, plain.out) << command;
  }
}

// The tunnel takes the fault flags of every walking command and records faults other than
// whole legs; --disable R1 and --fault R1@0 are the same run.
TEST(CliWalk, TheTunnelTakesAnyFault) {
  const auto disabled = run_cli("tunnel --disable R1 --max-steps 200 --json");
  const auto fault = run_cli("tunnel --fault R1@0 --max-steps 200 --json");
  ASSERT_EQ(fault.exit_code, 0) << fault.err;
  EXPECT_EQ(fault.out, disabled.out);
  const auto locked = run_cli("tunnel --fault R1.CTr:locked@0 --max-steps 200 --json");
  ASSERT_EQ(locked.exit_code, 0) << locked.err;
  const auto j = nlohmann::json::parse(locked.out);
  ASSERT_EQ(j.at("faults").size(), 1U);
  EXPECT_EQ(j.at("faults")[0].at("kind"), "locked");
  EXPECT_EQ(j.at("faults")[0].at("joint"), "CTr");
  const auto text = run_cli("tunnel --fault R1.CTr:locked@0 --max-steps 100");
  EXPECT_NE(text.out.find("faults R1.CTr:locked@0"), std::string::npos) << text.out;
  expect_bad_input("tunnel --fault R1.XX:locked@0", "--fault");
}

TEST(CliWalk, ExplicitPhysicsStepThatDivides) {
  const auto r = run_cli("walk --steps 20 --physics-dt 0.0037 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(r.out)["physics_dt_s"].get<double>(), 0.0037);
}

}  // namespace
