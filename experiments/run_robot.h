// The robot a run walks (RobotSpec): a built-in robot or a robot file, with its simulation
// options, held by every spec that runs a robot (RunSpec, LandscapeSpec, ExperimentSpec,
// CalibrationSpec, Python's Robot), and the one cache of the models made from it. A robot file
// is carried with the record every output keeps of it, so a result names the robot it was walked
// with and a resumed experiment sees when that robot changed (docs/robots.md "Your robot: robot
// files").
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "robot/morphology.h"
#include "robot/robot_file.h"
#include "sim/sim.h"

namespace multicpg::experiments {

struct RobotFileRecord {
  std::string path;            // the TOML, as read
  std::string name;            // its `name`
  std::string checksum_toml;   // of the TOML's bytes (common/checksum.h)
  std::string checksum_model;  // of its MJCF's text

  bool operator==(const RobotFileRecord&) const = default;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RobotFileRecord, path, name, checksum_toml, checksum_model)

struct RunRobotFile {
  robot::RobotFile file;
  RobotFileRecord record;
};

// The robot file at `path` and its record. Throws BadInput as sim::load_robot_file does.
std::shared_ptr<const RunRobotFile> load_run_robot_file(const std::filesystem::path& path);

// The built-in robot, or with a robot file the built-in whose layout it has (its legs,
// controller, servos and fault geometry; robot/robot_file.h), in the world its options make.
struct RobotSpec {
  robot::RobotKind kind = robot::RobotKind::hexapod;  // with a robot file, its layout
  std::shared_ptr<const RunRobotFile> file;           // null: the built-in robot
  sim::SimOptions sim;  // time steps, servos, scene, the controller's parameters, the body
};

// The robot `name` names, with default options: a built-in robot ("hexapod") or a robot file
// ("FILE.toml", sim::is_robot_file). Throws BadInput as robot::parse_robot and
// load_run_robot_file do.
RobotSpec named_robot(const std::string& name);

// Adds "robot_file" (RobotFileRecord) to `json` when the robot is a robot file's (`file` not
// null); a built-in robot's records stay as they were.
void record_robot_file(nlohmann::json& json, const std::shared_ptr<const RunRobotFile>& file);
void record_robot_file(nlohmann::json& json, const RobotSpec& robot);

// The robot file of a record record_robot_file wrote, read again from its recorded path; null
// for a record without one (a built-in robot's). The file must still hold the robot recorded.
// Throws OptionError keyed "robot_file" for a value that is no RobotFileRecord, "robot_file.path"
// for a file that cannot be read (as load_run_robot_file), and "robot_file.name",
// "robot_file.checksum_toml" or "robot_file.checksum_model": "'PATH' has changed since it was
// recorded (WAS, now IS)".
std::shared_ptr<const RunRobotFile> recorded_robot_file(const nlohmann::json& record);

// The robot of a record: its robot file (recorded_robot_file), else the built-in robot its
// "robot" names; default simulation options. Throws OptionError as recorded_robot_file does, or
// keyed "robot" for an unknown robot (nlohmann's exception for a record without "robot").
RobotSpec recorded_robot(const nlohmann::json& record);

// Equal robots make equal models: the same kind, robot file (by its record) and options.
bool operator==(const RobotSpec& a, const RobotSpec& b);

// Throws OptionError naming the key of the first bad option: "sim.control_dt",
// "sim.body.leg_postures[0].leg" (sim::validate), and with a robot file "sim.model" and
// "sim.body.<key>" for a body parameter other than the controller's (its body is its model).
void validate(const RobotSpec& robot);

// The robot's leg layout.
const robot::Morphology& morphology(const RobotSpec& robot);

// The robot's simulation.
sim::SimModel make_model(const RobotSpec& robot);

// The models of equal robots, made once and shared read-only while any user holds one (a
// compile takes tens of milliseconds: a sweep's runs and Python's equal robots share theirs).
// Thread-safe; a model is made under the cache's lock.
class ModelCache {
 public:
  std::shared_ptr<const sim::SimModel> model(const RobotSpec& robot);

 private:
  std::mutex mutex_;
  // Few distinct robots at a time (a sweep's grid of sim options at most): searched in order.
  std::vector<std::pair<RobotSpec, std::weak_ptr<const sim::SimModel>>> models_;
};

}  // namespace multicpg::experiments
