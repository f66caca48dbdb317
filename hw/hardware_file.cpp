#include "hw/hardware_file.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "common/checksum.h"
#include "common/errors.h"
#include "common/toml_file.h"
#include "common/user_text.h"
#include "hw/amosii.h"
#include "hw/dynamixel.h"
#include "hw/serial_port.h"

namespace multicpg::hw {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
// Dynamixel X: one turn in 4096 counts (hw/dynamixel.h).
constexpr double kDynamixelDegPerCount = 360.0 / dxl::kCountsPerTurn;

constexpr auto kProtocolNames =
    enum_names<Protocol>({{Protocol::amosii, "amosii"}, {Protocol::dynamixel, "dynamixel"}});
constexpr auto kStopActionNames = enum_names<StopAction>(
    {{StopAction::posture, "posture"}, {StopAction::torque_off, "torque_off"}});
constexpr auto kYawSourceNames =
    enum_names<YawSource>({{YawSource::board, "board"}, {YawSource::line, "line"}});

// As every input file is read (common/input_file.h): "FILE: cannot read (No such file or
// directory)", a FIFO refused without waiting.
std::string read_text(const TomlReader& r) {
  return r.read(kMaxHardwareFileBytes, "1 MiB", "hardware file");
}

class FileReader {
 public:
  FileReader(const TomlReader& r, HardwareFile& file) : r_(r), f_(file) {}

  void bus(const toml::table& doc) {
    f_.name = r_.text(doc, "", "name");
    f_.protocol = r_.choice(doc, "", "protocol", kProtocolNames);
    f_.port = r_.text(doc, "", "port");
    f_.baud = static_cast<int>(
        r_.integer_or(doc, "", "baud", 1, 4'000'000,
                      f_.protocol == Protocol::amosii ? amosii::kBaud : kDynamixelBaud));
    try {
      require_baud(f_.baud);
    } catch (const BadInput& e) {
      r_.fail("baud", e.what());
    }
    f_.timeout_ms = static_cast<int>(r_.integer_or(doc, "", "timeout_ms", 1, kMaxTimeoutMs, 20));
    f_.max_errors = static_cast<int>(r_.integer_or(doc, "", "max_errors", 1, kMaxErrorsLimit, 3));
    if (doc.contains("emulator_pid")) {
      f_.emulator_pid = static_cast<int>(r_.integer(doc, "", "emulator_pid", 1, kMaxPid));
    }
    if (doc.contains("deg_per_count")) {
      deg_per_count_ = r_.positive(doc, "", "deg_per_count");
    } else if (f_.protocol == Protocol::dynamixel) {
      deg_per_count_ = kDynamixelDegPerCount;
    }
  }

  ServoJoint joint(const toml::table& parent, const std::string& prefix, std::string_view key) {
    const std::string k = prefix + std::string(key);
    const toml::node& n = r_.node(parent, prefix, key);
    const toml::table* t = n.as_table();
    if (t == nullptr) {
      r_.fail(k, "must be a table { id = ..., sign = ..., zero = ..., limits_deg = [lo, hi] }");
    }
    const std::string p = k + ".";
    r_.only(*t, p, {"id", "sign", "zero", "limits_deg", "deg_per_count"});
    ServoJoint j;
    j.id = static_cast<int>(r_.integer(*t, p, "id", f_.protocol == Protocol::amosii ? 1 : 0,
                                       max_servo_id(f_.protocol)));
    j.sign = r_.number(*t, p, "sign");
    if (j.sign != 1.0 && j.sign != -1.0) r_.fail(p + "sign", "must be 1 or -1");
    j.zero = r_.number(*t, p, "zero");
    if (t->contains("deg_per_count")) {
      j.deg_per_count = r_.positive(*t, p, "deg_per_count");
    } else if (deg_per_count_) {
      j.deg_per_count = *deg_per_count_;
    } else {
      r_.fail(p + "deg_per_count",
              "missing (no deg_per_count for the whole file: an AMOSII board's servos need one)");
    }
    const toml::array* w = r_.node(*t, p, "limits_deg").as_array();
    if (w == nullptr || w->size() != 2) r_.fail(p + "limits_deg", "must be [lo, hi] in degrees");
    const double lo = r_.number(*w->get(0), p + "limits_deg");
    const double hi = r_.number(*w->get(1), p + "limits_deg");
    if (!(lo < hi)) r_.fail(p + "limits_deg", "lo must be below hi");
    j.limits = {lo * kRadPerDeg, hi * kRadPerDeg};
    // The limits' counts, unclamped and unrounded, must be counts the servo has.
    const CountRange range = servo_range(f_.protocol);
    for (double deg : {lo, hi}) {
      const double c = j.zero + j.sign * deg / j.deg_per_count;
      if (std::round(c) < range.lo || std::round(c) > range.hi) {
        r_.fail(p + "limits_deg", "limit " + fmt_deg(deg) + " deg is count " +
                                      std::to_string(std::lround(c)) +
                                      ", outside the servo's range " + std::to_string(range.lo) +
                                      ".." + std::to_string(range.hi));
      }
    }
    claim_id(j.id, k);
    return j;
  }

  std::optional<ContactInput> contact(const toml::table& leg, const std::string& prefix) {
    if (!leg.contains("contact")) return std::nullopt;
    const std::string k = prefix + "contact";
    if (f_.protocol != Protocol::amosii) {
      r_.fail(k, "foot contacts are read from an AMOSII board's inputs only");
    }
    const toml::table& t = r_.table(leg, prefix, "contact");
    const std::string p = k + ".";
    r_.only(t, p, {"port", "off", "on"});
    ContactInput c;
    c.port = static_cast<int>(r_.integer(t, p, "port", 1, amosii::kPorts));
    c.off = static_cast<int>(r_.integer(t, p, "off", 0, 255));
    c.on = static_cast<int>(r_.integer(t, p, "on", 0, 255));
    if (c.off == c.on) r_.fail(p + "on", "must differ from off");
    claim_input(c.port, p + "port");
    return c;
  }

  void legs(const toml::table& doc, const robot::Morphology& morph) {
    const toml::array* legs = r_.node(doc, "", "legs").as_array();
    if (legs == nullptr) r_.fail("legs", "must be an array of tables ([[legs]])");
    if (legs->size() != morph.size()) {
      r_.fail("legs", std::to_string(legs->size()) + " legs; the " + morph.name + " has " +
                          std::to_string(morph.size()) + " (" + morph.legs.front().name + ".." +
                          morph.legs.back().name + ")");
    }
    for (std::size_t i = 0; i < legs->size(); ++i) {
      const std::string key = "legs[" + std::to_string(i) + "]";
      const toml::table* t = legs->get(i)->as_table();
      if (t == nullptr) r_.fail(key, "must be a table");
      const std::string p = key + ".";
      r_.only(*t, p, {"name", "TC", "CTr", "FTi", "contact"});
      LegServos leg;
      leg.name = r_.text(*t, p, "name");
      if (leg.name != morph.legs[i].name) {
        r_.fail(p + "name", "'" + leg.name + "', expected '" + morph.legs[i].name +
                                "' (legs are listed in the order " + morph.legs.front().name +
                                ".." + morph.legs.back().name + ")");
      }
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        leg.joints[j] = joint(*t, p, robot::to_string(robot::kJoints[j]));
      }
      leg.contact = contact(*t, p);
      f_.legs.push_back(leg);
    }
  }

  void yaw(const toml::table& doc) {
    const toml::table& t = r_.table(doc, "", "yaw");
    YawSpec& y = f_.yaw;
    if (r_.choice(t, "yaw.", "source", kYawSourceNames) == YawSource::board) {
      if (f_.protocol != Protocol::amosii) {
        r_.fail("yaw.source", "'board': only an AMOSII board has inputs; use \"line\"");
      }
      r_.only(t, "yaw.", {"source", "port", "zero", "deg_per_count"});
      y.source = YawSource::board;
      y.board_port = static_cast<int>(r_.integer(t, "yaw.", "port", 1, amosii::kPorts));
      y.zero = r_.number(t, "yaw.", "zero");
      y.deg_per_count = r_.positive(t, "yaw.", "deg_per_count");
      claim_input(y.board_port, "yaw.port");
    } else {
      r_.only(t, "yaw.", {"source", "port", "baud", "timeout_ms", "position"});
      y.source = YawSource::line;
      y.port = r_.text(t, "yaw.", "port");
      y.baud = static_cast<int>(r_.integer_or(t, "yaw.", "baud", 1, 4'000'000, y.baud));
      try {
        require_baud(y.baud);
      } catch (const BadInput& e) {
        r_.fail("yaw.baud", e.what());
      }
      y.timeout_ms =
          static_cast<int>(r_.integer_or(t, "yaw.", "timeout_ms", 1, kMaxTimeoutMs, y.timeout_ms));
      y.position = r_.boolean(t, "yaw.", "position", false);
      if (y.port == f_.port) r_.fail("yaw.port", "is the servos' port '" + f_.port + "'");
    }
  }

  void stop(const toml::table& doc) {
    const toml::table& t = r_.table(doc, "", "stop");
    r_.only(t, "stop.", {"action", "posture_deg"});
    f_.stop = r_.choice(t, "stop.", "action", kStopActionNames);
    if (f_.stop == StopAction::torque_off && f_.protocol == Protocol::amosii) {
      r_.fail("stop.action",
              "'torque_off': the AMOSII board's protocol has no torque-off command; use "
              "\"posture\"");
    }
    const toml::table& p = r_.table(t, "stop.", "posture_deg");
    r_.only(p, "stop.posture_deg.", {"TC", "CTr", "FTi"});
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const std::string_view name = robot::to_string(robot::kJoints[j]);
      f_.safe_posture[j] = r_.number(p, "stop.posture_deg.", name) * kRadPerDeg;
      for (const LegServos& leg : f_.legs) {
        const robot::AngleRange& lim = leg.joints[j].limits;
        if (f_.safe_posture[j] < lim.lo || f_.safe_posture[j] > lim.hi) {
          r_.fail("stop.posture_deg." + std::string(name),
                  fmt_deg(f_.safe_posture[j] / kRadPerDeg) + " deg is outside " + leg.name + "." +
                      std::string(name) + "'s limits " + fmt_deg(lim.lo / kRadPerDeg) + ".." +
                      fmt_deg(lim.hi / kRadPerDeg));
        }
      }
    }
  }

  void backbone(const toml::table& doc) {
    if (!doc.contains("backbone")) return;
    f_.backbone = joint(doc, "", "backbone");
    if (f_.backbone->limits.lo > 0.0 || f_.backbone->limits.hi < 0.0) {
      r_.fail("backbone.limits_deg", "must hold 0, where the backbone is held");
    }
  }

 private:
  static constexpr int kDynamixelBaud = 57'600;  // X series' factory setting (e-Manual)

  static std::string fmt_deg(double deg) {
    std::ostringstream s;
    s << deg;
    return s.str();
  }

  void claim_id(int id, const std::string& key) {
    if (const auto [it, fresh] = ids_.emplace(id, key); !fresh) {
      r_.fail(key + ".id", "ID " + std::to_string(id) + " is also " + it->second + "'s");
    }
  }

  void claim_input(int port, const std::string& key) {
    if (const auto [it, fresh] = inputs_.emplace(port, key); !fresh) {
      r_.fail(key, "input " + std::to_string(port) + " is also " + it->second + "'s");
    }
  }

  const TomlReader& r_;
  HardwareFile& f_;
  std::optional<double> deg_per_count_;
  std::map<int, std::string> ids_;     // servo ID -> the key that claimed it
  std::map<int, std::string> inputs_;  // board input -> the key that claimed it
};

}  // namespace

std::string_view to_string(Protocol protocol) {
  return kProtocolNames.name(protocol);
}

std::vector<std::string> protocol_names() {
  return kProtocolNames.names();
}

Protocol parse_protocol(std::string_view text) {
  if (const std::optional<Protocol> protocol = kProtocolNames.find(text)) return *protocol;
  throw BadInput(unknown_name("protocol", text, kProtocolNames.names()));
}

std::string_view to_string(StopAction action) {
  return kStopActionNames.name(action);
}

CountRange servo_range(Protocol protocol) {
  return protocol == Protocol::amosii ? CountRange{amosii::kMinPosition, amosii::kMaxPosition}
                                      : CountRange{0, dxl::kMaxPosition};
}

int max_servo_id(Protocol protocol) {
  return protocol == Protocol::amosii ? amosii::kPorts : dxl::kMaxId;
}

int ServoJoint::counts(double angle_rad) const {
  const double a = std::clamp(angle_rad, limits.lo, limits.hi) / kRadPerDeg;
  return static_cast<int>(std::lround(zero + sign * a / deg_per_count));
}

double ServoJoint::angle(int c) const {
  return sign * (c - zero) * deg_per_count * kRadPerDeg;
}

bool ContactInput::touching(int reading) const {
  const double middle = 0.5 * (off + on);
  return on > off ? reading > middle : reading < middle;
}

std::string HardwareFile::servo_name(int id) const {
  for (const LegServos& leg : legs) {
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      if (leg.joints[j].id == id) {
        return leg.name + "." + std::string(robot::to_string(robot::kJoints[j])) + " (ID " +
               std::to_string(id) + ")";
      }
    }
  }
  if (backbone && backbone->id == id) return "backbone (ID " + std::to_string(id) + ")";
  return "ID " + std::to_string(id);
}

HardwareFile load_hardware_file(const std::filesystem::path& path, const robot::Morphology& morph) {
  const TomlReader r(path);
  const std::string source = read_text(r);
  const toml::table doc = r.parse(source);
  r.only(doc, "",
         {"name", "protocol", "port", "baud", "timeout_ms", "max_errors", "deg_per_count", "yaw",
          "stop", "legs", "backbone", "emulator_pid"});
  HardwareFile file;
  file.path = path;
  file.checksum = checksum_text(source);
  FileReader f(r, file);
  f.bus(doc);
  f.legs(doc, morph);
  f.backbone(doc);
  f.yaw(doc);
  f.stop(doc);
  return file;
}

std::string with_ports(const std::filesystem::path& path, const std::string& port,
                       const std::string& yaw_port, int emulator_pid) {
  const TomlReader r(path);
  toml::table doc = r.parse(read_text(r));
  doc.insert_or_assign("port", port);
  doc.insert_or_assign("emulator_pid", emulator_pid);
  if (toml::table* yaw = doc["yaw"].as_table(); yaw != nullptr && !yaw_port.empty()) {
    yaw->insert_or_assign("port", yaw_port);
  }
  std::ostringstream out;
  out << "# " << path.filename().string() << " with the emulator's ports (multicpg emulate)\n"
      << doc << "\n";
  return out.str();
}

}  // namespace multicpg::hw
