// Every bad input of every command is one line naming what is wrong and exit 2,
// before any work. The table below is run through the real CLI: the numeric flags with values
// outside their documented ranges, empty, non-numeric, with trailing junk, NaN and infinite, and
// the leg sets, period maps, fault timelines, choices, paths and combinations users get wrong.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

struct BadInput {
  std::string args;
  std::string must_mention;
};

// A numeric flag of a command: the arguments it needs to run, the flag and values out of range.
struct NumericFlag {
  std::string command;  // subcommand with what it needs besides the flag
  std::string flag;
  std::vector<std::string> out_of_range;
};

// Values no numeric flag takes: empty, words, trailing junk, NaN, infinities.
const std::vector<std::string> kNotNumbers{"''", "abc", "12x", "nan", "inf", "-inf", "1e999"};

std::vector<BadInput> numeric_cases() {
  const std::string exp = "experiment table --robot quadruped --out /tmp/multicpg-bad-exp";
  const std::vector<NumericFlag> flags{
      {"learn --disable R1", "--beta", {"-1", "100.5"}},
      {"learn --disable R1", "--threshold", {"0", "-3", "181"}},
      {"learn --disable R1", "--window", {"0", "-400", "100001"}},
      {"learn --disable R1", "--settle", {"-1", "100001"}},
      {"learn --disable R1", "--max-trials", {"0", "100001"}},
      {"learn --disable R1", "--hold-windows", {"0", "101"}},
      {"learn --disable R1", "--monitor-windows", {"0", "1001"}},
      {"learn --disable R1", "--control-dt", {"0", "-0.037", "1e-300", "2"}},
      {"learn --disable R1", "--physics-dt", {"-0.001", "0.5"}},
      {"learn --disable R1", "--servo-gain", {"-1", "1e5"}},
      {"learn --disable R1", "--disable-at", {"-3", "100000001"}},
      {"learn --disable R1", "--warmup", {"-1", "100000001"}},
      {"walk", "--steps", {"0", "-5", "100000001"}},
      {"walk", "--window", {"0", "100001"}},
      {"walk", "--settle", {"-1"}},
      {"walk", "--warmup", {"-1"}},
      {"gait", "--steps", {"0"}},
      {"gait", "--warmup", {"-2"}},
      {"cpg", "--period", {"0", "10"}},
      {"cpg", "--client-period", {"0", "10"}},
      {"cpg", "--steps", {"0"}},
      {"tunnel --disable R1", "--max-steps", {"0", "-1"}},
      {"render --out /tmp/multicpg-bad.png", "--width", {"0", "15", "100000"}},
      {"render --out /tmp/multicpg-bad.png", "--height", {"4097"}},
      {"render --out /tmp/multicpg-bad.png", "--speed", {"0", "1001"}},
      {"render --out /tmp/multicpg-bad.png", "--steps", {"0"}},
      {exp, "--runs", {"0", "100001"}},
      {exp, "--jobs", {"0", "-2", "5000"}},
      {exp, "--check-windows", {"-1", "1001"}},
      {"landscape --disable R1 --out /tmp/multicpg-bad-land", "--windows", {"0", "1001"}},
      {"landscape --disable R1 --out /tmp/multicpg-bad-land", "--jobs", {"0"}},
      {"landscape --disable R1 --out /tmp/multicpg-bad-land", "--threshold", {"0"}},
      {"reproduce --out /tmp/multicpg-bad-rep", "--jobs", {"0"}},
      // The body (robot/body_params.h): every parameter's range.
      {"walk", "--lift-body", {"-11", "16"}},
      {"walk", "--total-mass", {"4", "20"}},
      {"walk", "--trunk-mass", {"1", "4.5"}},
      {"walk", "--foot-friction", {"0", "3.5"}},
      {"walk", "--trunk-friction", {"0.1", "10"}},
      {"walk", "--slip", {"0", "0.0001", "0.1"}},
      {"walk", "--joint-compliance", {"-0.01", "0.3"}},
      {"walk", "--torsional-friction", {"-0.001", "0.02"}},
      {"walk", "--rolling-friction", {"-1", "0.01"}},
      {"walk", "--servo-torque", {"1", "31"}},
      {"walk", "--servo-speed", {"2", "13"}},
      {"tunnel --disable R1", "--total-mass", {"12"}},
      {"learn --disable R1", "--slip", {"1"}},
      {"landscape --disable R1 --out /tmp/multicpg-bad-land", "--servo-torque", {"0"}},
      {"render --out /tmp/multicpg-bad.png", "--trunk-mass", {"0"}},
      {"view", "--lift-body", {"90"}},
      {exp, "--foot-friction", {"-1"}},
      {"model", "--joint-compliance", {"1"}},
  };
  std::vector<BadInput> cases;
  for (const NumericFlag& f : flags) {
    for (const std::string& v : f.out_of_range)
      cases.push_back({f.command + " " + f.flag + " " + v, f.flag});
  }
  // Every kind of non-number for a sample of integer and floating flags of each command.
  for (const auto& [command, flag] : std::vector<std::pair<std::string, std::string>>{
           {"learn --disable R1", "--beta"},
           {"learn --disable R1", "--window"},
           {"walk", "--steps"},
           {"walk", "--control-dt"},
           {"render --out /tmp/multicpg-bad.png", "--width"},
           {exp, "--runs"},
           {"cpg", "--period"},
           {"walk", "--total-mass"},
           {"tunnel --disable R1", "--slip"},
       }) {
    for (const std::string& v : kNotNumbers)
      cases.push_back({command + " " + flag + " " + v, flag});
  }
  return cases;
}

const std::vector<BadInput> kOtherCases{
    // Seeds: no sign, nothing outside 0..4294967295 (common/limits.h), no junk.
    {"learn --disable R1 --seed -1", "--seed"},
    {"learn --disable R1 --seed 18446744073709551616", "--seed: must be in 0..4294967295"},
    {"learn --disable R1 --seed 4294967296", "--seed: must be in 0..4294967295, got 4294967296"},
    {"learn --disable R1 --seed 1.5", "--seed"},
    {"learn --disable R1 --seed ''", "--seed"},
    {"reproduce --out /tmp/multicpg-bad-rep --seed -7", "--seed"},
    // Leg sets.
    {"learn --disable R9", "R9"},
    {"learn --disable R1,R1", "twice"},
    {"learn --disable R1,", "empty leg"},
    {"learn --disable R1++R3", "empty leg"},
    {"learn --disable r1", "r1"},
    {"learn --disable R1,R2,R3,L1,L2,L3", "every leg"},
    {"learn --robot quadruped --disable R3", "R3"},
    {"walk --disable R1,R2,R3,L1,L2,L3", "every leg"},
    {"walk --robot quadruped --disable L3", "L3"},
    {"tunnel --disable X1", "X1"},
    {"landscape --disable R1,R1 --out /tmp/multicpg-bad-land", "twice"},
    {"gait --disable R7", "R7"},
    // Period maps.
    {"walk --periods 7", "gives no gait"},
    {"walk --periods 0", "gives no gait"},
    {"walk --periods R1=5,R1=6", "twice"},
    {"walk --periods R1=5,", "--periods"},
    {"walk --periods R1=", "--periods"},
    {"walk --periods =5", "--periods"},
    {"walk --periods R1=5x", "--periods"},
    {"walk --periods R1:5", "--periods"},
    {"walk --periods R9=5", "R9"},
    {"walk --periods ''", "--periods"},
    {"tunnel --disable R1 --periods R2=3", "gives no gait"},
    {"gait --period 7", "--period"},
    // Fault timelines.
    {"learn --fault R1,R1@0", "twice"},
    {"learn --fault R1@0 --fault R1@500", "already failed"},
    {"learn --fault R1@900 --recover R1@400", "has not failed"},
    {"learn --recover R1@400", "has not failed"},
    {"learn --fault R1@-5", "--fault"},
    {"learn --fault R1@12x", "--fault"},
    {"learn --fault R1", "LEGS@STEP"},
    {"learn --fault @400", "LEGS@STEP"},
    {"learn --fault R1@0 --fault R2@0 --mode paper", "paper mode"},
    {"walk --fault R1@200000000", "--fault"},
    // Fault kinds (docs/faults.md).
    {"walk --fault R2.CTr:melted@0", "melted"},
    {"walk --fault R2.Knee:locked@0", "Knee"},
    {"walk --fault L1:weak=0@0", "0.01..1"},
    {"walk --fault L1:weak=1.5@0", "0.01..1"},
    {"walk --fault R1:short=2@0", "0.1..1"},
    {"walk --fault imu:drift=20@0", "-10..10"},
    {"walk --fault imu:noise@0", "needs a value"},
    {"walk --fault R2:locked@0", "one joint"},
    {"walk --fault R1.TC:locked=90@0", "limits"},
    {"learn --fault L1:weak=0.3@0 --recover L2:weak@400", "is not weak"},
    {"walk --recover R2.CTr:locked@400", "is not locked"},
    // Terrains.
    {"walk --terrain slope:31", "0..30"},
    {"walk --terrain bumpy", "--terrain"},
    {"tunnel --terrain rough:x", "not a number"},
    {"learn --disable R1 --terrain steps:0.02", "steps:HEIGHT_M:DEPTH_M"},
    {"model --terrain rough:0.01", "--out"},
    // Choices.
    {"learn --disable R1 --mode fast", "fast"},
    {"learn --disable R1 --steering wheel", "wheel"},
    {"learn --disable R1 --mode paper --steering off", "robust-mode"},
    {"learn --disable R1 --mode paper --no-period-learning", "robust-mode"},
    {"learn --robot spider --disable R1", "spider"},
    {"walk --robot ''", "--robot"},
    {"cpg --sync maybe", "--sync"},
    {"experiment table --robot octopod --out /tmp/multicpg-bad-exp", "octopod"},
    // Time steps that do not fit together.
    {"walk --physics-dt 0.003", "--physics-dt"},
    {"walk --control-dt 0.037 --physics-dt 0.0000001", "--physics-dt"},
    {"walk --control-dt 0.0001 --physics-dt 0.001", "--physics-dt"},
    // Paths and missing arguments.
    {"learn", "--disable"},
    {"learn --disable R1 --out ''", "--out"},
    {"learn --disable R1 --out /proc/multicpg-out", "/proc/multicpg-out"},
    {"walk --csv ''", "--csv"},
    {"render --out ''", "--out"},
    {"render --out /tmp/multicpg-bad.gif", "gif"},
    {"render", "--out"},
    {"experiment table --robot quadruped", "--out"},
    {"experiment table --robot quadruped --out ''", "--out"},
    {"experiment results --out /tmp/multicpg-bad.md", "at least one"},
    {"landscape --out /tmp/multicpg-bad-land", "--disable"},
    {"tunnel --disable R1 --learn --periods 4", "exclude"},
    {"tunnel --disable R1 --video ''", "--video"},
    {"model --out ''", "--out"},
    // Body models and postures.
    {"walk --model nosuch", "--model"},
    {"walk --model ''", "--model"},
    {"learn --disable R1 --model Real", "--model"},
    {"walk --disabled-posture 0,0.7", "--disabled-posture"},
    {"walk --disabled-posture 0,0.7,-0.7,0", "--disabled-posture"},
    {"walk --disabled-posture 0,,-0.7", "--disabled-posture"},
    {"walk --disabled-posture 0,1.5,-0.7", "--disabled-posture"},
    {"walk --disabled-posture 0,x,-0.7", "--disabled-posture"},
    {"walk --leg-posture R3", "--leg-posture"},
    {"walk --leg-posture =0,0,0", "--leg-posture"},
    {"walk --leg-posture R3=,,-2", "--leg-posture"},
    {"walk --leg-posture R9=,,-0.5", "--leg-posture"},
    {"walk --leg-posture R3=,,-0.5 --leg-posture R3=0,,", "--leg-posture"},
    {"tunnel --disable R1 --leg-posture L4=0,0.7,-0.7", "--leg-posture"},
    {"walk --total-mass 5 --trunk-mass 4", "--trunk-mass"},
    {"model --list --model nosuch", "--model"},
    // Unknown flags and commands.
    {"walk --speed 3", "--speed"},
    {"fly", "fly"},
    {"learn --disable R1 --beta", "--beta"},
};

TEST(CliBadInput, EveryCaseIsOneLineAndExitTwo) {
  std::vector<BadInput> cases = numeric_cases();
  cases.insert(cases.end(), kOtherCases.begin(), kOtherCases.end());
  ASSERT_GE(cases.size(), 150u);
  for (const BadInput& c : cases) expect_bad_input(c.args, c.must_mention);
}

// A name in another convention or with a slip of case gets the one meant, and every message
// names the flag it came from (docs/cli.md "Exit codes and signals").
TEST(CliBadInput, NamesGetTheOneMeantAndTheFlag) {
  const std::vector<BadInput> cases{
      {"learn --disable RF",
       "--disable: the hexapod has no leg 'RF' (did you mean R1, the right "
       "front leg?)"},
      {"walk --disable LH", "(did you mean L3, the left hind leg?)"},
      {"walk --disable FR", "(did you mean R1, the right front leg?)"},
      {"walk --robot quadruped --disable RR", "(did you mean R2, the right hind leg?)"},
      {"walk --disable lm", "(did you mean L2, the left middle leg?)"},
      {"walk --disable r2", "(did you mean R2, the right middle leg?)"},
      {"walk --periods RF=5", "(did you mean R1, the right front leg?)"},
      {"learn --disable R1 --learner Prior",
       "--learner: unknown learner 'Prior' (did you mean "
       "prior?)"},
      {"learn --disable R1 --mode Paper", "--mode: unknown mode 'Paper' (did you mean paper?)"},
      {"learn --disable R1 --mode foo", "--mode: unknown mode 'foo' (robust or paper)"},
      {"learn --disable R1 --steering Reflex",
       "--steering: unknown steering 'Reflex' (did you "
       "mean reflex?)"},
      {"learner-benchmark --window-order Walked",
       "--window-order: unknown window order 'Walked' "
       "(did you mean walked?)"},
      {"learner-benchmark --mode Robust", "--mode: unknown mode 'Robust' (did you mean robust?)"},
      {"learner-benchmark --learners annealing,Bayes",
       "--learners: unknown learner 'Bayes' (did "
       "you mean bayes?)"},
      {"emulate --hardware examples/hardware/amosii.toml --protocol Dynamixel",
       "--protocol: unknown protocol 'Dynamixel' (did you mean dynamixel?)"},
      {"emulate --hardware examples/hardware/amosii.toml --protocol can",
       "--protocol: unknown protocol 'can' (amosii or dynamixel)"},
      {"walk --robot Hexapod", "--robot: unknown robot 'Hexapod' (did you mean hexapod?)"},
      {"gait --robot Quadruped", "--robot: unknown robot 'Quadruped' (did you mean quadruped?)"},
      {"walk --model Real", "--model: unknown body model 'Real' (did you mean real?)"},
      {"landscape --disable R1 --out /tmp/multicpg-bad-land --steering Off",
       "--steering: unknown steering 'Off' (did you mean off?)"},
  };
  for (const BadInput& c : cases) expect_bad_input(c.args, c.must_mention);
}

}  // namespace
}  // namespace multicpg::testing
