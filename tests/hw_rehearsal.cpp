#include "tests/hw_rehearsal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests/cli_runner.h"

namespace multicpg::testing {

Rehearsal::Rehearsal(const std::string& example, int timeout_ms,
                     const std::vector<std::string>& args,
                     const std::vector<std::pair<std::string, std::string>>& edits)
    : dir_(make_temp_dir("multicpg-hw-")) {
  const std::filesystem::path source =
      std::filesystem::path(MULTICPG_SOURCE_DIR) / "examples" / "hardware" / example;
  std::string text = std::regex_replace(read_file(source.string()), std::regex("timeout_ms = \\d+"),
                                        "timeout_ms = " + std::to_string(timeout_ms));
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const std::string hardware = dir_ + "/" + example;
  std::ofstream(hardware) << text;
  rehearsal_ = dir_ + "/rehearsal.toml";
  log_ = dir_ + "/emulator.jsonl";
  std::vector<std::string> argv{"emulate",  "--hardware", hardware, "--rehearsal",
                                rehearsal_, "--log",      log_};
  if (std::find(args.begin(), args.end(), "--runs") == args.end()) {
    argv.insert(argv.end(), {"--runs", "1"});
  }
  argv.insert(argv.end(), args.begin(), args.end());
  emulator_ = std::make_unique<CliProcess>(argv);
  const bool ready = wait_until(
      [&] { return std::filesystem::exists(rehearsal_) || emulator_->status_kb("VmRSS") < 0; },
      std::chrono::seconds(60));
  EXPECT_TRUE(ready && std::filesystem::exists(rehearsal_)) << emulator_->err();
}

Rehearsal::~Rehearsal() {
  emulator_.reset();
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

void Rehearsal::signal(int sig) const {
  emulator_->signal(sig);
}

bool Rehearsal::finish() {
  return emulator_->wait(std::chrono::seconds(60));
}

std::vector<nlohmann::json> Rehearsal::events(const std::string& kind) const {
  std::vector<nlohmann::json> out;
  std::string text = read_file(log_);
  text.erase(text.find_last_of('\n') + 1);  // npos + 1 == 0: no whole line yet
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    nlohmann::json e = nlohmann::json::parse(line);
    if (e.at("event") == kind) out.push_back(std::move(e));
  }
  return out;
}

bool Rehearsal::wait_walking(std::chrono::seconds limit) const {
  return wait_until([&] { return !events("inject").empty(); }, limit);
}

}  // namespace multicpg::testing
