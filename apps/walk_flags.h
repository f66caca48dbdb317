// Flags of the commands that walk a robot (walk, render, view): which robot, its periods, which
// legs fail and when. Declared and checked in one place; each throws BadInput with one line.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "robot/morphology.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace multicpg::apps {

struct WalkFlags {
  std::string robot = "hexapod";
  std::string periods = "4";
  std::string disable;
  long disable_at = 0;
  std::vector<std::string> faults;      // --fault LEGS@STEP, repeatable
  std::vector<std::string> recoveries;  // --recover LEGS@STEP, repeatable
  long warmup = sim::kControllerWarmup;
  bool cold = false;
};

// Adds --robot, --periods, --disable, --disable-at, --fault, --recover, --warmup and --cold.
void add_walk_flags(CLI::App& cmd, WalkFlags& flags);
// Adds only the fault flags (--disable, --disable-at, --fault, --recover).
void add_fault_flags(CLI::App& cmd, WalkFlags& flags);

struct WalkChoice {
  robot::RobotKind kind;
  std::vector<int> periods;           // one per leg, gait periods only
  std::vector<std::size_t> disabled;  // legs of --disable (never every leg)
  long disable_at;                    // >= 0
  sim::FaultTimeline faults;          // --disable/--disable-at and every --fault/--recover
  long warmup;                        // 0 with --cold
};

WalkChoice parse_walk_flags(const WalkFlags& flags);

// The fault timeline of --disable/--disable-at, --fault and --recover, in step order (a
// recovery before a failure at the same step); throws BadInput (sim::validate) when it cannot
// happen.
sim::FaultTimeline parse_faults(const robot::Morphology& morph, const WalkFlags& flags);

// Throws BadInput naming --disable-at (or --recover) unless every fault comes before step
// `steps` of a run.
void require_faults_within(const sim::FaultTimeline& faults, long steps);

// sim::walk, a bad spec named by the flags that set it (--steps, --settle, --window, --warmup,
// --periods; --disable-at, --fault or --recover for a fault) instead of the spec's keys.
sim::WalkResult walk_with_flags(const sim::SimModel& model, const sim::WalkSpec& spec);

// Throws unless some leg of `morph` stays working.
void require_working_leg(const robot::Morphology& morph, const std::vector<std::size_t>& disabled);

}  // namespace multicpg::apps
