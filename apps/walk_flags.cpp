#include "apps/walk_flags.h"

#include "apps/options.h"
#include "common/errors.h"

namespace multicpg::apps {

void add_walk_flags(CLI::App& cmd, WalkFlags& f) {
  cmd.add_option("--robot", f.robot, "hexapod, quadruped or octopod")->capture_default_str();
  cmd.add_option("--periods", f.periods,
                 "CPG period of every leg (1, 4, 5, 6, 8, 9), or per leg: R1=5,R2=4,... "
                 "(unnamed legs 4)")
      ->capture_default_str();
  cmd.add_option("--disable", f.disable, "legs that fail, e.g. R1,R3");
  cmd.add_option("--disable-at", f.disable_at, "controller step (from 0) at which they fail")
      ->capture_default_str();
}

void require_working_leg(const robot::Morphology& morph, const std::vector<std::size_t>& disabled) {
  if (disabled.size() == morph.size()) {
    throw BadInput("--disable: cannot disable every leg of the " + morph.name);
  }
}

WalkChoice parse_walk_flags(const WalkFlags& f) {
  const robot::RobotKind kind = robot::parse_robot(f.robot);
  const robot::Morphology& morph = robot::morphology(kind);
  WalkChoice choice{kind, parse_periods(morph, f.periods), robot::parse_leg_list(morph, f.disable),
                    f.disable_at};
  require_working_leg(morph, choice.disabled);
  if (f.disable_at < 0) {
    throw BadInput("--disable-at must not be negative, got " + std::to_string(f.disable_at));
  }
  return choice;
}

}  // namespace multicpg::apps
