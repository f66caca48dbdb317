#include "apps/run_flags.h"

#include <algorithm>
#include <map>

#include "apps/flag_checks.h"
#include "apps/options.h"
#include "apps/sim_flags.h"
#include "body/fault_spec.h"
#include "common/errors.h"
#include "robot/leg_sets.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

// The fault timeline of --disable/--disable-at, --fault and --recover, in step order.
body::FaultTimeline parse_faults(const robot::Morphology& morph, const RunFlags& f) {
  body::FaultTimeline faults =
      body::fail_at(parse_leg_flag(morph, f.disable, "--disable"), f.disable_at);
  const auto add = [&](const std::vector<std::string>& texts, bool recover) {
    for (const std::string& text : texts) {
      try {
        faults.push_back(body::parse_fault(morph, text, recover));
      } catch (const BadInput& e) {
        throw BadInput(std::string(recover ? "--recover" : "--fault") + ": " + e.what());
      }
    }
  };
  add(f.faults, false);
  add(f.recoveries, true);
  body::sort_timeline(faults);
  return faults;
}

// The flags the user gave for the run's faults, "--disable/--fault" as the message names them.
std::string fault_flags(const RunFlags& f) {
  std::string flags;
  const auto add = [&](bool given, const char* flag) {
    if (!given) return;
    if (!flags.empty()) flags += '/';
    flags += flag;
  };
  add(!f.disable.empty(), "--disable");
  add(!f.disable.empty() && f.disable_at > 0, "--disable-at");
  add(!f.faults.empty(), "--fault");
  add(!f.recoveries.empty(), "--recover");
  return flags.empty() ? "--disable or --fault" : flags;
}

}  // namespace

void add_robot_flag(CLI::App& cmd, RunFlags& f) {
  cmd.add_option("--robot", f.robot,
                 "hexapod, quadruped, octopod or a robot file FILE.toml (docs/robots.md)")
      ->check(robot_name())
      ->capture_default_str();
}

void add_start_flags(CLI::App& cmd, RunFlags& f) {
  cmd.add_option("--periods", f.periods,
                 "CPG period of every leg (1, 4, 5, 6, 8, 9), or per leg: R1=5,R2=4,... "
                 "(unnamed legs 4)")
      ->capture_default_str();
  CLI::Option* warmup =
      cmd.add_option("--warmup", f.warmup,
                     "controller steps run before the robot moves, so it starts walking with "
                     "locked CPGs and full delay lines")
          ->check(in(body::kStepLimits))
          ->capture_default_str();
  // Flags that contradict one another or do nothing alone are refused, never silently ignored.
  cmd.add_flag("--cold", f.cold, "start from a cold controller (no warm-up, as --warmup 0)")
      ->excludes(warmup);
}

void add_fault_flags(CLI::App& cmd, RunFlags& f) {
  CLI::Option* disable = cmd.add_option("--disable", f.disable, "legs that fail, e.g. R1,R3");
  cmd.add_option("--disable-at", f.disable_at,
                 "controller step (from 0) at which the legs of --disable fail")
      ->check(in(body::kStepLimits))
      ->capture_default_str()
      ->needs(disable);
  cmd.add_option("--fault", f.faults,
                 "SPEC@STEP: a fault before that step (repeatable). SPEC: LEGS (the legs fail, "
                 "R1,R3), LEGS.JOINT:locked[=DEG], LEGS.JOINT:passive, LEGS[.JOINT]:weak=FACTOR, "
                 "LEGS:short=FRACTION, LEGS:slip=FACTOR, imu:drift=DEG_PER_S, imu:noise=DEG "
                 "(docs/faults.md)");
  cmd.add_option("--recover", f.recoveries,
                 "SPEC@STEP: that fault ends from that step (repeatable; the value may be left "
                 "out)");
}

void add_walk_flags(CLI::App& cmd, RunFlags& f) {
  add_robot_flag(cmd, f);
  add_start_flags(cmd, f);
  add_fault_flags(cmd, f);
}

std::string flag_of(const std::string& key, const RunFlags& f) {
  // The learning options' flag names differ from their keys.
  static const std::map<std::string, std::string> kFlags{
      {"robot", "--robot"},
      {"start.periods", "--periods"},
      {"start.warmup", "--warmup"},
      {"sim.scene.terrain", "--terrain"},
      {"learning.annealing.beta", "--beta"},
      {"learning.annealing.threshold_deg", "--threshold"},
      {"learning.annealing.max_trials", "--max-trials"},
      {"learning.window_steps", "--window"},
      {"learning.settle_steps", "--settle"},
      {"hardware.file", "--hardware"},
  };
  if (key == "faults") return fault_flags(f);
  const std::string option = "learning.learner.options.";
  if (key.rfind(option, 0) == 0) return "--learner-option " + key.substr(option.size());
  if (key.rfind("learning.learner", 0) == 0) return "--learner";
  if (const auto it = kFlags.find(key); it != kFlags.end()) return it->second;
  if (key.rfind("sim.", 0) == 0) return sim_flag(key.substr(4));
  // sim.control_dt -> --control-dt, learning.hold_windows -> --hold-windows, steps -> --steps
  std::string flag = "--" + key.substr(key.find('.') + 1);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

void add_hardware_flags(CLI::App& cmd, RunFlags& flags) {
  cmd.add_option("--hardware", flags.hardware,
                 "run on a real robot through this hardware file (docs/hardware.md), in real time "
                 "at the control rate");
  cmd.add_flag("--lock-step", flags.lock_step,
               "with --hardware: no pacing, each step as soon as the last one's answers came "
               "(rehearsal with `multicpg emulate`; never on a real robot)");
}

std::optional<experiments::HardwareSetup> hardware_setup(const experiments::RunSpec& spec,
                                                         const RunFlags& flags) {
  if (!spec.hardware) return std::nullopt;
  try {
    return experiments::hardware_setup(spec);
  } catch (const OptionError& e) {
    throw BadInput(flag_of(e.key(), flags) + ": " + e.what());
  }
}

experiments::RunSpec run_spec(const RunFlags& f, bool learn) {
  if (f.lock_step && f.hardware.empty()) throw BadInput("--lock-step needs --hardware");
  experiments::RunSpec spec;
  if (!f.hardware.empty()) spec.hardware = experiments::HardwareSpec{f.hardware, f.lock_step};
  spec.robot = experiments::named_robot(f.robot);
  spec.robot.sim = with_body(f.sim, f.body);
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  spec.faults = parse_faults(morph, f);
  if (learn) {
    spec.learning = learning_options(f.learning, spec.robot, spec.faults);
    spec.start = experiments::learning_start(spec.learning->mode);
    try {
      spec.learning->learner = learning::resolve_learner(spec.learning->learner);
    } catch (const OptionError& e) {
      throw BadInput(flag_of("learning.learner." + e.key(), f) + ": " + e.what());
    }
  } else {
    spec.start = {parse_periods_flag(morph, f.periods, "--periods"), f.cold ? 0 : f.warmup};
  }
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    throw BadInput(flag_of(e.key(), f) + ": " + e.what());
  }
  return spec;
}

}  // namespace multicpg::apps
