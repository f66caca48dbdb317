// multicpg view: without a display it says so in one line and exits 2; bad flags are
// reported before the display is looked at; under a virtual X server (Xvfb) it really opens a
// window, renders and quits after --steps.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "tests/cli_runner.h"

namespace {

using multicpg::testing::CliResult;
using multicpg::testing::count_lines;
using multicpg::testing::run_shell;

// The binary with no display in its environment.
CliResult run_headless(const std::string& args) {
  return run_shell(std::string("env -u DISPLAY -u WAYLAND_DISPLAY ") + MULTICPG_EXE + " " + args);
}

// The binary on a fresh virtual X server; -a picks a free server number, so tests may run in
// parallel.
CliResult run_on_xvfb(const std::string& args) {
  return run_shell(std::string("env -u WAYLAND_DISPLAY xvfb-run -a ") + MULTICPG_EXE + " " + args);
}

bool have_xvfb() {
  return run_shell("command -v xvfb-run").exit_code == 0;
}

void expect_one_line_exit_2(const CliResult& r, const std::string& must_mention,
                            const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << what << "\n" << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << what << "\n" << r.err;
  EXPECT_NE(r.err.find(must_mention), std::string::npos) << what << "\n" << r.err;
}

TEST(View, NoDisplayIsOneLineAndExit2) {
  for (const char* args : {"view", "view --steps 5", "view --robot quadruped --disable R1"}) {
    const CliResult r = run_headless(args);
    expect_one_line_exit_2(r, "no display", args);
    EXPECT_NE(r.err.find("DISPLAY"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// A display that cannot be opened is reported like a missing one, GLFW's own message folded
// into the line rather than printed separately.
TEST(View, UnreachableDisplayIsOneLineAndExit2) {
  const CliResult r = run_shell(std::string("env -u WAYLAND_DISPLAY DISPLAY=:9876 ") +
                                MULTICPG_EXE + " view --steps 5");
  expect_one_line_exit_2(r, "no display", "DISPLAY=:9876");
}

TEST(View, BadFlagsAreReportedBeforeTheDisplay) {
  const std::pair<std::string, std::string> cases[] = {
      {"view --robot spider", "spider"},
      {"view --disable R9", "R9"},
      {"view --robot quadruped --disable R3", "R3"},
      {"view --periods 3", "1, 4, 5, 6, 8, 9"},
      {"view --periods R1=7", "1, 4, 5, 6, 8, 9"},
      {"view --periods X1=4", "X1"},
      {"view --steps 0", "--steps"},
      {"view --steps -3", "--steps"},
      {"view --disable R1 --disable-at -1", "--disable-at"},
      {"view --disable R1 --disable-at 10 --steps 10", "--disable-at"},
      {"view --disable R1,R2,R3,L1,L2,L3", "every leg"},
      {"view --no-such-flag", "--no-such-flag"},
  };
  for (const auto& [args, mention] : cases) {
    const CliResult r = run_headless(args);
    expect_one_line_exit_2(r, mention, args);
    EXPECT_EQ(r.err.find("no display"), std::string::npos) << args << "\n" << r.err;
  }
}

TEST(View, OpensARealWindowUnderXvfb) {
  ASSERT_TRUE(have_xvfb()) << "xvfb-run is missing: scripts/setup.sh installs it (xvfb, xauth)";
  const CliResult r = run_on_xvfb("view --steps 30");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("viewed 30 steps"), std::string::npos) << r.out;
}

TEST(View, OtherRobotsFaultsAndFreeClientsUnderXvfb) {
  ASSERT_TRUE(have_xvfb()) << "xvfb-run is missing: scripts/setup.sh installs it (xvfb, xauth)";
  const CliResult r = run_on_xvfb(
      "view --robot octopod --periods R1=5,L4=6 --disable L2 --disable-at 5 --steps 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("viewed 10 steps"), std::string::npos) << r.out;
}

// A robot nobody designed the viewer around: its camera follows the body of its free joint.
TEST(View, AnExampleRobotFromItsFileUnderXvfb) {
  ASSERT_TRUE(have_xvfb()) << "xvfb-run is missing: scripts/setup.sh installs it (xvfb, xauth)";
  const CliResult r = run_on_xvfb("view --robot " + std::string(MULTICPG_SOURCE_DIR) +
                                  "/examples/robots/spider_quadruped.toml --disable R1 --steps 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("viewed 10 steps"), std::string::npos) << r.out;
}

}  // namespace
