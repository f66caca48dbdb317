#include "experiments/run_robot.h"

#include <fstream>
#include <sstream>

#include "common/checksum.h"
#include "common/errors.h"
#include "sim/robot_file.h"

namespace multicpg::experiments {

std::shared_ptr<const RunRobotFile> load_run_robot_file(const std::filesystem::path& path) {
  auto loaded = std::make_shared<RunRobotFile>();
  loaded->file = sim::load_robot_file(path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream toml;
  toml << in.rdbuf();
  // It was read a moment ago: this fails only when the file went away since.
  if (!in) throw BadInput(path.string() + ": file: cannot be read");
  loaded->record = {path.string(), loaded->file.name, checksum_text(toml.str()),
                    checksum_text(loaded->file.model_xml)};
  return loaded;
}

}  // namespace multicpg::experiments
