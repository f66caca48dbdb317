#include "learning/landscapes.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "common/atomic_file.h"
#include "common/checksum.h"
#include "common/errors.h"
#include "robot/leg_sets.h"
#include "sim/deviation.h"

namespace multicpg::learning {
namespace {

namespace fs = std::filesystem;

constexpr int kFormatVersion = 1;
constexpr int kJsonIndent = 2;
constexpr const char* kFailedCell = "x";
// zlib's "gzip wrapper" flag for deflateInit2/inflateInit2 window bits (zlib.h).
constexpr int kGzipWindowBits = 15 + 16;
constexpr int kMemLevel = 8;  // zlib's default
constexpr std::size_t kChunk = 1 << 16;

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

std::string angle(double deg) {
  const double r = std::round(deg / kLandscapeAngleResolutionDeg) * kLandscapeAngleResolutionDeg;
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(3);
  out << (r == 0.0 ? 0.0 : r);  // no "-0.000"
  return out.str();
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
      throw BadInput("'" + path.string() + "' is not a whole gzip file (cut short or damaged)");
    }
    out.append(chunk.data(), chunk.size() - z.avail_out);
    if (rc == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
      inflateEnd(&z);
      throw BadInput("'" + path.string() + "' is cut short");
    }
  }
  inflateEnd(&z);
  return out;
}

std::string read_whole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BadInput("cannot read the landscape file '" + path.string() + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(line);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

double number(const std::string& text, const fs::path& path, std::size_t line) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v)) {
    throw BadInput("'" + path.string() + "' line " + std::to_string(line) + ": '" + text +
                   "' is not a number");
  }
  return v;
}

}  // namespace

std::filesystem::path repository_dataset(robot::RobotKind robot) {
  return fs::path(MULTICPG_DATA_DIR) / "landscapes" / std::string(robot::to_string(robot));
}

double LandscapePoint::window_error(std::size_t window, bool yaw_only) const {
  const double yaw = std::abs(yaw_deg.at(window));
  return yaw_only ? yaw : std::max(yaw, std::abs(path_deg.at(window)));
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

void write_landscape_dataset(const LandscapeDataset& d, const fs::path& path) {
  const robot::Morphology& morph = robot::morphology(d.robot);
  std::ostringstream csv;
  csv << "scenario";
  for (const robot::Leg& leg : morph.legs) csv << "," << leg.name;
  for (int w = 1; w <= d.windows; ++w) csv << ",w" << w << "_yaw,w" << w << "_path";
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
      for (int w = 0; w < d.windows; ++w) {
        csv << "," << angle(p.yaw_deg.at(w)) << "," << angle(p.path_deg.at(w));
      }
      csv << "," << angle(p.worst_deg) << "," << (p.holds ? 1 : 0) << "\n";
    }
    const std::size_t holding = s.holding();
    scenarios.push_back(
        {{"scenario", name},
         {"combinations", s.points.size()},
         {"holding", holding},
         {"share_holding",
          s.points.empty() ? 0.0
                           : static_cast<double>(holding) / static_cast<double>(s.points.size())}});
  }
  const std::string text = csv.str();
  const nlohmann::json manifest{{"format", "multicpg landscape dataset"},
                                {"version", kFormatVersion},
                                {"robot", robot::to_string(d.robot)},
                                {"period_set", d.period_set},
                                {"windows", d.windows},
                                {"window_steps", d.window_steps},
                                {"threshold_deg", d.threshold_deg},
                                {"angle_resolution_deg", kLandscapeAngleResolutionDeg},
                                {"sim", d.sim},
                                {"scenarios", scenarios},
                                {"checksum", checksum_text(text)}};
  const fs::path stem = stem_of(path);
  write_file_atomic(csv_path(stem), gzip(text));
  write_file_atomic(manifest_path(stem), manifest.dump(kJsonIndent) + "\n");
}

LandscapeDataset read_landscape_dataset(const fs::path& path) {
  const fs::path stem = stem_of(path);
  const fs::path mpath = manifest_path(stem);
  const fs::path cpath = csv_path(stem);
  nlohmann::json m;
  try {
    m = nlohmann::json::parse(read_whole(mpath));
  } catch (const nlohmann::json::exception&) {
    throw BadInput("'" + mpath.string() + "' is not a landscape manifest (not JSON)");
  }
  LandscapeDataset d;
  std::map<std::string, std::size_t> expected;
  try {
    if (m.at("format") != "multicpg landscape dataset") throw BadInput("not a landscape manifest");
    if (m.at("version").get<int>() != kFormatVersion) {
      throw BadInput("format version " + m.at("version").dump() + ", this program reads " +
                     std::to_string(kFormatVersion));
    }
    d.robot = robot::parse_robot(m.at("robot").get<std::string>());
    d.period_set = m.at("period_set").get<std::vector<int>>();
    d.windows = m.at("windows").get<int>();
    d.window_steps = m.at("window_steps").get<long>();
    d.threshold_deg = m.at("threshold_deg").get<double>();
    d.sim = m.at("sim");
    for (const nlohmann::json& s : m.at("scenarios")) {
      expected[s.at("scenario").get<std::string>()] = s.at("combinations").get<std::size_t>();
    }
  } catch (const nlohmann::json::exception& e) {
    throw BadInput("'" + mpath.string() + "' is not a landscape manifest: " + e.what());
  } catch (const BadInput& e) {
    throw BadInput("'" + mpath.string() + "': " + e.what());
  }
  if (d.windows < 1) throw BadInput("'" + mpath.string() + "': windows must be at least 1");
  const std::string text = gunzip(read_whole(cpath), cpath);
  if (checksum_text(text) != m.at("checksum").get<std::string>()) {
    throw BadInput("'" + cpath.string() + "' does not match its manifest's checksum (edited?)");
  }

  const robot::Morphology& morph = robot::morphology(d.robot);
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  const std::size_t columns = 1 + morph.size() + 2 * static_cast<std::size_t>(d.windows) + 2;
  if (split(line, ',').size() != columns) {
    throw BadInput("'" + cpath.string() + "' has not the columns its manifest says");
  }
  std::size_t number_of_line = 1;
  std::map<std::string, std::size_t> index;
  while (std::getline(in, line)) {
    ++number_of_line;
    const std::vector<std::string> cells = split(line, ',');
    const auto bad = [&](const std::string& what) {
      return BadInput("'" + cpath.string() + "' line " + std::to_string(number_of_line) + ": " +
                      what);
    };
    if (cells.size() != columns) throw bad("expected " + std::to_string(columns) + " cells");
    if (!index.count(cells[0])) {
      index[cells[0]] = d.scenarios.size();
      ScenarioLandscape s;
      try {
        s.failed = robot::parse_leg_set(morph, cells[0]);
      } catch (const BadInput& e) {
        throw bad(e.what());
      }
      d.scenarios.push_back(std::move(s));
    }
    ScenarioLandscape& s = d.scenarios[index[cells[0]]];
    LandscapePoint p;
    for (std::size_t leg = 0; leg < morph.size(); ++leg) {
      const std::string& c = cells[1 + leg];
      const bool is_failed = std::binary_search(s.failed.begin(), s.failed.end(), leg);
      if (is_failed != (c == kFailedCell))
        throw bad("leg " + morph.legs[leg].name + " is '" + c + "'");
      const int period =
          is_failed ? kStartPeriod : static_cast<int>(number(c, cpath, number_of_line));
      if (!is_failed &&
          std::find(d.period_set.begin(), d.period_set.end(), period) == d.period_set.end()) {
        throw bad("period " + c + " is not in the period set");
      }
      p.periods.push_back(period);
    }
    std::size_t at = 1 + morph.size();
    for (int w = 0; w < d.windows; ++w) {
      p.yaw_deg.push_back(number(cells[at++], cpath, number_of_line));
      p.path_deg.push_back(number(cells[at++], cpath, number_of_line));
    }
    p.worst_deg = number(cells[at++], cpath, number_of_line);
    if (cells[at] != "0" && cells[at] != "1") throw bad("holds must be 0 or 1");
    p.holds = cells[at] == "1";
    s.points.push_back(std::move(p));
  }
  for (const auto& [name, count] : expected) {
    const auto it = index.find(name);
    const std::size_t have = it == index.end() ? 0 : d.scenarios[it->second].points.size();
    if (have != count) {
      throw BadInput("'" + cpath.string() + "' has " + std::to_string(have) + " combinations of " +
                     name + ", its manifest " + std::to_string(count));
    }
  }
  if (index.size() != expected.size()) {
    throw BadInput("'" + cpath.string() + "' has scenarios its manifest does not list");
  }
  return d;
}

}  // namespace multicpg::learning
