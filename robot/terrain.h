// The ground the robot walks on (paper §6: rough terrain as the next step; docs/faults.md):
//
//   flat                        the plane of the paper's experiments
//   slope:DEG[:HEADING_DEG]     a plane rising DEG (0..30) towards HEADING (0 = +x, the way the
//                               robot starts walking: uphill; 180 = downhill)
//   rough:HEIGHT_M[:SEED]       a heightfield of random bumps up to HEIGHT (0.001..0.05 m) on a
//                               grid of kRoughCell, seeded (default 1)
//   steps:HEIGHT_M:DEPTH_M      past kStepsStart ahead of and behind the start, the floor steps up
//                               HEIGHT (0.001..0.05 m) for DEPTH (0.05..1 m), down for DEPTH, and
//                               so on, full width
//
// Rough ground and steps cover a square of kTerrainSide around the start; a robot that walks off
// it has left the terrain it was asked to walk on (sim::sim_step fails). The tunnel's walls stand
// on the terrain. Deviations are measured in the horizontal plane whatever the ground.
//
// A terrain kind is an alternative of TerrainKind with its traits in its own struct, as fault
// kinds are (body/faults.h): its name and an example, the parameters its text gives (kParams, with
// values() returning them in that order), whether it covers only kTerrainSide (kBounded) and
// whether a robot file keeps its own ground under it (kOwnGround), and, where it has them, its tilt
// (rotation), the height its bumps rise to (rise), its heightfield (heightfield_samples) and the
// boxes standing on it (boxes). Adding a kind: its struct here, its alternative in TerrainKind and
// its geometry in terrain.cpp. Parsing, text, JSON, validation, the MJCF (robot/mjcf.cpp), the CLI,
// experiment files and the simulation go through the traits.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <variant>
#include <vector>

#include "common/limits.h"

namespace multicpg::robot {

// Documented ranges. Slopes: AMOSII-like robots climb up to about 20-30 deg; steepness past 30 deg
// is refused. Bumps and steps up to 5 cm: the hexapod's feet lift about 4 cm in a stride (CTr
// 45-75 deg on a 6 cm femur), so higher ones block it outright.
inline constexpr Limits<double> kSlopeLimits{0.0, 30.0};
inline constexpr Limits<double> kHeadingLimits{-180.0, 180.0};
inline constexpr Limits<double> kBumpLimits{0.001, 0.05};
inline constexpr Limits<double> kStepDepthLimits{0.05, 1.0};
// Rough ground and steps: a square of this side (m) around the start. Robust learning on rough
// ground walked 20 m from the start in 19,584 steps (docs/faults.md "Measurements"), past an
// earlier 40 m square; 100 m leaves room for runs of 50,000 steps at the tripod's 1 m per 1,000.
inline constexpr double kTerrainSide = 100.0;
// Rough ground: heightfield cell (m), a third of the hexapod's foot-to-foot spacing along a side.
inline constexpr double kRoughCell = 0.05;
// Steps begin this far ahead of and behind the start (m), so the robot starts on flat ground.
inline constexpr double kStepsStart = 0.5;

// A parameter of a terrain kind, written after its name: KIND:VALUE[:VALUE].
struct TerrainParam {
  std::string_view key;   // the member's name: OptionError's key ("slope_deg")
  std::string_view form;  // how the text's form names it ("DEG")
  std::string_view what;  // how messages name it ("the slope")
  std::string_view unit;  // "deg", "m"
  // Its documented range; none: any whole number (a seed, std::uint64_t).
  std::optional<Limits<double>> limits;
  // What it is when the text leaves it out; none: the text must give it.
  std::optional<double> fallback;
};

// A box standing on the ground (steps): its centre and half sizes, m.
struct TerrainBox {
  std::array<double, 3> centre;
  std::array<double, 3> half;
};

struct Flat {
  static constexpr std::string_view kName = "flat";
  static constexpr std::string_view kExample = "";  // for messages
  static constexpr std::array<TerrainParam, 0> kParams{};
  static constexpr bool kBounded = false;
  static constexpr bool kOwnGround = true;
  auto values() { return std::tie(); }
  auto values() const { return std::tie(); }
  bool operator==(const Flat&) const = default;
};

struct Slope {
  static constexpr std::string_view kName = "slope";
  static constexpr std::string_view kExample = "slope:5";  // for messages
  static constexpr std::array<TerrainParam, 2> kParams{{
      {"slope_deg", "DEG", "the slope", "deg", kSlopeLimits, std::nullopt},
      {"heading_deg", "HEADING_DEG", "the heading", "deg", kHeadingLimits, 0.0},
  }};
  static constexpr bool kBounded = false;
  static constexpr bool kOwnGround = false;
  double slope_deg = 0.0;
  double heading_deg = 0.0;  // the uphill direction, + = left of +x
  auto values() { return std::tie(slope_deg, heading_deg); }
  auto values() const { return std::tie(slope_deg, heading_deg); }
  // The plane's frame in the world (w, x, y, z): a rotation about the horizontal axis across the
  // heading.
  std::array<double, 4> rotation() const;
  bool operator==(const Slope&) const = default;
};

struct Rough {
  static constexpr std::string_view kName = "rough";
  static constexpr std::string_view kExample = "rough:0.01";  // for messages
  static constexpr std::array<TerrainParam, 2> kParams{{
      {"height_m", "HEIGHT_M", "the bump height", "m", kBumpLimits, std::nullopt},
      {"seed", "SEED", "the seed", "", std::nullopt, 1.0},
  }};
  static constexpr bool kBounded = true;
  static constexpr bool kOwnGround = false;
  double height_m = 0.0;
  std::uint64_t seed = 1;
  auto values() { return std::tie(height_m, seed); }
  auto values() const { return std::tie(height_m, seed); }
  double rise() const { return height_m; }
  // kTerrainSide / kRoughCell + 1 samples a side, row-major (rows along y), each in 0..1 of the
  // bump height, the lowest 0 and the highest 1 (so MuJoCo, which scales a heightfield file to
  // 0..1, keeps it as it is), drawn from the seed.
  std::vector<float> heightfield_samples() const;
  bool operator==(const Rough&) const = default;
};

struct Steps {
  static constexpr std::string_view kName = "steps";
  static constexpr std::string_view kExample = "steps:0.02:0.2";  // for messages
  static constexpr std::array<TerrainParam, 2> kParams{{
      {"height_m", "HEIGHT_M", "the step height", "m", kBumpLimits, std::nullopt},
      {"depth_m", "DEPTH_M", "the step depth", "m", kStepDepthLimits, std::nullopt},
  }};
  static constexpr bool kBounded = true;
  static constexpr bool kOwnGround = true;
  double height_m = 0.0;
  double depth_m = 0.0;
  auto values() { return std::tie(height_m, depth_m); }
  auto values() const { return std::tie(height_m, depth_m); }
  // Ahead of and behind the start: up for depth_m, down for depth_m, ..., to the terrain's edge.
  std::vector<TerrainBox> boxes() const;
  bool operator==(const Steps&) const = default;
};

using TerrainKind = std::variant<Flat, Slope, Rough, Steps>;

struct Terrain {
  TerrainKind kind = Flat{};
  bool operator==(const Terrain&) const = default;
};

// Throws OptionError (key "slope_deg", "height_m", ...) for a value outside its range.
void validate(const Terrain& terrain);

// Reads a terrain spec; throws BadInput (one line, no flag name) naming what is wrong.
Terrain parse_terrain(std::string_view text);
// The spec parse_terrain reads back: "flat", "slope:5:0", "rough:0.01:1", "steps:0.02:0.2".
std::string terrain_text(const Terrain& terrain);
// The kind's name: "flat", "slope", ...
std::string_view terrain_name(const Terrain& terrain);
// Whether the terrain is the flat plane of the paper's experiments.
bool is_flat(const Terrain& terrain);

// Whether the terrain covers only kTerrainSide around the start (rough, steps).
bool bounded(const Terrain& terrain);
// Whether a robot file's own ground stays under the terrain (flat, steps) rather than giving way
// to the terrain's (a slope's plane, rough ground's heightfield).
bool keeps_own_ground(const Terrain& terrain);
// Whether the ground is tilted (a slope, even of 0 deg): its plane and the walls carry
// ground_rotation.
bool tilted(const Terrain& terrain);
// How high the ground rises above z = 0 where the robot starts (rough ground's highest bump).
double rise(const Terrain& terrain);
// The heightfield the ground is (rough), none for a plane.
std::optional<std::vector<float>> heightfield_samples(const Terrain& terrain);
// The heightfield's samples per side.
int heightfield_samples_per_side();
// The boxes standing on the ground (steps).
std::vector<TerrainBox> terrain_boxes(const Terrain& terrain);

// The ground's frame in the world as a rotation quaternion (w, x, y, z): a slope rises slope_deg
// towards heading_deg, so it is a rotation about the horizontal axis across the heading; the
// identity for every other terrain.
std::array<double, 4> ground_rotation(const Terrain& terrain);
// Rotates a vector by a quaternion (w, x, y, z).
std::array<double, 3> rotate(const std::array<double, 4>& q, const std::array<double, 3>& v);
// A world point in the ground's frame: x and y along its surface, z along its normal.
std::array<double, 3> to_ground_frame(const Terrain& terrain, const std::array<double, 3>& p);

}  // namespace multicpg::robot
