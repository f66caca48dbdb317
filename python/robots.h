// Robots in Python (python/robots.cpp): a robot and its compiled model, and the arguments that
// name one (a Robot, a robot name, or a robot file FILE.toml).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <string_view>

#include "experiments/run_robot.h"
#include "python/keywords.h"
#include "robot/morphology.h"
#include "robot/terrain.h"
#include "sim/sim.h"

namespace multicpg::python {

namespace py = pybind11;

// A robot and its simulation model, shared read-only by every Simulation of it. Two robots are
// equal when their specs are (the same kind, robot file and options), whichever object holds them.
struct Robot {
  experiments::RobotSpec spec;
  std::shared_ptr<const sim::SimModel> model;  // of every robot equal to it (ModelCache)

  const robot::Morphology& morph() const { return model->controller.morphology; }
};

// The Python parameter a simulation option is set by (for messages).
std::string sim_argument(const std::string& key);
// A terrain argument: a multicpg.Terrain, or its text ("slope:5", robot/terrain.h).
robot::Terrain terrain_arg(py::handle value, std::string_view name);

// The simulation's keywords (Robot's and tunnel's): control_dt, physics_dt, servo_gain, terrain,
// model, body; and the options they give.
Params sim_params();
sim::SimOptions sim_options(const Keywords& k, bool tunnel);

// A robot checked whole; a bad option is a ValueError naming its argument.
std::shared_ptr<Robot> robot_of(experiments::RobotSpec spec);
// Robot.from_file: a bad file is a ValueError with the CLI's one line.
std::shared_ptr<const experiments::RunRobotFile> load_robot_file(const std::string& path);
// A robot's key, its pickled form (and a State's "robot"): {"robot": its layout's name,
// "robot_file": the file's record (with a robot file), "sim": its options}.
nlohmann::json robot_key(const experiments::RobotSpec& spec);
// The robot a key records (experiments::recorded_robot), default options: a robot file that
// cannot be read or changed since, or an unknown robot, is a ValueError naming `name`.
experiments::RobotSpec recorded_robot(const nlohmann::json& key, std::string_view name);
// A robot read back from its key (a pickled Robot or State).
std::shared_ptr<Robot> robot_from_key(const nlohmann::json& key, std::string_view name);
// A robot argument: a Robot, a robot name or a robot file, the latter two with default options.
std::shared_ptr<Robot> robot_arg(py::handle robot, std::string_view name = "robot");
// The robot on `terrain` (None: as it is).
std::shared_ptr<Robot> with_terrain(const std::shared_ptr<Robot>& robot, py::handle terrain);
// multicpg.Robot('hexapod', terrain='slope:5'): how to make it again.
std::string robot_repr(const Robot& r);

// multicpg.Terrain and multicpg.Robot.
void register_robots(py::module_& m);

}  // namespace multicpg::python
