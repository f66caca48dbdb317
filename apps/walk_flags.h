// Flags of the commands that walk a robot (walk, render, view): which robot, its periods, which
// legs fail and when. Declared and checked in one place; each throws BadInput with one line.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::apps {

struct WalkFlags {
  std::string robot = "hexapod";
  std::string periods = "4";
  std::string disable;
  long disable_at = 0;
};

// Adds --robot, --periods, --disable and --disable-at.
void add_walk_flags(CLI::App& cmd, WalkFlags& flags);

struct WalkChoice {
  robot::RobotKind kind;
  std::vector<int> periods;           // one per leg, gait periods only
  std::vector<std::size_t> disabled;  // never every leg
  long disable_at;                    // >= 0
};

WalkChoice parse_walk_flags(const WalkFlags& flags);

// Throws unless some leg of `morph` stays working.
void require_working_leg(const robot::Morphology& morph, const std::vector<std::size_t>& disabled);

}  // namespace multicpg::apps
