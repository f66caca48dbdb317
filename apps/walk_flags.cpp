#include "apps/walk_flags.h"

#include <algorithm>

#include "apps/flag_checks.h"
#include "apps/options.h"
#include "common/errors.h"
#include "robot/leg_sets.h"
#include "sim/walk.h"

namespace multicpg::apps {

void add_walk_flags(CLI::App& cmd, WalkFlags& f) {
  cmd.add_option("--robot", f.robot, "hexapod, quadruped or octopod")->capture_default_str();
  cmd.add_option("--periods", f.periods,
                 "CPG period of every leg (1, 4, 5, 6, 8, 9), or per leg: R1=5,R2=4,... "
                 "(unnamed legs 4)")
      ->capture_default_str();
  add_fault_flags(cmd, f);
  cmd.add_option("--warmup", f.warmup,
                 "controller steps run before the robot moves, so it starts walking with locked "
                 "CPGs and full delay lines")
      ->check(in(sim::kStepLimits))
      ->capture_default_str();
  cmd.add_flag("--cold", f.cold, "start from a cold controller (no warm-up, as --warmup 0)");
}

void add_fault_flags(CLI::App& cmd, WalkFlags& f) {
  cmd.add_option("--disable", f.disable, "legs that fail, e.g. R1,R3");
  cmd.add_option("--disable-at", f.disable_at, "controller step (from 0) at which they fail")
      ->check(in(sim::kStepLimits))
      ->capture_default_str();
  cmd.add_option("--fault", f.faults, "LEGS@STEP: these legs fail before that step (repeatable)");
  cmd.add_option("--recover", f.recoveries,
                 "LEGS@STEP: these failed legs work again from that step (repeatable)");
}

namespace {

sim::Fault parse_fault(const robot::Morphology& morph, const std::string& text, bool recover) {
  const char* flag = recover ? "--recover" : "--fault";
  const std::size_t at = text.find('@');
  if (at == std::string::npos || at == 0 || at + 1 == text.size()) {
    throw BadInput(std::string(flag) + " takes LEGS@STEP, e.g. R1@0 or R1,R3@6000; got '" + text +
                   "'");
  }
  sim::Fault f;
  f.recover = recover;
  f.legs = robot::parse_leg_set(morph, text.substr(0, at));
  f.step = parse_step(text.substr(at + 1), flag);
  return f;
}

}  // namespace

sim::FaultTimeline parse_faults(const robot::Morphology& morph, const WalkFlags& f) {
  if (f.disable_at < 0) {
    throw BadInput("--disable-at must not be negative, got " + std::to_string(f.disable_at));
  }
  sim::FaultTimeline faults;
  const std::vector<std::size_t> disabled = parse_leg_flag(morph, f.disable, "--disable");
  if (!disabled.empty()) faults.push_back({f.disable_at, disabled, false});
  for (const std::string& t : f.faults) faults.push_back(parse_fault(morph, t, false));
  for (const std::string& t : f.recoveries) faults.push_back(parse_fault(morph, t, true));
  std::stable_sort(faults.begin(), faults.end(), [](const sim::Fault& a, const sim::Fault& b) {
    return a.step != b.step ? a.step < b.step : a.recover && !b.recover;
  });
  sim::validate(morph, faults);
  return faults;
}

void require_faults_within(const sim::FaultTimeline& faults, long steps) {
  for (const sim::Fault& f : faults) {
    if (f.step >= steps) {
      throw BadInput(std::string(f.recover ? "--recover" : "--disable-at") + " must be in 0.." +
                     std::to_string(steps - 1) + ", got " + std::to_string(f.step));
    }
  }
}

sim::WalkResult walk_with_flags(const sim::SimModel& model, const sim::WalkSpec& spec) {
  require_faults_within(spec.faults, spec.settle + spec.steps);
  try {
    return sim::walk(model, spec);
  } catch (const OptionError& e) {
    const std::string flag =
        e.key() == "faults" ? "--disable-at, --fault or --recover" : "--" + e.key();
    throw BadInput(flag + ": " + e.what());
  }
}

void require_working_leg(const robot::Morphology& morph, const std::vector<std::size_t>& disabled) {
  if (disabled.size() == morph.size()) {
    throw BadInput("--disable: cannot disable every leg of the " + morph.name);
  }
}

WalkChoice parse_walk_flags(const WalkFlags& f) {
  const robot::RobotKind kind = robot::parse_robot(f.robot);
  const robot::Morphology& morph = robot::morphology(kind);
  WalkChoice choice{kind,
                    parse_periods_flag(morph, f.periods, "--periods"),
                    parse_leg_flag(morph, f.disable, "--disable"),
                    f.disable_at,
                    parse_faults(morph, f),
                    f.cold ? 0 : f.warmup};
  require_working_leg(morph, choice.disabled);
  return choice;
}

}  // namespace multicpg::apps
