// A robot file as runs carry it (experiments::RunSpec): the leg map and model it describes, and
// the record every output of a run keeps of it, so a result names the robot it was walked with
// and a resumed experiment sees when that robot changed (docs/robots.md "Your robot: robot
// files").
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "robot/robot_file.h"

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

}  // namespace multicpg::experiments
