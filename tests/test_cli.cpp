// The real multicpg binary: gait and cpg commands, their files and their bad-input handling.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/cli_runner.h"

namespace {

using namespace multicpg::testing;

TEST(CliGait, PrintsDiagramAndWritesCsv) {
  const std::string dir = make_temp_dir("gait-");
  const auto r = run_cli("gait --robot hexapod --period 4 --steps 36 --csv " + dir + "/g.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("R1 "), std::string::npos);
  EXPECT_NE(r.out.find("swing fraction"), std::string::npos);
  const std::string csv = read_file(dir + "/g.csv");
  EXPECT_EQ(first_line(csv), "step,R1,R2,R3,L1,L2,L3");
  EXPECT_EQ(count_lines(csv), 37);
  std::filesystem::remove_all(dir);
}

TEST(CliGait, QuadrupedAndOctopodColumns) {
  const std::string dir = make_temp_dir("gait-");
  ASSERT_EQ(
      run_cli("gait --robot quadruped --period 4 --steps 10 --csv " + dir + "/q.csv").exit_code, 0);
  EXPECT_EQ(first_line(read_file(dir + "/q.csv")), "step,R1,R2,L1,L2");
  ASSERT_EQ(run_cli("gait --robot octopod --period 5 --steps 10 --csv " + dir + "/o.csv").exit_code,
            0);
  EXPECT_EQ(first_line(read_file(dir + "/o.csv")), "step,R1,R2,R3,R4,L1,L2,L3,L4");
  std::filesystem::remove_all(dir);
}

TEST(CliGait, BadInput) {
  expect_bad_input("gait --robot spider --period 4", "spider");
  expect_bad_input("gait --period 3", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --period 7", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --period 0", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --period 10", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --steps 0", "--steps");
  expect_bad_input("gait --steps -5", "--steps");
  expect_bad_input("gait --disable R4", "R4");
  expect_bad_input("gait --robot quadruped --disable R3", "R3");
  expect_bad_input("gait --period four", "--period");
  expect_bad_input("gait --csv /nonexistent-dir/g.csv", "/nonexistent-dir/g.csv");
  expect_bad_input("gait --no-such-flag", "--no-such-flag");
  expect_bad_input("", "subcommand");
}

TEST(CliGait, UnwritableCsvLeavesNoFile) {
  const std::string dir = make_temp_dir("gait-");
  const std::string target = dir + "/sub/g.csv";  // parent directory missing
  EXPECT_EQ(run_cli("gait --csv " + target).exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(target));
  std::filesystem::remove_all(dir);
}

TEST(CliCpg, WritesColumnsAndReportsOrbits) {
  const std::string dir = make_temp_dir("cpg-");
  const auto r = run_cli("cpg --period 5 --client-period 6 --sync off --csv " + dir + "/c.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("master x1: period-5 orbit"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("client x1: period-6 orbit"), std::string::npos) << r.out;
  const std::string csv = read_file(dir + "/c.csv");
  EXPECT_EQ(first_line(csv), "step,master_x1,master_x2,client_x1,client_x2");
  EXPECT_EQ(count_lines(csv), 3001);

  const auto synced = run_cli("cpg --period 5 --client-period 6 --sync on");
  ASSERT_EQ(synced.exit_code, 0);
  EXPECT_NE(synced.out.find("client x1: period-5 orbit"), std::string::npos) << synced.out;
  EXPECT_NE(synced.out.find("identical to the master's"), std::string::npos) << synced.out;

  const auto chaos = run_cli("cpg --uncontrolled --sync off");
  ASSERT_EQ(chaos.exit_code, 0);
  EXPECT_NE(chaos.out.find("master x1: no periodic orbit"), std::string::npos) << chaos.out;
  std::filesystem::remove_all(dir);
}

TEST(CliCpg, BadInput) {
  expect_bad_input("cpg --period 0", "1..9");
  expect_bad_input("cpg --period 10", "1..9");
  expect_bad_input("cpg --period 4 --client-period 11", "--client-period");
  expect_bad_input("cpg --steps 0", "--steps");
  expect_bad_input("cpg --sync maybe", "--sync");
  expect_bad_input("cpg --csv /nonexistent-dir/c.csv", "/nonexistent-dir/c.csv");
}

TEST(Cli, HelpExitsZero) {
  const auto r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("gait"), std::string::npos);
}

}  // namespace
