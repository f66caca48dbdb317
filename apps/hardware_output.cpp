#include "apps/hardware_output.h"

#include <fmt/format.h>

#include <iostream>

#include "common/atomic_file.h"
#include "hw/hardware_body.h"

namespace multicpg::apps {

experiments::StoppedSink stopped_record(bool json, const std::string& file) {
  return [json, file](const nlohmann::json& record) {
    if (!file.empty()) write_file_atomic(file, record.dump(2) + "\n");
    if (json) std::cout << record.dump(2) << "\n" << std::flush;
  };
}

std::string hardware_summary(const nlohmann::json& h) {
  const nlohmann::json& t = h.at("timing");
  std::string text;
  const double period = t.at("period_mean_s").get<double>();
  if (h.at("pacing") == hw::kPacingNames.name(hw::Pacing::lock_step)) {
    text = fmt::format("loop: lock-step, {:.0f} steps/s", period > 0.0 ? 1.0 / period : 0.0);
  } else {
    text = fmt::format("loop: {:.1f} Hz (period {:.2f} ms, p99 jitter {:.2f} ms, {} overruns)",
                       period > 0.0 ? 1.0 / period : 0.0, 1e3 * period,
                       1e3 * t.at("jitter_p99_s").get<double>(), t.at("overruns").get<long>());
  }
  std::string errors;
  bool late_only = true;  // only answers that came too late or not at all
  for (const char* line : {"bus", "yaw"}) {
    for (const auto& [kind, count] : h.at("errors").at(line).items()) {
      if (count.get<long>() > 0) {
        errors +=
            fmt::format("{}{} {} {}", errors.empty() ? "" : ", ", line, kind, count.get<long>());
        late_only = late_only && (kind == hw::to_string(hw::LinkError::timeout) ||
                                  kind == hw::to_string(hw::LinkError::short_answer));
      }
    }
  }
  text += ", link errors: " + (errors.empty() ? std::string("none") : errors);
  // Whether they are to worry about (docs/hardware.md "Safety"): a busy machine reads answers
  // late, a wire or a servo garbles them.
  if (!errors.empty()) {
    text += late_only ? " (isolated late answers are normal on a busy machine, an emulator's "
                        "too: each such step was walked with the last readings; raise "
                        "timeout_ms if they are many)"
                      : " (answers garbled or from the wrong servo: not a busy machine's doing; "
                        "check the wiring, the baud and the IDs)";
  }
  if (const long clamped = h.at("clamped_targets").get<long>(); clamped > 0) {
    text += fmt::format(", {} targets clamped to their limits", clamped);
  }
  return text;
}

}  // namespace multicpg::apps
