// `--replay FILE.html` of walk, learn, tunnel and render: the run recorded as it goes and written
// as a 3D replay page (report/replay/page.h, docs/replay.md).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "report/replay/recording.h"

namespace multicpg::apps {

// "multicpg learn --disable R1 ...": the command line with the program's name as users type it
// (the replay's and the --plot picture's title), an absolute path cut to its file's name.
std::string command_title();

// Adds --replay, bound to `path`.
void add_replay_flag(CLI::App& cmd, std::string& path);

// A replay to write, when --replay named a file.
class ReplayOutput {
 public:
  // Checks the path before any work (BadInput naming --replay) and starts recording.
  explicit ReplayOutput(std::string path);
  // The recorder to attach to the run; null without --replay.
  sim::Observer* observer() { return recorder_ ? &*recorder_ : nullptr; }
  // Writes the page (when --replay named one), titled with the command line.
  void write() const;

 private:
  std::string path_;
  std::optional<report::ReplayRecorder> recorder_;
};

}  // namespace multicpg::apps
