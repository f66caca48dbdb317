#include "hw/hardware_record.h"

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

}  // namespace multicpg::hw
