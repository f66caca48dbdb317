// The flags that describe one run (experiments::RunSpec): which robot, how it starts, what fails
// when, how it learns and how it is simulated. Declared once for every command that walks or
// learns, and turned into one checked RunSpec whose errors name the flag the user typed.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "apps/learning_options.h"
#include "apps/sim_flags.h"
#include "experiments/bodies.h"
#include "experiments/run_spec.h"
#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::apps {

struct RunFlags {
  std::string robot = "hexapod";
  std::string periods = "4";
  long warmup = body::kControllerWarmup;
  bool cold = false;
  std::string disable;
  long disable_at = 0;
  std::vector<std::string> faults;      // --fault LEGS@STEP, repeatable
  std::vector<std::string> recoveries;  // --recover LEGS@STEP, repeatable
  LearningFlags learning;
  sim::SimOptions sim;
  BodyFlags body;        // the body model and parameters over it (apps/sim_flags.h)
  std::string hardware;  // --hardware FILE.toml: a real robot walks the run (docs/hardware.md)
  bool lock_step = false;
};

// --robot.
void add_robot_flag(CLI::App& cmd, RunFlags& flags);
// --periods, --warmup and --cold.
void add_start_flags(CLI::App& cmd, RunFlags& flags);
// --disable, --disable-at, --fault and --recover.
void add_fault_flags(CLI::App& cmd, RunFlags& flags);
// --robot, the start and the fault flags: the commands that walk a robot (walk, render, view).
void add_walk_flags(CLI::App& cmd, RunFlags& flags);

// --hardware and --lock-step.
void add_hardware_flags(CLI::App& cmd, RunFlags& flags);

// The run the flags describe: a walk from --periods and --warmup, or with `learn` a learning run
// (the learning flags; it starts as experiments::learning_start says), on the simulation or, with
// --hardware, a real robot. Checked whole (experiments::validate); throws BadInput, one line
// naming the flag of the bad value.
experiments::RunSpec run_spec(const RunFlags& flags, bool learn);

// What a run on a real robot needs (experiments::hardware_setup), checked before any port opens;
// nothing for the simulation. Throws BadInput naming the flag of a bad value.
std::optional<experiments::HardwareSetup> hardware_setup(const experiments::RunSpec& spec,
                                                         const RunFlags& flags);

// The flag the user typed for a RunSpec key ("sim.control_dt" -> "--control-dt", "faults" -> the
// fault flags given).
std::string flag_of(const std::string& key, const RunFlags& flags);

}  // namespace multicpg::apps
