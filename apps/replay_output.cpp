#include "apps/replay_output.h"

#include <mujoco/mujoco.h>

#include <filesystem>

#include "common/errors.h"
#include "common/provenance.h"
#include "report/replay/page.h"

namespace multicpg::apps {
namespace {

// `word` with an absolute path ("/home/me/runs/walk.html", "--out=/tmp/x") cut to the file's
// name: a page or picture shared with others does not carry the folders of who made it.
std::string without_folders(const std::string& word) {
  const std::size_t eq = word.find('=');
  const std::size_t start = word.rfind("--", 0) == 0 && eq != std::string::npos ? eq + 1 : 0;
  if (word.compare(start, 1, "/") != 0) return word;
  return word.substr(0, start) + std::filesystem::path(word.substr(start)).filename().string();
}

}  // namespace

std::string command_title() {
  const std::string line = provenance(mj_versionString()).at("command_line").get<std::string>();
  std::string title = "multicpg";
  std::size_t space = line.find(' ');
  while (space != std::string::npos) {
    const std::size_t next = line.find(' ', space + 1);
    title +=
        ' ' + without_folders(line.substr(
                  space + 1, next == std::string::npos ? std::string::npos : next - space - 1));
    space = next;
  }
  return title;
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
