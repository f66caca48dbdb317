// Where a result came from, recorded with every experiment: the command line,
// the project's git commit, the MuJoCo version and the CPU. Not compared on resume: the same
// experiment may be continued from another shell or machine.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace multicpg {

// Remembers the program's arguments (main calls it first thing).
void set_command_line(int argc, const char* const* argv);

// {"command_line", "git_commit", "mujoco_version", "cpu"}. The MuJoCo version is passed in, so
// this library does not link MuJoCo.
nlohmann::json provenance(const std::string& mujoco_version);

// What this program is: {"version" (the project's), "git_commit" ("+dirty" with uncommitted
// changes, "unknown" outside a git checkout), "mujoco_version", "compiler"}; `multicpg
// --version` prints it.
nlohmann::json build_info(const std::string& mujoco_version);
// build_info as one line: "multicpg 0.1.0 (git 1a2b3c4, MuJoCo 2.2.2, compiler 12.2.0)".
std::string build_info_text(const std::string& mujoco_version);

}  // namespace multicpg
