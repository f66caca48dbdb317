#include "apps/replay_output.h"

#include <mujoco/mujoco.h>

#include "common/errors.h"
#include "common/provenance.h"
#include "report/replay/page.h"

namespace multicpg::apps {
std::string command_title() {
  const std::string line = provenance(mj_versionString()).at("command_line").get<std::string>();
  const std::size_t space = line.find(' ');
  return "multicpg" + (space == std::string::npos ? std::string() : line.substr(space));
}

void add_replay_flag(CLI::App& cmd, std::string& path) {
  cmd.add_option("--replay", path,
                 "also write the run as a 3D replay, FILE.html: one page that opens offline in "
                 "any browser (docs/replay.md)");
}

ReplayOutput::ReplayOutput(std::string path) : path_(std::move(path)) {
  if (path_.empty()) return;
  try {
    report::check_replay_path(path_);
  } catch (const BadInput& e) {
    throw BadInput(std::string("--replay: ") + e.what());
  }
  recorder_.emplace();
}

void ReplayOutput::write() const {
  if (recorder_) report::write_replay(recorder_->recording(), command_title(), path_);
}

}  // namespace multicpg::apps
