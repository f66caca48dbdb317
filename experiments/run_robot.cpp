#include "experiments/run_robot.h"

#include <fstream>
#include <string>

#include "common/checksum.h"
#include "common/errors.h"
#include "sim/robot_file.h"

namespace multicpg::experiments {

std::shared_ptr<const RunRobotFile> load_run_robot_file(const std::filesystem::path& path) {
  auto loaded = std::make_shared<RunRobotFile>();
  loaded->file = sim::load_robot_file(path);
  // Read again for its bytes, as bounded as the first reading (which checked it is a regular
  // file of at most kMaxRobotFileBytes).
  std::ifstream in(path, std::ios::binary);
  std::string toml(sim::kMaxRobotFileBytes + 1, '\0');
  in.read(toml.data(), static_cast<std::streamsize>(toml.size()));
  toml.resize(static_cast<std::size_t>(in.gcount()));
  if (!in.is_open() || in.bad() || toml.size() > sim::kMaxRobotFileBytes) {
    throw BadInput(path.string() + ": file: changed while it was read");
  }
  loaded->record = {path.string(), loaded->file.name, checksum_text(toml),
                    checksum_text(loaded->file.model_xml)};
  return loaded;
}

}  // namespace multicpg::experiments
