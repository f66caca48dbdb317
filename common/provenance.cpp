#include "common/provenance.h"

#include <fstream>
#include <mutex>

#include "multicpg_git_commit.h"

namespace multicpg {
namespace {

std::mutex& command_line_mutex() {
  static std::mutex m;
  return m;
}

std::string& command_line() {
  static std::string line;
  return line;
}

// The "model name" of /proc/cpuinfo (Linux), or "unknown".
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}

}  // namespace

void set_command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) line += ' ';
    line += argv[i];
  }
  const std::lock_guard<std::mutex> lock(command_line_mutex());
  command_line() = line;
}

nlohmann::json provenance(const std::string& mujoco_version) {
  const std::lock_guard<std::mutex> lock(command_line_mutex());
  return {{"command_line", command_line()},
          {"git_commit", MULTICPG_GIT_COMMIT},
          {"mujoco_version", mujoco_version},
          {"cpu", cpu_model()}};
}

nlohmann::json build_info(const std::string& mujoco_version) {
  return {{"version", MULTICPG_VERSION},
          {"git_commit", MULTICPG_GIT_COMMIT},
          {"mujoco_version", mujoco_version},
          {"compiler", __VERSION__}};
}

std::string build_info_text(const std::string& mujoco_version) {
  const nlohmann::json info = build_info(mujoco_version);
  return "multicpg " + info.at("version").get<std::string>() + " (git " +
         info.at("git_commit").get<std::string>() + ", MuJoCo " +
         info.at("mujoco_version").get<std::string>() + ", compiler " +
         info.at("compiler").get<std::string>() + ")";
}

}  // namespace multicpg
