// The ports of a run on hardware (docs/hardware.md "Safety", "Rehearse on the emulator"): an
// emulator that ends at any moment of a walk ends it with the one stop line and exit 1; a port is
// one program's, a second one is refused before it writes a byte; the emulator serves run after
// run, and a run after it ended is told so.
#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "learning/landscapes.h"
#include "robot/morphology.h"
#include "tests/cli_process.h"
#include "tests/cli_runner.h"
#include "tests/hw_rehearsal.h"

namespace multicpg::testing {
namespace {

// Wide enough that a busy machine's scheduling is no timeout (tests/test_hw_faults.cpp).
constexpr int kTimeoutMs = 200;
// Hang guards, not timing claims.
constexpr std::chrono::seconds kHang(120);

// The one line a walk ends with when its robot's ports fail: a stop after a step, saying whether
// the stop went out; or a start-up check that failed before anything moved; or the port already
// gone (the emulator ended before the walk opened it).
const std::regex kStopLine(
    "multicpg: (hardware stop after step [0-9]+: .+; (robot commanded to its safe posture|the "
    "stop could not be sent: .+)|start-up check: .+; nothing has moved|cannot open port .+: the "
    "emulator that served it has ended; .+)\n");

// The ports a rehearsal file names, the bus first.
std::vector<std::string> ports(const Rehearsal& r) {
  const std::string text = read_file(r.file());
  const std::regex port("\nport = ['\"]([^'\"]+)['\"]");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), port); it != std::sregex_iterator();
       ++it) {
    out.push_back((*it)[1].str());
  }
  EXPECT_FALSE(out.empty()) << text;
  return out;
}

std::string bus_port(const Rehearsal& r) {
  const std::vector<std::string> all = ports(r);
  return all.empty() ? "" : all.front();
}

// Whether process `pid` has `path` open.
bool holds(pid_t pid, const std::string& path) {
  std::error_code ec;
  for (const auto& fd :
       std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    std::error_code link_ec;
    if (std::filesystem::read_symlink(fd.path(), link_ec).string() == path) return true;
  }
  return false;
}

TEST(HardwarePorts, AnEmulatorHangingUpAtAnyStepEndsTheWalkWithTheStopLine) {
  struct Case {
    std::string example, injection, sent;
  };
  // The bus closing first: the stop cannot go out. The yaw line's closing first (as a killed
  // emulator's ports may close in either order): the stop goes out on the bus.
  const Case cases[] = {
      {"dynamixel-hexapod.toml", "hangup@0", "the stop could not be sent"},
      {"dynamixel-hexapod.toml", "hangup@7", "the stop could not be sent"},
      {"dynamixel-hexapod.toml", "hangup@60", "the stop could not be sent"},
      {"dynamixel-hexapod.toml", "hangup-yaw@0", "robot commanded to its safe posture"},
      {"dynamixel-hexapod.toml", "hangup-yaw@7", "robot commanded to its safe posture"},
      {"dynamixel-hexapod.toml", "hangup-yaw@60", "robot commanded to its safe posture"},
      {"amosii.toml", "hangup@0", "the stop could not be sent"},
      {"amosii.toml", "hangup@60", "the stop could not be sent"},
  };
  for (const Case& c : cases) {
    Rehearsal r(c.example, kTimeoutMs, {"--inject", c.injection});
    const CliResult host = run_cli("walk --steps 200 --hardware " + r.file() + " --lock-step");
    ASSERT_TRUE(r.finish()) << c.injection << ": the emulator hangs";
    EXPECT_EQ(host.exit_code, 1) << c.injection << ": " << host.err;
    EXPECT_TRUE(std::regex_match(host.err, kStopLine)) << c.injection << ": " << host.err;
    EXPECT_NE(host.err.find("hardware stop after step"), std::string::npos) << host.err;
    EXPECT_NE(host.err.find(c.sent), std::string::npos) << c.injection << ": " << host.err;
  }
}

TEST(HardwarePorts, AnEmulatorHangingUpAtTheLastStepLeavesNoStopUntold) {
  // The port closes as the last step's answers go out: the end's stop was written before it
  // closed (exit 0, no line), or could not be and is told as every stop is (exit 1).
  for (const std::string example : {"amosii.toml", "dynamixel-hexapod.toml"}) {
    for (int run = 0; run < 3; ++run) {
      Rehearsal r(example, kTimeoutMs, {"--inject", "hangup@199"});
      const CliResult host = run_cli("walk --steps 200 --hardware " + r.file() + " --lock-step");
      ASSERT_TRUE(r.finish()) << example << ": the emulator hangs";
      if (host.exit_code == 0) {
        EXPECT_EQ(host.err, "") << example;
      } else {
        EXPECT_EQ(host.exit_code, 1) << example << ": " << host.err;
        EXPECT_TRUE(std::regex_match(host.err, kStopLine)) << example << ": " << host.err;
      }
    }
  }
}

TEST(HardwarePorts, AKilledEmulatorEndsTheWalkWithTheStopLine) {
  // Killed at several moments: while the walk loads, opens its ports, or walks.
  for (const int wait_ms : {0, 300, 1000, 2500, 5000}) {
    Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs);
    CliProcess host({"walk", "--steps", "1000000", "--hardware", r.file(), "--lock-step"});
    std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
    r.signal(SIGKILL);
    ASSERT_TRUE(host.wait(kHang)) << "killed after " << wait_ms << " ms: the walk hangs";
    EXPECT_EQ(host.exit_code(), 1) << wait_ms << " ms: " << host.err();
    EXPECT_TRUE(std::regex_match(host.err(), kStopLine)) << wait_ms << " ms: " << host.err();
  }
}

TEST(HardwarePorts, ASecondProgramOnARobotsPortIsRefusedBeforeItWritesAByte) {
  Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs, {"--inject", Rehearsal::kWalkingMark});
  const std::string port = bus_port(r);
  CliProcess first({"walk", "--steps", "1000000", "--hardware", r.file(), "--lock-step"});
  ASSERT_TRUE(wait_until([&] { return holds(first.pid(), port); }, kHang)) << first.err();
  const CliResult second = run_cli("walk --steps 20 --hardware " + r.file() + " --lock-step");
  EXPECT_EQ(second.exit_code, 1) << second.err;
  EXPECT_EQ(count_lines(second.err), 1) << second.err;
  EXPECT_NE(second.err.find("port " + port + " is in use by pid " + std::to_string(first.pid())),
            std::string::npos)
      << second.err;
  // The first walks on, its link untouched: not a byte of the second reached the emulator. (It
  // may have held the port before its first step; a robot stopped then is not commanded.)
  ASSERT_TRUE(r.wait_walking(kHang)) << first.err();
  first.signal(SIGINT);
  ASSERT_TRUE(first.wait(kHang));
  EXPECT_EQ(first.exit_code(), 130) << first.err();
  ASSERT_TRUE(r.finish());
  EXPECT_EQ(r.events("malformed").size(), 0u);
  EXPECT_EQ(r.events("posture").size(), 1u);
}

TEST(HardwarePorts, TheEmulatorServesRunAfterRunAndAGoneOneIsNamed) {
  Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs, {"--runs", "2"});
  const std::string walk = "walk --steps 60 --json --hardware " + r.file() + " --lock-step";
  const CliResult one = run_cli(walk);
  const CliResult two = run_cli(walk);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  // Each run from the robot's start pose: the same walk, the same bytes.
  EXPECT_EQ(first_line(one.out.substr(one.out.find("final_yaw_deg"))),
            first_line(two.out.substr(two.out.find("final_yaw_deg"))));
  ASSERT_TRUE(r.finish());
  EXPECT_EQ(r.exit_code(), 0) << r.err();
  EXPECT_NE(r.out().find("run 2: served 61 control steps"), std::string::npos) << r.out();
  const CliResult gone = run_cli(walk);
  EXPECT_EQ(gone.exit_code, 1) << gone.err;
  EXPECT_EQ(count_lines(gone.err), 1) << gone.err;
  EXPECT_NE(gone.err.find("the emulator that served it has ended; start it again"),
            std::string::npos)
      << gone.err;
}

TEST(HardwarePorts, AGoneEmulatorsPortNumberHeldByAnotherProgramIsNotOpened) {
  // The kernel gives a pseudo-terminal's number to the next program that asks once its emulator
  // ended: here this test's own ptys stand at the ports of the ended emulator's rehearsal file.
  std::string text;
  std::vector<std::string> gone;
  {
    Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs);
    text = read_file(r.file());
    gone = ports(r);
    r.signal(SIGTERM);
    ASSERT_TRUE(r.finish());
  }
  struct Pty {
    int master = -1;
    int slave = -1;
  };
  std::vector<Pty> mine(gone.size());
  for (std::size_t i = 0; i < gone.size(); ++i) {
    ASSERT_EQ(::openpty(&mine[i].master, &mine[i].slave, nullptr, nullptr, nullptr), 0);
    const std::string quoted = "'" + gone[i] + "'";
    const std::size_t at = text.find(quoted);
    ASSERT_NE(at, std::string::npos) << text;
    text = text.substr(0, at) + "'" + ::ptsname(mine[i].master) + "'" +
           text.substr(at + quoted.size());
  }
  const std::string bus = ::ptsname(mine.front().master);
  const std::string dir = make_temp_dir("multicpg-gone-");
  std::ofstream(dir + "/rehearsal.toml") << text;
  const CliResult walk =
      run_cli("walk --steps 20 --hardware " + dir + "/rehearsal.toml --lock-step");
  EXPECT_EQ(walk.exit_code, 1) << walk.err;
  EXPECT_EQ(count_lines(walk.err), 1) << walk.err;
  EXPECT_NE(walk.err.find("cannot open port " + bus + ": the emulator that served it has ended"),
            std::string::npos)
      << walk.err;
  // Not a byte reached the program that holds the numbers now.
  for (const Pty& p : mine) {
    pollfd ready{p.master, POLLIN, 0};
    EXPECT_EQ(::poll(&ready, 1, 0), 0);
    ::close(p.slave);
    ::close(p.master);
  }
  std::filesystem::remove_all(dir);
}

TEST(HardwarePorts, APriorOfAnotherPeriodSetIsRefusedBeforeTheRobotWalks) {
  // The repository's hexapod dataset cut to the periods 4, 5, 6, 8: a prior of another period
  // set than the run's (4, 5, 6, 8, 9).
  learning::LandscapeDataset d = learning::read_landscape_dataset(
      learning::repository_dataset(robot::RobotKind::hexapod, false));
  d.period_set = {4, 5, 6, 8};
  for (learning::ScenarioLandscape& s : d.scenarios) {
    std::erase_if(s.points, [](const learning::LandscapePoint& p) {
      return std::find(p.periods.begin(), p.periods.end(), 9) != p.periods.end();
    });
  }
  const std::string dir = make_temp_dir("multicpg-prior-");
  learning::write_landscape_dataset(d, dir + "/cut");
  Rehearsal r("dynamixel-hexapod.toml", kTimeoutMs);
  const CliResult refused =
      run_cli("learn --mode paper --disable R1 --learner prior --learner-option dataset=" + dir +
              "/cut.json --hardware " + r.file() + " --lock-step");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_EQ(count_lines(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("has the period set 4,5,6,8, this run 4,5,6,8,9"), std::string::npos)
      << refused.err;
  // The refused run never spoke to the robot: the emulator's one run is the next command's
  // (its 5 steps and the stop).
  const CliResult walk = run_cli("walk --steps 5 --hardware " + r.file() + " --lock-step");
  EXPECT_EQ(walk.exit_code, 0) << walk.err;
  ASSERT_TRUE(r.finish());
  EXPECT_NE(r.out().find("run 1: served 6 control steps"), std::string::npos) << r.out();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace multicpg::testing
