#include "robot/terrain.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/errors.h"

namespace multicpg::robot {
namespace {

const std::string kForm =
    "takes flat, slope:DEG[:HEADING_DEG], rough:HEIGHT_M[:SEED] or steps:HEIGHT_M:DEPTH_M "
    "(e.g. slope:5, rough:0.01, steps:0.02:0.2)";

std::vector<std::string_view> fields(std::string_view text) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t colon = text.find(':', start);
    out.push_back(text.substr(start, colon - start));
    if (colon == std::string_view::npos) return out;
    start = colon + 1;
  }
}

double number(std::string_view text, std::string_view what, const Limits<double>& limits,
              std::string_view unit) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw BadInput(fmt::format("terrain: {} '{}' is not a number", what, text));
  }
  if (!limits.contains(v)) {
    throw BadInput(
        fmt::format("terrain: {} must be in {} {}, got {}", what, limits.text(), unit, text));
  }
  return v;
}

std::string shortest(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

// SplitMix64: a fixed, portable stream of 64-bit draws, so a seed gives the same terrain on every
// machine and library (std's distributions are not specified bit for bit).
std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace

void validate(const Terrain& t) {
  switch (t.kind) {
    case TerrainKind::flat:
      break;
    case TerrainKind::slope:
      require_in("slope_deg", t.slope_deg, kSlopeLimits);
      require_in("heading_deg", t.heading_deg, kHeadingLimits);
      break;
    case TerrainKind::rough:
      require_in("height_m", t.height_m, kBumpLimits);
      break;
    case TerrainKind::steps:
      require_in("height_m", t.height_m, kBumpLimits);
      require_in("depth_m", t.depth_m, kStepDepthLimits);
      break;
  }
}

Terrain parse_terrain(std::string_view text) {
  const std::vector<std::string_view> f = fields(text);
  Terrain t;
  const auto count = [&](std::size_t lo, std::size_t hi) {
    if (f.size() < lo || f.size() > hi) throw BadInput(kForm + "; got '" + std::string(text) + "'");
  };
  if (f[0] == "flat") {
    count(1, 1);
  } else if (f[0] == "slope") {
    count(2, 3);
    t.kind = TerrainKind::slope;
    t.slope_deg = number(f[1], "the slope", kSlopeLimits, "deg");
    if (f.size() == 3) t.heading_deg = number(f[2], "the heading", kHeadingLimits, "deg");
  } else if (f[0] == "rough") {
    count(2, 3);
    t.kind = TerrainKind::rough;
    t.height_m = number(f[1], "the bump height", kBumpLimits, "m");
    if (f.size() == 3) {
      const std::string_view s = f[2];
      const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), t.seed);
      if (s.empty() || ec != std::errc() || ptr != s.data() + s.size()) {
        throw BadInput("terrain: the seed '" + std::string(s) + "' is not a whole number");
      }
    }
  } else if (f[0] == "steps") {
    count(3, 3);
    t.kind = TerrainKind::steps;
    t.height_m = number(f[1], "the step height", kBumpLimits, "m");
    t.depth_m = number(f[2], "the step depth", kStepDepthLimits, "m");
  } else {
    throw BadInput(kForm + "; got '" + std::string(text) + "'");
  }
  return t;
}

std::string terrain_text(const Terrain& t) {
  switch (t.kind) {
    case TerrainKind::flat:
      break;
    case TerrainKind::slope:
      return "slope:" + shortest(t.slope_deg) + ":" + shortest(t.heading_deg);
    case TerrainKind::rough:
      return "rough:" + shortest(t.height_m) + ":" + std::to_string(t.seed);
    case TerrainKind::steps:
      return "steps:" + shortest(t.height_m) + ":" + shortest(t.depth_m);
  }
  return "flat";
}

std::array<double, 4> ground_rotation(const Terrain& t) {
  if (t.kind != TerrainKind::slope) return {1.0, 0.0, 0.0, 0.0};
  const double angle = -t.slope_deg * std::numbers::pi / 180.0;
  const double heading = t.heading_deg * std::numbers::pi / 180.0;
  const double s = std::sin(angle / 2.0);
  return {std::cos(angle / 2.0), -std::sin(heading) * s, std::cos(heading) * s, 0.0};
}

std::array<double, 3> rotate(const std::array<double, 4>& q, const std::array<double, 3>& v) {
  // v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
  const std::array<double, 3> u{q[1], q[2], q[3]};
  const auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  const std::array<double, 3> t = cross(u, v);
  const std::array<double, 3> t2 = cross(u, t);
  return {v[0] + 2.0 * (q[0] * t[0] + t2[0]), v[1] + 2.0 * (q[0] * t[1] + t2[1]),
          v[2] + 2.0 * (q[0] * t[2] + t2[2])};
}

std::array<double, 3> to_ground_frame(const Terrain& terrain, const std::array<double, 3>& p) {
  const std::array<double, 4> q = ground_rotation(terrain);
  return rotate({q[0], -q[1], -q[2], -q[3]}, p);  // the inverse rotation
}

bool bounded(const Terrain& terrain) {
  return terrain.kind == TerrainKind::rough || terrain.kind == TerrainKind::steps;
}

int rough_samples_per_side() {
  return static_cast<int>(std::lround(kTerrainSide / kRoughCell)) + 1;
}

std::vector<float> rough_samples(const Terrain& terrain) {
  const int n = rough_samples_per_side();
  std::vector<float> out(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  std::uint64_t state = terrain.seed;
  for (float& v : out) {
    // The top 24 bits: every float in [0, 1) they give is exact.
    v = static_cast<float>(splitmix64(state) >> 40) / static_cast<float>(1 << 24);
  }
  const auto [lo, hi] = std::minmax_element(out.begin(), out.end());
  const float low = *lo;
  const float span = *hi - *lo;
  for (float& v : out) v = (v - low) / span;
  return out;
}

}  // namespace multicpg::robot
