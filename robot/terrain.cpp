#include "robot/terrain.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/errors.h"
#include "common/random.h"
#include "common/variants.h"

namespace multicpg::robot {
namespace {

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
    throw BadInput(fmt::format("{} '{}' is not a number", what, text));
  }
  if (!limits.contains(v)) {
    throw BadInput(fmt::format("{} must be in {} {}, got {}", what, limits.text(), unit, text));
  }
  return v;
}

std::string shortest(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

// "flat, slope:DEG[:HEADING_DEG], ... or steps:HEIGHT_M:DEPTH_M (e.g. slope:5, ...)" from the
// kinds' parameters.
std::string forms() {
  std::vector<std::string> all;
  std::vector<std::string> examples;
  each_alternative<TerrainKind>([&](const auto& kind) {
    using Kind = std::decay_t<decltype(kind)>;
    std::string form(Kind::kName);
    for (const TerrainParam& p : Kind::kParams) {
      form += p.fallback ? "[:" + std::string(p.form) + "]" : ":" + std::string(p.form);
    }
    all.push_back(form);
    if (!Kind::kExample.empty()) examples.emplace_back(Kind::kExample);
  });
  const auto list = [](const std::vector<std::string>& items, const char* last) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
      out += (i == 0 ? "" : i + 1 == items.size() ? last : ", ") + items[i];
    }
    return out;
  };
  return "takes " + list(all, " or ") + " (e.g. " + list(examples, ", ") + ")";
}

// One parameter's text, read as its type.
void read_value(std::string_view text, const TerrainParam& p, double& value) {
  value = number(text, p.what, *p.limits, p.unit);
}
void read_value(std::string_view text, const TerrainParam& p, std::uint64_t& value) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
    throw BadInput(std::string(p.what) + " '" + std::string(text) + "' is not a whole number");
  }
}
std::string value_text(double v) {
  return shortest(v);
}
std::string value_text(std::uint64_t v) {
  return std::to_string(v);
}

// Calls f(param, value) for each parameter of `kind` with its member.
template <class Kind, class F>
void each_value(Kind& kind, F&& f) {
  std::size_t i = 0;
  std::apply([&](auto&... value) { (f(Kind::kParams[i++], value), ...); }, kind.values());
}

// The traits a kind may have (robot/terrain.h).
template <class Kind>
concept Tilted = requires(const Kind& k) {
  k.rotation();
};

}  // namespace

std::array<double, 4> Slope::rotation() const {
  const double angle = -slope_deg * std::numbers::pi / 180.0;
  const double heading = heading_deg * std::numbers::pi / 180.0;
  const double s = std::sin(angle / 2.0);
  return {std::cos(angle / 2.0), -std::sin(heading) * s, std::cos(heading) * s, 0.0};
}

std::vector<float> Rough::heightfield_samples() const {
  const int n = heightfield_samples_per_side();
  std::vector<float> out(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  std::uint64_t state = seed;
  for (float& v : out) {
    // The top 24 bits: every float in [0, 1) they give is exact.
    v = static_cast<float>(splitmix64_next(state) >> 40) / static_cast<float>(1 << 24);
  }
  const auto [lo, hi] = std::minmax_element(out.begin(), out.end());
  const float low = *lo;
  const float span = *hi - *lo;
  for (float& v : out) v = (v - low) / span;
  return out;
}

std::vector<TerrainBox> Steps::boxes() const {
  std::vector<TerrainBox> out;
  for (double side : {1.0, -1.0}) {
    for (double x = kStepsStart; x + depth_m <= kTerrainSide / 2.0; x += 2.0 * depth_m) {
      out.push_back({{side * (x + depth_m / 2.0), 0.0, height_m / 2.0},
                     {depth_m / 2.0, kTerrainSide / 2.0, height_m / 2.0}});
    }
  }
  return out;
}

void validate(const Terrain& t) {
  std::visit(
      [](const auto& kind) {
        each_value(kind, [](const TerrainParam& p, const auto& value) {
          if (p.limits) require_in(std::string(p.key), static_cast<double>(value), *p.limits);
        });
      },
      t.kind);
}

Terrain parse_terrain(std::string_view text) {
  const std::vector<std::string_view> f = fields(text);
  std::optional<Terrain> made;
  each_alternative<TerrainKind>([&](auto kind) {
    using Kind = decltype(kind);
    if (made || f[0] != Kind::kName) return;
    std::size_t required = 0;
    for (const TerrainParam& p : Kind::kParams) required += p.fallback ? 0 : 1;
    if (f.size() < 1 + required || f.size() > 1 + Kind::kParams.size()) {
      throw BadInput(forms() + "; got '" + std::string(text) + "'");
    }
    std::size_t i = 1;
    each_value(kind, [&](const TerrainParam& p, auto& value) {
      using Value = std::decay_t<decltype(value)>;
      if (i < f.size()) {
        read_value(f[i], p, value);
      } else {
        value = static_cast<Value>(*p.fallback);
      }
      ++i;
    });
    made = Terrain{kind};
  });
  if (!made) throw BadInput(forms() + "; got '" + std::string(text) + "'");
  return *made;
}

std::string terrain_text(const Terrain& t) {
  return std::visit(
      [](const auto& kind) {
        std::string text(kind.kName);
        each_value(kind, [&](const TerrainParam&, const auto& value) {
          text += ':';
          text += value_text(value);
        });
        return text;
      },
      t.kind);
}

std::string_view terrain_name(const Terrain& t) {
  return std::visit([](const auto& kind) { return kind.kName; }, t.kind);
}

bool is_flat(const Terrain& t) {
  return std::holds_alternative<Flat>(t.kind);
}

bool bounded(const Terrain& t) {
  return std::visit([](const auto& kind) { return kind.kBounded; }, t.kind);
}

bool keeps_own_ground(const Terrain& t) {
  return std::visit([](const auto& kind) { return kind.kOwnGround; }, t.kind);
}

bool tilted(const Terrain& t) {
  return std::visit([]<class Kind>(const Kind&) { return Tilted<Kind>; }, t.kind);
}

double rise(const Terrain& t) {
  return std::visit(
      [](const auto& kind) {
        if constexpr (requires { kind.rise(); }) {
          return kind.rise();
        } else {
          return 0.0;
        }
      },
      t.kind);
}

std::optional<std::vector<float>> heightfield_samples(const Terrain& t) {
  return std::visit(
      [](const auto& kind) -> std::optional<std::vector<float>> {
        if constexpr (requires { kind.heightfield_samples(); }) {
          return kind.heightfield_samples();
        } else {
          return std::nullopt;
        }
      },
      t.kind);
}

int heightfield_samples_per_side() {
  return static_cast<int>(std::lround(kTerrainSide / kRoughCell)) + 1;
}

std::vector<TerrainBox> terrain_boxes(const Terrain& t) {
  return std::visit(
      [](const auto& kind) -> std::vector<TerrainBox> {
        if constexpr (requires { kind.boxes(); }) {
          return kind.boxes();
        } else {
          return {};
        }
      },
      t.kind);
}

std::array<double, 4> ground_rotation(const Terrain& t) {
  return std::visit(
      []<class Kind>(const Kind& kind) -> std::array<double, 4> {
        if constexpr (Tilted<Kind>) {
          return kind.rotation();
        } else {
          return {1.0, 0.0, 0.0, 0.0};
        }
      },
      t.kind);
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

}  // namespace multicpg::robot
