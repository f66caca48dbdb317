// A rehearsal for a test: `multicpg emulate` on a copy of an example hardware file (its timeouts
// widened so a busy machine's scheduling is not taken for a fault), the rehearsal file the host
// commands use (--hardware), and the emulator's log.
#pragma once

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tests/cli_process.h"

namespace multicpg::testing {

class Rehearsal {
 public:
  // An injection that changes nothing (a yaw drift of 0 deg/s from step 20): its "inject" event,
  // logged when the host sends step 21, tells a test the robot has walked.
  static constexpr const char* kWalkingMark = "drift=0@20";

  // `example`: a file of examples/hardware; every `timeout_ms = ` in it becomes `timeout_ms`;
  // `edits` then replace text in it (from, to); `args`: more emulator flags (--inject ...). It
  // serves one run unless `args` say --runs.
  Rehearsal(const std::string& example, int timeout_ms, const std::vector<std::string>& args = {},
            const std::vector<std::pair<std::string, std::string>>& edits = {});
  ~Rehearsal();

  const std::string& file() const { return rehearsal_; }
  const std::string& dir() const { return dir_; }
  void signal(int sig) const;  // to the emulator
  // Waits for the emulator to end (it does when the host has hung up); false if it hangs.
  bool finish();
  int exit_code() const { return emulator_->exit_code(); }
  std::string out() const { return emulator_->out(); }
  std::string err() const { return emulator_->err(); }
  // The log's events of `kind` ("posture", "torque_off", "inject", ...), the line being written
  // left out.
  std::vector<nlohmann::json> events(const std::string& kind) const;
  // Waits until the host has walked past kWalkingMark (given in `args`); false if it never does.
  bool wait_walking(std::chrono::seconds limit) const;

 private:
  std::string dir_;
  std::string rehearsal_;
  std::string log_;
  std::unique_ptr<CliProcess> emulator_;
};

}  // namespace multicpg::testing
