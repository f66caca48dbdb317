// The ground the robot walks on (paper §6: rough terrain as the next step; docs/faults.md):
//
//   flat                        the plane of the paper's experiments
//   slope:DEG[:HEADING_DEG]     a plane rising DEG (0..30) towards HEADING (0 = +x, the way the
//                               robot starts walking: uphill; 180 = downhill)
//   rough:HEIGHT_M[:SEED]       a heightfield of random bumps up to HEIGHT (0.001..0.05 m) on a
//   grid
//                               of kRoughCell, seeded (default 1)
//   steps:HEIGHT_M:DEPTH_M      past kStepsStart ahead of and behind the start, the floor steps up
//                               HEIGHT (0.001..0.05 m) for DEPTH (0.05..1 m), down for DEPTH, and
//                               so on, full width
//
// Rough ground and steps cover a square of kTerrainSide around the start; a robot that walks off
// it has left the terrain it was asked to walk on (sim::sim_step fails). The tunnel's walls stand
// on the terrain. Deviations are measured in the horizontal plane whatever the ground.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/limits.h"

namespace multicpg::robot {

enum class TerrainKind { flat, slope, rough, steps };

struct Terrain {
  TerrainKind kind = TerrainKind::flat;
  double slope_deg = 0.0;    // slope
  double heading_deg = 0.0;  // slope: the uphill direction, + = left of +x
  double height_m = 0.0;     // rough, steps
  double depth_m = 0.0;      // steps
  std::uint64_t seed = 1;    // rough
  bool operator==(const Terrain&) const = default;
};

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

// Throws OptionError (key "slope_deg", "height_m", ...) for a value outside its range.
void validate(const Terrain& terrain);

// Reads a terrain spec; throws BadInput (one line, no flag name) naming what is wrong.
Terrain parse_terrain(std::string_view text);
// The spec parse_terrain reads back: "flat", "slope:5:0", "rough:0.01:1", "steps:0.02:0.2".
std::string terrain_text(const Terrain& terrain);

// Whether the terrain covers only kTerrainSide around the start (rough, steps).
bool bounded(const Terrain& terrain);

// The ground's frame in the world as a rotation quaternion (w, x, y, z): a slope rises slope_deg
// towards heading_deg, so it is a rotation about the horizontal axis across the heading; the
// identity for every other terrain.
std::array<double, 4> ground_rotation(const Terrain& terrain);
// Rotates a vector by a quaternion (w, x, y, z).
std::array<double, 3> rotate(const std::array<double, 4>& q, const std::array<double, 3>& v);
// A world point in the ground's frame: x and y along its surface, z along its normal.
std::array<double, 3> to_ground_frame(const Terrain& terrain, const std::array<double, 3>& p);

// Rough ground's heightfield: kTerrainSide / kRoughCell + 1 samples a side, row-major (rows along
// y), each in 0..1 of the bump height, the lowest 0 and the highest 1 (so MuJoCo, which scales a
// heightfield file to 0..1, keeps it as it is), drawn from the terrain's seed.
std::vector<float> rough_samples(const Terrain& terrain);
int rough_samples_per_side();

}  // namespace multicpg::robot
