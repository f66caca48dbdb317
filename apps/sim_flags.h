// Flags of every command that simulates a robot: time steps and servo gain (docs/robots.md
// "Servos"), bound directly to sim::SimOptions, and the body (robot/body_params.h): a named model
// and one flag per physical parameter over it.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "robot/body_models.h"
#include "sim/sim.h"

namespace multicpg::apps {

// The body flags as given: a model, and the parameters given to override its values.
struct BodyFlags {
  std::string model{robot::to_string(robot::kDefaultBodyModel)};
  std::optional<std::string> disabled_posture;  // "TC,CTr,FTi"
  std::vector<std::string> leg_postures;        // "LEG=TC,CTr,FTi", repeatable
  std::optional<double> lift_body;
  std::optional<double> total_mass;
  std::optional<double> trunk_mass;
  std::optional<double> foot_friction;
  std::optional<double> trunk_friction;
  std::optional<double> slip;
  std::optional<double> joint_compliance;
  std::optional<double> torsional_friction;
  std::optional<double> rolling_friction;
  std::optional<double> servo_torque;
  std::optional<double> servo_speed;
};

// Adds --control-dt --physics-dt, and --servo-gain unless `with_servo` is false (commands that
// only write the model), writing into `options`, and the body flags (add_body_flags). Each
// range is shown in --help and checked at parse time.
void add_sim_flags(CLI::App& cmd, sim::SimOptions& options, BodyFlags& body,
                   bool with_servo = true);
// Adds --model and the option group "Body": one flag per physical parameter.
void add_body_flags(CLI::App& cmd, BodyFlags& body);

// `options` with the body of the flags: the model's parameters, the given flags over them. Throws
// BadInput naming the flag of a posture that does not parse; checked whole with the run.
sim::SimOptions with_body(const sim::SimOptions& options, const BodyFlags& body);
// `options` with the body of the flags, checked whole for `kind` (sim::validate); throws
// BadInput naming the flag.
sim::SimOptions sim_options(const sim::SimOptions& options, const BodyFlags& body,
                            robot::RobotKind kind);
// The flag bound to a simulation option's key: "body.total_mass" -> "--total-mass",
// "control_dt" -> "--control-dt".
std::string sim_flag(const std::string& key);
// `options` checked whole (sim::validate: a control step that is not a whole multiple of the
// physics step); throws OptionError naming the flag.
sim::SimOptions sim_options(const sim::SimOptions& options);

}  // namespace multicpg::apps
