#include "report/replay/page.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "body/fault_spec.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/table.h"
#include "learning/model_learner.h"
#include "report/replay/assets.h"
#include "robot/leg_sets.h"

namespace multicpg::report {
namespace {

using nlohmann::json;

// Heightfield elevations are kept as 16-bit fractions of the field's elevation (0.05 m of rough
// ground in steps of under a micrometre).
constexpr double kHfieldLevels = 65535.0;

// Base64 (RFC 4648) by hand: nothing in the project's libraries encodes it, and the page decodes
// it with the browser's atob().
std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const auto n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]) << 16 |
                                              static_cast<unsigned char>(bytes[i + 1]) << 8 |
                                              static_cast<unsigned char>(bytes[i + 2]));
    for (int shift : {18, 12, 6, 0}) out += kAlphabet[(n >> shift) & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    std::uint32_t n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]) << 16);
    if (rest == 2) n |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += rest == 2 ? kAlphabet[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

template <class T>
std::string base64_of(const std::vector<T>& values) {
  // Little-endian, as the page's DataView reads it (every machine the project builds on).
  return base64(
      std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
}

// The poses as the page decodes them: body by body, value by value, each value's steps as the
// change from the step before (the first from 0), zigzag-mapped to unsigned and written 7 bits a
// byte (LEB128), so a value that barely moves costs one byte a step.
std::string encode_poses(const Recording& r) {
  const std::size_t rows = r.rows();
  const std::size_t width = r.scene.bodies.size() * kReplayPoseValues;
  std::string out;
  out.reserve(rows * width * 2);
  for (std::size_t column = 0; column < width; ++column) {
    std::int64_t last = 0;
    for (std::size_t row = 0; row < rows; ++row) {
      const std::int64_t value = r.poses[row * width + column];
      const std::int64_t delta = value - last;
      last = value;
      auto zigzag = static_cast<std::uint64_t>(delta < 0 ? ~(delta << 1) : delta << 1);
      do {
        const auto low = static_cast<unsigned char>(zigzag & 0x7F);
        zigzag >>= 7;
        out += static_cast<char>(zigzag != 0 ? low | 0x80 : low);
      } while (zigzag != 0);
    }
  }
  return out;
}

// One bit per leg and step, the legs of a step in ceil(legs / 8) bytes.
std::string encode_contacts(const Recording& r) {
  const std::size_t legs = r.scene.morphology.size();
  const std::size_t per_row = (legs + 7) / 8;
  std::string out(r.rows() * per_row, '\0');
  for (std::size_t row = 0; row < r.rows(); ++row) {
    for (std::size_t leg = 0; leg < legs; ++leg) {
      if (r.contacts[row * legs + leg] != 0) {
        out[row * per_row + leg / 8] = static_cast<char>(
            static_cast<unsigned char>(out[row * per_row + leg / 8]) | (1U << (leg % 8)));
      }
    }
  }
  return out;
}

json colour_json(const Rgba& c) {
  return json::array({c[0], c[1], c[2], c[3]});
}

json geom_json(const ReplayGeom& g) {
  json j{{"type", g.type},
         {"body", g.body},
         {"name", g.name},
         {"pos", g.pos},
         {"quat", g.quat},
         {"size", g.size},
         {"rgba", colour_json(g.rgba)}};
  if (g.mesh >= 0) j["mesh"] = g.mesh;
  if (g.hfield >= 0) j["hfield"] = g.hfield;
  if (g.checker) {
    j["checker"] = {{"first", colour_json(g.checker->first)},
                    {"second", colour_json(g.checker->second)},
                    {"repeat", g.checker->repeat}};
  }
  return j;
}

// The part of the run's ground the page draws: everything within kGroundMarginM of where any
// body went (rough ground's heightfield covers 100 m a side, four million samples; a run walks a
// few metres of it).
constexpr double kGroundMarginM = 3.0;

struct Extent {
  double min_x, max_x, min_y, max_y;
};

Extent run_extent(const Recording& r) {
  Extent e{1e300, -1e300, 1e300, -1e300};
  for (std::size_t row = 0; row < r.rows(); ++row) {
    for (std::size_t b = 0; b < r.scene.bodies.size(); ++b) {
      const std::array<double, 3> p = r.position(row, b);
      e.min_x = std::min(e.min_x, p[0]);
      e.max_x = std::max(e.max_x, p[0]);
      e.min_y = std::min(e.min_y, p[1]);
      e.max_y = std::max(e.max_y, p[1]);
    }
  }
  return {e.min_x - kGroundMarginM, e.max_x + kGroundMarginM, e.min_y - kGroundMarginM,
          e.max_y + kGroundMarginM};
}

// The samples of `h` (under a geom at `pos`, not turned) within `extent`, as a grid from x[0] to
// x[1] and y[0] to y[1] in the geom's frame; a turned geom's field is kept whole.
json hfield_json(const ReplayHfield& h, const ReplayGeom* geom, const Extent& extent) {
  const double sx = h.size[0];
  const double sy = h.size[1];
  int c0 = 0, c1 = h.ncol - 1, r0 = 0, r1 = h.nrow - 1;
  if (geom != nullptr && geom->body < 0 &&
      geom->quat == std::array<double, 4>{1.0, 0.0, 0.0, 0.0}) {
    const auto index = [](double local, double half, int samples) {
      return std::clamp((local + half) / (2.0 * half) * (samples - 1), 0.0, samples - 1.0);
    };
    c0 = static_cast<int>(std::floor(index(extent.min_x - geom->pos[0], sx, h.ncol)));
    c1 = static_cast<int>(std::ceil(index(extent.max_x - geom->pos[0], sx, h.ncol)));
    r0 = static_cast<int>(std::floor(index(extent.min_y - geom->pos[1], sy, h.nrow)));
    r1 = static_cast<int>(std::ceil(index(extent.max_y - geom->pos[1], sy, h.nrow)));
    c1 = std::max(c1, std::min(c0 + 1, h.ncol - 1));
    r1 = std::max(r1, std::min(r0 + 1, h.nrow - 1));
  }
  std::vector<std::uint16_t> levels;
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const float v = h.data[static_cast<std::size_t>(r) * h.ncol + c];
      levels.push_back(
          static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0F, 1.0F) * kHfieldLevels)));
    }
  }
  const auto at = [](int i, double half, int samples) {
    return -half + 2.0 * half * i / (samples - 1);
  };
  return {{"nrow", r1 - r0 + 1},
          {"ncol", c1 - c0 + 1},
          {"x", {at(c0, sx, h.ncol), at(c1, sx, h.ncol)}},
          {"y", {at(r0, sy, h.nrow), at(r1, sy, h.nrow)}},
          {"elevation", h.size[2]},
          {"levels", kHfieldLevels},
          {"data", base64_of(levels)}};
}

// The events with the names a reader knows: legs by name, faults as the CLI writes them.
json event_json(const robot::Morphology& morph, const body::Event& e) {
  json j{{"kind", body::to_string(e.kind)}, {"step", e.step}};
  switch (e.kind) {
    case body::EventKind::fault:
    case body::EventKind::recovery:
      j["legs"] = robot::leg_set_name(morph, e.legs);
      if (e.fault) j["fault"] = body::malfunction_text(morph, *e.fault);
      break;
    case body::EventKind::detection:
      j["episode"] = e.episode;
      j["deviation_deg"] = e.deviation_deg;
      break;
    case body::EventKind::trial_start:
      j["episode"] = e.episode;
      j["trial"] = e.trial;
      j["periods"] = e.periods;
      break;
    case body::EventKind::trial_end:
    case body::EventKind::episode_end:
      j["episode"] = e.episode;
      j["trial"] = e.trial;
      j["periods"] = e.periods;
      j["deviation_deg"] = e.deviation_deg;
      j["accepted"] = e.accepted;
      // A model-based learner's forecast of the trial's E (docs/learning.md "Inside the model").
      if (const std::optional<learning::ForecastE> f = learning::forecast_e(e.details)) {
        j["predicted_e_deg"] = f->deg;
        j["predicted_e_low_deg"] = f->low_deg;
        j["predicted_e_high_deg"] = f->high_deg;
      }
      break;
  }
  return j;
}

json paint_json(const Recording& r, const ReplayPaint& p) {
  // Fault colours name the model's geoms; the page knows the visible ones by their index.
  json colours = json::array();
  for (const GeomColour& c : p.colours) {
    for (std::size_t i = 0; i < r.scene.geoms.size(); ++i) {
      if (r.scene.geoms[i].model_geom == c.geom)
        colours.push_back({{"geom", i}, {"rgba", colour_json(c.rgba)}});
    }
  }
  json reshaped = json::array();
  for (const ReplayReshape& s : p.reshaped) {
    reshaped.push_back({{"geom", s.geom}, {"pos", s.pos}, {"quat", s.quat}, {"size", s.size}});
  }
  json legs = json::object();
  for (const auto& [leg, rgba] : p.legs) {
    legs[r.scene.morphology.legs[leg].name] = colour_json(rgba);
  }
  return {{"step", p.step},
          {"faults", p.faults},
          {"colours", colours},
          {"legs", legs},
          {"reshaped", reshaped}};
}

// Splits the page template at "@NAME@" markers and joins it with the values, in one pass (so
// nothing inserted is scanned again).
std::string fill_template(
    std::string_view page,
    const std::vector<std::pair<std::string_view, std::string_view>>& values) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = page.find('@', at);
    if (open == std::string_view::npos) break;
    const std::size_t close = page.find('@', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view name = page.substr(open + 1, close - open - 1);
    const auto value =
        std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == name; });
    if (value == values.end()) {
      out += page.substr(at, close - at);
      at = close;
      continue;
    }
    out += page.substr(at, open - at);
    out += value->second;
    at = close + 1;
  }
  out += page.substr(at);
  return out;
}

// JSON inside a <script> element: "</" would end it, so it is written "<\\/" (the same string).
std::string script_safe(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

}  // namespace

void check_replay_path(const std::filesystem::path& out) {
  const std::string ext = out.extension().string();
  if (ext != ".html") {  // docs/replay.md: one spelling, the one the browser and the docs use
    throw BadInput("cannot write a replay to '" + out.string() +
                   "': the file type must be .html (one self-contained page)");
  }
  require_writable_file(out);
}

json replay_document(const Recording& r, const std::string& title) {
  const ReplayScene& s = r.scene;
  json bodies = json::array();
  for (const ReplayBody& b : s.bodies) bodies.push_back({{"name", b.name}, {"parent", b.parent}});
  json geoms = json::array();
  for (const ReplayGeom& g : s.geoms) geoms.push_back(geom_json(g));
  json meshes = json::array();
  for (const ReplayMesh& m : s.meshes) {
    meshes.push_back({{"vertices", base64_of(m.vertices)}, {"faces", base64_of(m.faces)}});
  }
  json hfields = json::array();
  const Extent extent = run_extent(r);
  for (std::size_t i = 0; i < s.hfields.size(); ++i) {
    const auto geom = std::find_if(s.geoms.begin(), s.geoms.end(), [&](const ReplayGeom& g) {
      return g.hfield == static_cast<int>(i);
    });
    hfields.push_back(hfield_json(s.hfields[i], geom == s.geoms.end() ? nullptr : &*geom, extent));
  }
  json legs = json::array();
  for (const robot::Leg& leg : s.morphology.legs) legs.push_back(leg.name);
  json events = json::array();
  for (const body::Event& e : r.events) events.push_back(event_json(s.morphology, e));
  json paints = json::array();
  for (const ReplayPaint& p : r.paints) paints.push_back(paint_json(r, p));
  json periods = json::array();
  for (const ReplayPeriods& p : r.periods)
    periods.push_back({{"step", p.step}, {"periods", p.periods}});
  json tunnel;
  if (s.tunnel) tunnel = {{"length_m", (*s.tunnel)[0]}, {"width_m", (*s.tunnel)[1]}};
  return {{"format", kReplayFormat},
          {"version", kReplayVersion},
          {"title", title},
          {"robot", s.robot},
          {"legs", legs},
          {"control_dt", s.control_dt},
          {"first_step", r.first_step},
          {"rows", r.rows()},
          {"bodies", bodies},
          {"trunk", s.trunk},
          {"geoms", geoms},
          {"meshes", meshes},
          {"hfields", hfields},
          {"tunnel", tunnel},
          {"ground_margin_m", kGroundMarginM},
          {"start", {{"x", r.start[0]}, {"y", r.start[1]}, {"yaw_deg", r.start[2]}}},
          {"poses",
           {{"unit_m", kReplayPositionUnit},
            {"unit_quat", kReplayQuaternionUnit},
            {"values", kReplayPoseValues},
            {"data", base64(encode_poses(r))}}},
          {"contacts", base64(encode_contacts(r))},
          {"events", events},
          {"paints", paints},
          {"periods", periods}};
}

std::string replay_html(const Recording& r, const std::string& title) {
  const ReplayAssets& a = replay_assets();
  const std::string data = script_safe(replay_document(r, title).dump());
  const std::string escaped_title = html_escape(title);
  return fill_template(a.page, {{"TITLE", escaped_title},
                                {"STYLE", a.style},
                                {"DATA", data},
                                {"THREE", a.three},
                                {"ORBIT_CONTROLS", a.orbit_controls},
                                {"SCRIPT", a.script}});
}

void write_replay(const Recording& r, const std::string& title, const std::filesystem::path& out) {
  check_replay_path(out);
  if (r.rows() == 0) throw RuntimeFailure("no step of the run was recorded for " + out.string());
  write_file_atomic(out, replay_html(r, title));
}

}  // namespace multicpg::report
