#include "hw/hardware_record.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace multicpg::hw {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

nlohmann::json errors_json(const LinkErrors& errors) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t k = 0; k < kLinkErrorKinds; ++k) {
    j[std::string(to_string(static_cast<LinkError>(k)))] = errors.counts[k];
  }
  return j;
}

nlohmann::json stop_json(const StopRecord& r) {
  return {{"cause", r.cause},
          {"message", r.message},
          {"fault", r.fault},
          {"step", r.step},
          {"detected_s", r.detected_s},
          {"commanded_s", r.commanded_s},
          {"command_error", r.command_error}};
}

std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace

nlohmann::json hardware_json(const HardwareFile& f, Pacing pacing, const HardwareBody& body) {
  nlohmann::json j{
      {"file", f.path.string()},
      {"name", f.name},
      {"checksum", f.checksum},
      {"protocol", to_string(f.protocol)},
      {"pacing", kPacingNames.name(pacing)},
      {"senses_position", f.senses_position()},
      {"timing", body.timing()},
      {"errors",
       {{"bus", errors_json(body.bus_errors())}, {"yaw", errors_json(body.yaw_errors())}}},
      {"clamped_targets", body.clamped_targets()},
      {"stop", body.stopped() ? stop_json(*body.stopped()) : nlohmann::json()}};
  return j;
}

StepCsv::StepCsv(std::ostream& out, const HardwareFile& file, const robot::Morphology& morph)
    : out_(out), file_(file) {
  out_ << "step,time_s,x_m,y_m,yaw_deg";
  for (const char* what : {"target_deg", "angle_deg"}) {
    if (std::string(what) == "angle_deg" && file.protocol != Protocol::dynamixel) continue;
    for (const robot::Leg& leg : morph.legs) {
      for (robot::Joint joint : robot::kJoints) {
        out_ << "," << leg.name << "." << robot::to_string(joint) << "_" << what;
      }
    }
  }
  if (file.protocol == Protocol::amosii) {
    for (const robot::Leg& leg : morph.legs) out_ << "," << leg.name << "_contact";
  }
  out_ << ",errors\n";
}

void StepCsv::row(const StepRow& r) {
  out_ << r.step << "," << cell(r.time_s) << "," << cell(r.pose.x) << "," << cell(r.pose.y) << ","
       << cell(r.pose.yaw_deg);
  for (const auto& leg : r.targets) {
    for (double a : leg) out_ << "," << cell(a * kDegPerRad);
  }
  if (file_.protocol == Protocol::dynamixel) {
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        const bool known = i < r.feedback.angles.size() && r.feedback.angles[i][j];
        out_ << "," << (known ? cell(*r.feedback.angles[i][j] * kDegPerRad) : "");
      }
    }
  }
  if (file_.protocol == Protocol::amosii) {
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
      const bool known = i < r.feedback.contacts.size() && r.feedback.contacts[i];
      out_ << "," << (known ? (*r.feedback.contacts[i] ? "1" : "0") : "");
    }
  }
  out_ << "," << r.errors << "\n";
}

std::string hardware_summary(const nlohmann::json& h) {
  const nlohmann::json& t = h.at("timing");
  std::string text;
  const double period = t.at("period_mean_s").get<double>();
  if (h.at("pacing") == kPacingNames.name(Pacing::lock_step)) {
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
        late_only = late_only && (kind == to_string(LinkError::timeout) ||
                                  kind == to_string(LinkError::short_answer));
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

}  // namespace multicpg::hw
