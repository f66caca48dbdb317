#include "experiments/run_robot.h"

#include <algorithm>
#include <string>
#include <tuple>

#include "common/checksum.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/limits.h"
#include "robot/body_models.h"
#include "sim/robot_file.h"

namespace multicpg::experiments {

std::shared_ptr<const RunRobotFile> load_run_robot_file(const std::filesystem::path& path) {
  auto loaded = std::make_shared<RunRobotFile>();
  loaded->file = sim::load_robot_file(path);
  // Read again for its bytes, as bounded as the first reading (a file swapped for a FIFO in
  // between is refused, not waited on).
  std::string toml;
  try {
    toml = read_input_file(path, sim::kMaxRobotFileBytes, sim::kMaxRobotFileText, "a robot file");
  } catch (const BadInput&) {
    throw BadInput(path.string() + ": file: changed while it was read");
  }
  loaded->record = {path.string(), loaded->file.name, checksum_text(toml),
                    checksum_text(loaded->file.model_xml)};
  return loaded;
}

RobotSpec named_robot(const std::string& name) {
  RobotSpec robot;
  if (sim::is_robot_file(name)) {
    robot.file = load_run_robot_file(name);
    robot.kind = robot.file->file.layout;
  } else {
    robot.kind = robot::parse_robot(name);
  }
  return robot;
}

void record_robot_file(nlohmann::json& json, const std::shared_ptr<const RunRobotFile>& file) {
  if (file) json["robot_file"] = file->record;
}

void record_robot_file(nlohmann::json& json, const RobotSpec& robot) {
  record_robot_file(json, robot.file);
}

std::shared_ptr<const RunRobotFile> recorded_robot_file(const nlohmann::json& record) {
  const auto field = record.find("robot_file");
  if (field == record.end()) return nullptr;
  RobotFileRecord recorded;
  try {
    recorded = field->get<RobotFileRecord>();
  } catch (const nlohmann::json::exception&) {
    throw OptionError("robot_file",
                      "must be a table of path, name, checksum_toml and checksum_model");
  }
  std::shared_ptr<const RunRobotFile> file;
  try {
    file = load_run_robot_file(recorded.path);
  } catch (const BadInput& e) {
    throw OptionError("robot_file.path", e.what());
  }
  const RobotFileRecord& now = file->record;
  for (const auto& [key, was, is] :
       {std::tuple{"name", recorded.name, now.name},
        {"checksum_toml", recorded.checksum_toml, now.checksum_toml},
        {"checksum_model", recorded.checksum_model, now.checksum_model}}) {
    if (was != is) {
      throw OptionError(
          "robot_file." + std::string(key),
          "'" + now.path + "' has changed since it was recorded (" + was + ", now " + is + ")");
    }
  }
  return file;
}

RobotSpec recorded_robot(const nlohmann::json& record) {
  RobotSpec robot;
  robot.file = recorded_robot_file(record);
  if (robot.file) {
    robot.kind = robot.file->file.layout;
    return robot;
  }
  const std::string name = record.at("robot").get<std::string>();
  try {
    robot.kind = robot::parse_robot(name);
  } catch (const BadInput& e) {
    throw OptionError("robot", e.what());
  }
  return robot;
}

bool operator==(const RobotSpec& a, const RobotSpec& b) {
  const bool same_file = a.file && b.file ? a.file->record == b.file->record : a.file == b.file;
  return a.kind == b.kind && same_file && a.sim == b.sim;
}

namespace {

// A robot file's body is its MJCF: of the body parameters only those of the controller apply
// (the disabled legs' posture and the body lift, robot/body_params.h).
void validate_file_robot(const sim::SimOptions& options) {
  if (options.model != robot::kDefaultBodyModel) {
    throw OptionError("sim.model", "a robot file's body is its model (docs/robots.md)");
  }
  const robot::BodyParams defaults = robot::body_params(robot::kDefaultBodyModel);
  for (const robot::NumberParam& p : robot::number_params()) {
    const bool controller = p.key == "lift_body" || p.key.starts_with("disabled_posture");
    if (!controller && p.get(options.body) != p.get(defaults)) {
      throw OptionError("sim.body." + std::string(p.key),
                        "a robot file's body is its model (docs/robots.md)");
    }
  }
}

}  // namespace

void validate(const RobotSpec& robot) {
  within("sim", [&] { sim::validate(robot.sim, robot.kind); });
  if (robot.file) validate_file_robot(robot.sim);
}

const robot::Morphology& morphology(const RobotSpec& robot) {
  return robot::morphology(robot.kind);
}

sim::SimModel make_model(const RobotSpec& robot) {
  return robot.file ? sim::make_sim_model(robot.file->file, robot.sim)
                    : sim::make_sim_model(robot.kind, robot.sim);
}

std::shared_ptr<const sim::SimModel> ModelCache::model(const RobotSpec& robot) {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::erase_if(models_, [](const auto& entry) { return entry.second.expired(); });
  const auto found = std::find_if(models_.begin(), models_.end(),
                                  [&](const auto& entry) { return entry.first == robot; });
  // Its last user may let it go between the pruning and here.
  if (found != models_.end()) {
    if (std::shared_ptr<const sim::SimModel> model = found->second.lock()) return model;
  }
  auto made = std::make_shared<const sim::SimModel>(make_model(robot));
  if (found != models_.end()) {
    found->second = made;
  } else {
    models_.emplace_back(robot, made);
  }
  return made;
}

}  // namespace multicpg::experiments
