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

}  // namespace multicpg
