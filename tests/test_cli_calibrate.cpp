// multicpg calibrate end to end (docs/fidelity.md "Calibration"): a two-candidate search with one
// start walks real tunnel runs, writes its tables, resumes without walking again, refuses a resume
// with other options, and refuses bad searches with one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli_runner.h"

namespace {

using namespace multicpg::testing;
namespace fs = std::filesystem;

TEST(CliCalibrate, ASmallSearchWritesItsTablesAndResumes) {
  const fs::path dir = make_temp_dir("calibrate");
  const std::string args =
      "calibrate --budget 2 --warmups 1000 --jobs 2 --search slip "
      "--search servo_torque=8..20 --out " +
      (dir / "c").string();
  const CliResult r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 candidates (2 walked now, 0 loaded)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("real robot -42°"), std::string::npos) << r.out;
  // header and one row per candidate
  EXPECT_EQ(count_lines(read_file((dir / "c" / "candidates.csv").string())), 3);
  const auto summary = nlohmann::json::parse(read_file((dir / "c" / "summary.json").string()));
  const auto& best = summary.at("best");
  EXPECT_EQ(best.at("fit").size(), 3U);
  for (const auto& scenario : best.at("fit")) {
    EXPECT_LT(scenario.at("mean_deg").get<double>(), 0.0) << "a right leg lost turns right";
  }
  const double slip = best.at("body").at("slip").get<double>();
  EXPECT_GE(slip, 0.0005);
  EXPECT_LE(slip, 0.05);
  EXPECT_TRUE(is_png(dir / "c" / "calibration-sensitivity.png"));

  const CliResult again = run_cli(args);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("(0 walked now, 2 loaded)"), std::string::npos) << again.out;
  EXPECT_EQ(again.out.substr(again.out.find("best")), r.out.substr(r.out.find("best")));

  const CliResult other = run_cli(args + " --seed 2");
  EXPECT_EQ(other.exit_code, 2) << other.err;
  EXPECT_EQ(count_lines(other.err), 1) << other.err;
  fs::remove_all(dir);
}

TEST(CliCalibrate, BadSearchesAreOneLineAndExitTwo) {
  const fs::path dir = make_temp_dir("calibrate-bad");
  const std::string out = " --out " + (dir / "x").string();
  expect_bad_input("calibrate --search no_such" + out, "no_such");
  expect_bad_input("calibrate --search slip=1..2" + out, "slip");
  expect_bad_input("calibrate --search slip=0.02..0.01" + out, "slip");
  expect_bad_input("calibrate --search slip --search slip" + out, "slip");
  expect_bad_input("calibrate --robot quadruped" + out, "hexapod");
  expect_bad_input("calibrate --budget 1" + out, "--budget");
  expect_bad_input("calibrate --target table9" + out, "table9");
  expect_bad_input("calibrate --warmups -3" + out, "--warmups");
  EXPECT_FALSE(fs::exists(dir / "x"));
  fs::remove_all(dir);
}

}  // namespace
