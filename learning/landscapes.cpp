#include "learning/landscapes.h"

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "common/atomic_file.h"
#include "common/checksum.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/installed_data.h"
#include "learning/compensation.h"
#include "learning/json.h"
#include "robot/leg_sets.h"

namespace multicpg::learning {
namespace {

namespace fs = std::filesystem;

constexpr int kFormatVersion = 2;
constexpr int kFirstFormatVersion = 1;  // before the reflex: read as "steering": "off"
constexpr const char* kFormat = "multicpg landscape dataset";
constexpr int kJsonIndent = 2;
constexpr const char* kFailedCell = "x";
// zlib's "gzip wrapper" flag for deflateInit2/inflateInit2 window bits (zlib.h).
constexpr int kGzipWindowBits = 15 + 16;
constexpr int kMemLevel = 8;  // zlib's default
constexpr std::size_t kChunk = 1 << 16;
// Bounds of what is read: the hexapod's datasets are about 1.2 MB of gzip and 5 MB of CSV; an
// octopod's three-leg losses would be some 50 times that.
constexpr std::size_t kMaxManifestBytes = std::size_t{16} << 20;
constexpr std::string_view kMaxManifestText = "16 MiB";
constexpr std::size_t kMaxGzipBytes = std::size_t{256} << 20;
constexpr std::string_view kMaxGzipText = "256 MiB";
constexpr std::size_t kMaxCsvBytes = std::size_t{2} << 30;
// Windows a dataset may measure per combination (experiments/landscape.h's limit).
constexpr int kMaxWindows = 1000;

fs::path stem_of(const fs::path& path) {
  fs::path p = path;
  if (p.extension() == ".json") return p.replace_extension();
  if (p.extension() == ".gz") p.replace_extension();
  if (p.extension() == ".csv") p.replace_extension();
  return p;
}
fs::path csv_path(const fs::path& stem) {
  return fs::path(stem.string() + ".csv.gz");
}
fs::path manifest_path(const fs::path& stem) {
  return fs::path(stem.string() + ".json");
}

// The datasets' folder in each directory of the search path (data/landscapes in the source tree).
constexpr const char* kLandscapesDir = "landscapes";

// $MULTICPG_DATA, unless unset or empty.
std::optional<fs::path> data_env() {
  const char* given = std::getenv(kDataEnv);
  if (given == nullptr || *given == '\0') return std::nullopt;
  return fs::path(given);
}

std::string rounded(double v, double resolution, int decimals) {
  const double r = std::round(v / resolution) * resolution;
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << (r == 0.0 ? 0.0 : r);  // no "-0.000"
  return out.str();
}
std::string angle(double deg) {
  return rounded(deg, kLandscapeAngleResolutionDeg, 3);
}
std::string effort(double share) {
  return rounded(share, kLandscapeEffortResolution, 4);
}

// zlib does the compression; gzip's own CRC and length make a cut or damaged file fail to read.
std::string gzip(const std::string& text) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, kGzipWindowBits, kMemLevel,
                   Z_DEFAULT_STRATEGY) != Z_OK) {
    throw RuntimeFailure("zlib could not start compressing");
  }
  std::string out;
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    std::string chunk(kChunk, '\0');
    z.next_out = reinterpret_cast<Bytef*>(chunk.data());
    z.avail_out = static_cast<uInt>(chunk.size());
    rc = deflate(&z, Z_FINISH);
    if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
      deflateEnd(&z);
      throw RuntimeFailure("zlib could not compress the landscape");
    }
    out.append(chunk.data(), chunk.size() - z.avail_out);
  }
  deflateEnd(&z);
  return out;
}

std::string gunzip(const std::string& data, const fs::path& path) {
  const std::string name = path.string();
  z_stream z{};
  if (inflateInit2(&z, kGzipWindowBits) != Z_OK) {
    throw RuntimeFailure("zlib could not start decompressing");
  }
  std::string out;
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    std::string chunk(kChunk, '\0');
    z.next_out = reinterpret_cast<Bytef*>(chunk.data());
    z.avail_out = static_cast<uInt>(chunk.size());
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      inflateEnd(&z);
      throw BadInput(name + ": is not a whole gzip file (cut short or damaged)");
    }
    out.append(chunk.data(), chunk.size() - z.avail_out);
    if (out.size() > kMaxCsvBytes) {
      inflateEnd(&z);
      throw BadInput(name + ": unpacks to more than the 2 GiB a landscape dataset may have");
    }
    if (rc == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
      inflateEnd(&z);
      throw BadInput(name + ": is cut short");
    }
  }
  inflateEnd(&z);
  return out;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(line);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

// A number as the writer writes it: decimal digits, a sign, a point; no blanks, no "nan".
std::optional<double> decimal(const std::string& text) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

// The manifest's fields, each of the type the writer writes; BadInput "FILE: KEY ..." otherwise.
class Manifest {
 public:
  Manifest(const nlohmann::json& j, std::string name) : j_(j), name_(std::move(name)) {}
  BadInput bad(const std::string& key, const std::string& what) const {
    return BadInput(name_ + ": " + key + " " + what);
  }
  const nlohmann::json& at(const std::string& key) const {
    if (!j_.contains(key)) throw bad(key, "is missing");
    return j_.at(key);
  }
  long integer(const std::string& key, const Limits<long>& limits) const {
    return integer_of(at(key), key, limits);
  }
  long integer_of(const nlohmann::json& v, const std::string& key,
                  const Limits<long>& limits) const {
    if (!v.is_number_integer()) throw bad(key, "must be a whole number, got " + v.dump());
    const long n = v.get<long>();
    if (!limits.contains(n)) {
      throw bad(key, "must be in " + limits.text() + ", got " + std::to_string(n));
    }
    return n;
  }
  double number(const std::string& key, const Limits<double>& limits) const {
    const nlohmann::json& v = at(key);
    if (!v.is_number()) throw bad(key, "must be a number, got " + v.dump());
    const double x = v.get<double>();
    if (!limits.contains(x)) throw bad(key, "must be in " + limits.text() + ", got " + v.dump());
    return x;
  }
  std::string text(const std::string& key) const {
    const nlohmann::json& v = at(key);
    if (!v.is_string()) throw bad(key, "must be text, got " + v.dump());
    return v.get<std::string>();
  }
  const std::string& name() const { return name_; }

 private:
  const nlohmann::json& j_;
  std::string name_;
};

nlohmann::json window_json(const body::WindowMeasure& w, bool reflex) {
  nlohmann::json j{{"yaw_deg", std::stod(angle(w.yaw_deg))},
                   {"path_deg", std::stod(angle(w.path_deg))}};
  if (reflex) j["steering_effort"] = std::stod(effort(w.steering_effort));
  return j;
}

}  // namespace

std::vector<fs::path> dataset_search_path() {
  std::vector<fs::path> dirs;
  if (const std::optional<fs::path> given = data_env()) dirs.push_back(*given);
  if (fs::path installed = installed_data_dir(); !installed.empty()) {
    dirs.push_back(std::move(installed));
  }
  dirs.emplace_back(MULTICPG_DATA_DIR);
  return dirs;
}

std::filesystem::path repository_dataset(robot::RobotKind robot, bool reflex) {
  const std::string name = std::string(robot::to_string(robot)) + (reflex ? "-reflex" : "");
  std::string looked = data_env() ? std::string() : std::string("$") + kDataEnv + " unset";
  for (const fs::path& dir : dataset_search_path()) {
    const fs::path path = dir / kLandscapesDir / name;
    std::error_code ec;
    if (fs::exists(manifest_path(path), ec)) return path;
    looked += (looked.empty() ? "" : ", ") + path.parent_path().string();
  }
  throw BadInput("no landscape dataset " + name + " (.json, .csv.gz) in " + looked +
                 " (docs/python.md \"Datasets\")");
}

std::optional<std::size_t> ScenarioLandscape::find(const Periods& periods) const {
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool same = true;
    for (std::size_t leg = 0; leg < periods.size() && same; ++leg) {
      const bool is_failed = std::binary_search(failed.begin(), failed.end(), leg);
      same = is_failed || points[i].periods.at(leg) == periods[leg];
    }
    if (same) return i;
  }
  return std::nullopt;
}

std::size_t ScenarioLandscape::holding() const {
  return static_cast<std::size_t>(
      std::count_if(points.begin(), points.end(), [](const LandscapePoint& p) { return p.holds; }));
}

std::size_t ScenarioLandscape::best() const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const LandscapePoint& a = points[i];
    const LandscapePoint& b = points[best];
    if (a.holds != b.holds ? a.holds : a.worst_deg < b.worst_deg) best = i;
  }
  return best;
}

const ScenarioLandscape* LandscapeDataset::find(std::vector<std::size_t> failed) const {
  std::sort(failed.begin(), failed.end());
  for (const ScenarioLandscape& s : scenarios) {
    if (s.failed == failed) return &s;
  }
  return nullptr;
}

Criterion LandscapeDataset::criterion() const {
  return reflex ? reflex_criterion(threshold_deg, reflex->max_effort) : kPeriodsAloneCriterion;
}

std::string LandscapeDataset::walked() const {
  return reflex ? "the steering reflex" : "periods alone";
}

void write_landscape_dataset(const LandscapeDataset& d, const fs::path& path) {
  const robot::Morphology& morph = robot::morphology(d.robot);
  const bool reflex = d.reflex.has_value();
  std::ostringstream csv;
  csv << "scenario";
  for (const robot::Leg& leg : morph.legs) csv << "," << leg.name;
  for (int w = 1; w <= d.windows; ++w) {
    csv << ",w" << w << "_yaw,w" << w << "_path";
    if (reflex) csv << ",w" << w << "_effort";
  }
  csv << ",worst,holds\n";
  nlohmann::json scenarios = nlohmann::json::array();
  for (const ScenarioLandscape& s : d.scenarios) {
    const std::string name = robot::leg_set_name(morph, s.failed);
    for (const LandscapePoint& p : s.points) {
      csv << name;
      for (std::size_t leg = 0; leg < morph.size(); ++leg) {
        const bool is_failed = std::binary_search(s.failed.begin(), s.failed.end(), leg);
        csv << "," << (is_failed ? std::string(kFailedCell) : std::to_string(p.periods[leg]));
      }
      for (std::size_t w = 0; w < static_cast<std::size_t>(d.windows); ++w) {
        if (w >= p.windows.size()) {
          csv << (reflex ? ",,," : ",,");  // not walked
          continue;
        }
        csv << "," << angle(p.windows[w].yaw_deg) << "," << angle(p.windows[w].path_deg);
        if (reflex) csv << "," << effort(p.windows[w].steering_effort);
      }
      csv << "," << angle(p.worst_deg) << "," << (p.holds ? 1 : 0) << "\n";
    }
    const std::size_t holding = s.holding();
    nlohmann::json entry{
        {"scenario", name},
        {"combinations", s.points.size()},
        {"holding", holding},
        {"share_holding",
         s.points.empty() ? 0.0
                          : static_cast<double>(holding) / static_cast<double>(s.points.size())}};
    if (reflex) {
      nlohmann::json start = nlohmann::json::array();
      for (const body::WindowMeasure& w : s.start_windows) start.push_back(window_json(w, true));
      entry["start_windows"] = start;
    }
    scenarios.push_back(std::move(entry));
  }
  const std::string text = csv.str();
  nlohmann::json manifest{{"format", kFormat},
                          {"version", kFormatVersion},
                          {"robot", robot::to_string(d.robot)},
                          {"period_set", d.period_set},
                          {"windows", d.windows},
                          {"window_steps", d.window_steps},
                          {"threshold_deg", d.threshold_deg},
                          {"angle_resolution_deg", kLandscapeAngleResolutionDeg},
                          {"sim", d.sim},
                          {"steering", reflex ? "reflex" : "off"},
                          {"scenarios", scenarios},
                          {"checksum", checksum_text(text)}};
  if (!d.robot_file.is_null()) manifest["robot_file"] = d.robot_file;
  if (reflex) {
    manifest["steering_params"] = *d.reflex;
    manifest["monitor_windows"] = d.monitor_windows;
    manifest["effort_resolution"] = kLandscapeEffortResolution;
  }
  const fs::path stem = stem_of(path);
  write_file_atomic(csv_path(stem), gzip(text));
  write_file_atomic(manifest_path(stem), manifest.dump(kJsonIndent) + "\n");
}

namespace {

std::string read_manifest_file(const fs::path& stem) {
  return read_input_file(manifest_path(stem), kMaxManifestBytes, kMaxManifestText,
                         "a landscape manifest");
}

std::string read_csv_file(const fs::path& stem) {
  return read_input_file(csv_path(stem), kMaxGzipBytes, kMaxGzipText, "a landscape dataset");
}

// The dataset of `path` from its files' bytes: the manifest's text, and the CSV's gzip bytes,
// read here when not given (after the manifest is checked, so a bad manifest is named first).
LandscapeDataset parse_dataset(const fs::path& path, const std::string& manifest_text,
                               const std::string* csv_gzip) {
  const fs::path stem = stem_of(path);
  const fs::path mpath = manifest_path(stem);
  const fs::path cpath = csv_path(stem);
  const std::string mname = mpath.string();
  nlohmann::json m;
  try {
    m = nlohmann::json::parse(manifest_text);
  } catch (const nlohmann::json::exception&) {
    throw BadInput(mname + ": is not a landscape manifest (not JSON)");
  }
  if (!m.is_object()) throw BadInput(mname + ": is not a landscape manifest (not a JSON object)");
  const Manifest f(m, mname);
  if (f.text("format") != kFormat) throw f.bad("format", "is not \"" + std::string(kFormat) + "\"");
  const long version = f.integer("version", {kFirstFormatVersion, 1'000'000});
  if (version > kFormatVersion) {
    throw f.bad("version", std::to_string(version) + " is newer than this program reads (" +
                               std::to_string(kFormatVersion) + ")");
  }
  LandscapeDataset d;
  try {
    d.robot = robot::parse_robot(f.text("robot"));
  } catch (const BadInput& e) {
    throw f.bad("robot", e.what());
  }
  const nlohmann::json& set = f.at("period_set");
  if (!set.is_array()) throw f.bad("period_set", "must be a list of periods");
  for (const nlohmann::json& p : set) {
    d.period_set.push_back(
        static_cast<int>(f.integer_of(p, "period_set", {1, std::numeric_limits<int>::max()})));
  }
  d.windows = static_cast<int>(f.integer("windows", {1, kMaxWindows}));
  d.window_steps = f.integer("window_steps", kWindowStepsLimits);
  d.threshold_deg = f.number("threshold_deg", kThresholdLimits);
  SearchBounds bounds;
  bounds.period_set = d.period_set;
  bounds.threshold_deg = d.threshold_deg;
  try {
    validate(bounds);  // periods that give a gait, each once
  } catch (const OptionError& e) {
    throw f.bad(e.key(), e.what());
  }
  d.sim = f.at("sim");
  if (!d.sim.is_object()) throw f.bad("sim", "must be a table of simulation options");
  if (m.contains("robot_file")) {
    const nlohmann::json& file = f.at("robot_file");
    if (!file.is_object()) throw f.bad("robot_file", "must be the record of a robot file");
    Manifest(file, mname + ": robot_file").text("name");  // a record names its file at least
    d.robot_file = file;
  }
  const std::string steering = version == kFirstFormatVersion ? "off" : f.text("steering");
  if (steering == "reflex") {
    try {
      d.reflex = f.at("steering_params").get<SteeringParams>();
      validate(*d.reflex);
    } catch (const nlohmann::json::exception& e) {
      throw f.bad("steering_params", std::string("is not the reflex's parameters: ") + e.what());
    } catch (const OptionError& e) {
      throw f.bad("steering_params." + e.key(), e.what());
    }
    d.monitor_windows = f.integer("monitor_windows", {1, 1000});
  } else if (steering != "off") {
    throw f.bad("steering", "must be \"off\" or \"reflex\", got \"" + steering + "\"");
  }
  const std::string checksum = f.text("checksum");
  const robot::Morphology& morph = robot::morphology(d.robot);
  const Criterion criterion = d.criterion();

  // Each scenario the manifest lists, with its count and (reflex) its start windows.
  const nlohmann::json& listed = f.at("scenarios");
  if (!listed.is_array() || listed.empty()) {
    throw f.bad("scenarios", "must list at least one scenario");
  }
  std::map<std::string, std::size_t> index;
  std::vector<std::size_t> expected;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    const std::string where = "scenarios[" + std::to_string(i) + "]";
    if (!listed[i].is_object()) throw f.bad(where, "must be a table");
    const Manifest s(listed[i], mname + ": " + where);
    ScenarioLandscape scenario;
    const std::string name = s.text("scenario");
    try {
      scenario.failed = robot::parse_leg_set(morph, name);
    } catch (const BadInput& e) {
      throw s.bad("scenario", e.what());
    }
    std::sort(scenario.failed.begin(), scenario.failed.end());
    if (scenario.failed.size() >= morph.size()) throw s.bad("scenario", "fails every leg");
    if (!index.emplace(robot::leg_set_name(morph, scenario.failed), d.scenarios.size()).second) {
      throw s.bad("scenario", name + " is listed twice");
    }
    std::size_t grid = 1;
    for (std::size_t w = 0; w < morph.size() - scenario.failed.size(); ++w)
      grid *= d.period_set.size();
    const long count = s.integer("combinations", {0, std::numeric_limits<long>::max()});
    if (static_cast<std::size_t>(count) != grid) {
      throw s.bad("combinations", "must be " + std::to_string(grid) + " (every combination of " +
                                      name + "), got " + std::to_string(count));
    }
    expected.push_back(grid);
    if (d.reflex) {
      const nlohmann::json& start = s.at("start_windows");
      if (!start.is_array() || start.empty()) {
        throw s.bad("start_windows", "must list the windows walked before the combinations");
      }
      for (const nlohmann::json& w : start) {
        if (!w.is_object() || !w.contains("yaw_deg") || !w.contains("path_deg") ||
            !w.contains("steering_effort") || !w.at("yaw_deg").is_number() ||
            !w.at("path_deg").is_number() || !w.at("steering_effort").is_number()) {
          throw s.bad("start_windows", "must hold yaw_deg, path_deg and steering_effort numbers");
        }
        body::WindowMeasure m;
        m.yaw_deg = w.at("yaw_deg").get<double>();
        m.path_deg = w.at("path_deg").get<double>();
        m.steering_effort = w.at("steering_effort").get<double>();
        if (!std::isfinite(m.yaw_deg) || !std::isfinite(m.path_deg) ||
            !(m.steering_effort >= 0.0 && m.steering_effort <= 1.0)) {
          throw s.bad("start_windows", "holds a value out of range");
        }
        scenario.start_windows.push_back(m);
      }
    }
    d.scenarios.push_back(std::move(scenario));
  }

  const std::string text = gunzip(csv_gzip != nullptr ? *csv_gzip : read_csv_file(stem), cpath);
  if (checksum_text(text) != checksum) {
    throw BadInput(cpath.string() + ": does not match its manifest's checksum (edited?)");
  }
  std::istringstream in(text);
  std::string line;
  std::ostringstream header;
  header << "scenario";
  for (const robot::Leg& leg : morph.legs) header << "," << leg.name;
  for (int w = 1; w <= d.windows; ++w) {
    header << ",w" << w << "_yaw,w" << w << "_path";
    if (d.reflex) header << ",w" << w << "_effort";
  }
  header << ",worst,holds";
  if (!std::getline(in, line) || line != header.str()) {
    throw BadInput(cpath.string() + ": line 1 is not the header its manifest says (" +
                   header.str() + ")");
  }
  const std::size_t per_window = d.reflex ? 3 : 2;
  const std::size_t columns =
      1 + morph.size() + per_window * static_cast<std::size_t>(d.windows) + 2;
  // The tolerance of a value rounded to its resolution when it is compared again.
  const double tolerance =
      kLandscapeAngleResolutionDeg + criterion.effort_deg(kLandscapeEffortResolution);
  std::size_t number_of_line = 1;
  std::vector<std::set<Periods>> seen(d.scenarios.size());
  while (std::getline(in, line)) {
    ++number_of_line;
    const auto bad = [&](const std::string& what) {
      return BadInput(cpath.string() + ": line " + std::to_string(number_of_line) + ": " + what);
    };
    const std::vector<std::string> cells = split(line, ',');
    if (cells.size() != columns) {
      throw bad("has " + std::to_string(cells.size()) + " cells, the header " +
                std::to_string(columns));
    }
    const auto it = index.find(cells[0]);
    if (it == index.end()) throw bad("scenario '" + cells[0] + "' is not in the manifest");
    ScenarioLandscape& s = d.scenarios[it->second];
    LandscapePoint p;
    for (std::size_t leg = 0; leg < morph.size(); ++leg) {
      const std::string& c = cells[1 + leg];
      const std::string& leg_name = morph.legs[leg].name;
      const bool is_failed = std::binary_search(s.failed.begin(), s.failed.end(), leg);
      if (is_failed) {
        if (c != kFailedCell) throw bad(leg_name + " failed in " + cells[0] + ", so its cell is x");
        p.periods.push_back(kStartPeriod);
        continue;
      }
      int period = 0;
      const auto [end, ec] = std::from_chars(c.data(), c.data() + c.size(), period);
      if (c.empty() || ec != std::errc() || end != c.data() + c.size() ||
          std::find(d.period_set.begin(), d.period_set.end(), period) == d.period_set.end()) {
        throw bad(leg_name + " = '" + c + "' is not a period of the period set");
      }
      p.periods.push_back(period);
    }
    if (!seen[it->second].insert(p.periods).second) {
      throw bad("repeats the combination " + robot::period_map_text(morph, p.periods, s.failed) +
                " of " + cells[0]);
    }
    std::size_t at = 1 + morph.size();
    bool ended = false;  // a window not walked: every later one is not either
    double worst = 0.0;
    for (int w = 0; w < d.windows; ++w, at += per_window) {
      const std::string label = "window " + std::to_string(w + 1);
      const bool empty = std::all_of(cells.begin() + static_cast<std::ptrdiff_t>(at),
                                     cells.begin() + static_cast<std::ptrdiff_t>(at + per_window),
                                     [](const std::string& c) { return c.empty(); });
      if (empty) {
        if (!d.reflex)
          throw bad(label + " is empty: a dataset of periods alone walks every window");
        if (w == 0) throw bad("window 1 is empty: every combination walks at least one window");
        if (!ended && body::holds(worst, d.threshold_deg - tolerance)) {
          throw bad(label + " is empty, but no window before it was over the threshold");
        }
        ended = true;
        continue;
      }
      if (ended) throw bad(label + " has values after a window that was not walked");
      body::WindowMeasure m;
      const std::optional<double> yaw = decimal(cells[at]);
      const std::optional<double> path = decimal(cells[at + 1]);
      if (!yaw) throw bad(label + "'s yaw '" + cells[at] + "' is not a number");
      if (!path) throw bad(label + "'s path '" + cells[at + 1] + "' is not a number");
      m.yaw_deg = *yaw;
      m.path_deg = *path;
      if (d.reflex) {
        const std::optional<double> e = decimal(cells[at + 2]);
        if (!e || *e < 0.0 || *e > 1.0) {
          throw bad(label + "'s effort '" + cells[at + 2] + "' is not a share from 0 to 1");
        }
        m.steering_effort = *e;
      }
      worst = std::max(worst, criterion.error(m));
      p.windows.push_back(m);
    }
    const std::optional<double> stored_worst = decimal(cells[at]);
    if (!stored_worst) throw bad("worst '" + cells[at] + "' is not a number");
    if (std::abs(*stored_worst - worst) > tolerance) {
      throw bad("worst " + cells[at] + " is not the largest window error (" + angle(worst) + ")");
    }
    p.worst_deg = *stored_worst;
    const std::string& holds = cells[at + 1];
    if (holds != "0" && holds != "1") throw bad("holds must be 0 or 1, got '" + holds + "'");
    p.holds = holds == "1";
    const bool all_walked = static_cast<int>(p.windows.size()) == d.windows;
    if (p.holds && (!all_walked || !body::holds(worst, d.threshold_deg + tolerance))) {
      throw bad("holds is 1, but a window is over the threshold or was not walked");
    }
    if (!p.holds && all_walked && body::holds(worst, d.threshold_deg - tolerance)) {
      throw bad("holds is 0, but every window is under the threshold");
    }
    s.points.push_back(std::move(p));
  }
  for (std::size_t i = 0; i < d.scenarios.size(); ++i) {
    if (d.scenarios[i].points.size() != expected[i]) {
      throw BadInput(cpath.string() + ": has " + std::to_string(d.scenarios[i].points.size()) +
                     " combinations of " + robot::leg_set_name(morph, d.scenarios[i].failed) +
                     ", its manifest " + std::to_string(expected[i]));
    }
  }
  return d;
}

}  // namespace

LandscapeDataset read_landscape_dataset(const fs::path& path) {
  return parse_dataset(path, read_manifest_file(stem_of(path)), nullptr);
}

LandscapeFiles read_landscape_files(const fs::path& path) {
  const fs::path stem = stem_of(path);
  return {read_manifest_file(stem), read_csv_file(stem)};
}

LandscapeDataset parse_landscape_dataset(const fs::path& path, const LandscapeFiles& files) {
  return parse_dataset(path, files.manifest, &files.csv_gzip);
}

}  // namespace multicpg::learning
