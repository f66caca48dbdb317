// The landscape dataset (docs/learning.md "The landscape dataset"): for every leg-loss scenario
// of a robot, every combination of the working legs' periods with what it measured over its
// windows (periods alone, no steering), as experiments/landscape.h walks them. The learners'
// ground truth: the benchmark replays learners against it (learning/benchmark.h) and the
// prior-based learner learns from the scenarios other than the one under test.
//
// On disk, two files side by side:
//   NAME.csv.gz  gzip of a CSV, one row per combination, grouped by scenario:
//     scenario,<leg>...,w1_yaw,w1_path,...,wN_yaw,wN_path,worst,holds
//   scenario "R1+R3" (failed legs, robot/leg_sets.h); each leg's period, "x" for a failed leg;
//   each window's yaw change and path angle in degrees (sim::WindowMeasure) to 0.001 deg; worst =
//   the largest |yaw| or |path| of the windows; holds = 1 when every window held
//   (sim::holds), decided before the values were rounded.
//   NAME.json    the manifest: robot, period set, windows, window steps, threshold, the simulation
//   options it was walked with, each scenario's count and share of holding combinations, and the
//   checksum of the CSV's text (common/checksum.h), so an edited or cut file is refused.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "learning/annealing.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// One combination of a scenario.
struct LandscapePoint {
  Periods periods;               // every leg; a failed leg's is kStartPeriod
  std::vector<double> yaw_deg;   // per window, + = left
  std::vector<double> path_deg;  // per window
  double worst_deg = 0.0;
  bool holds = false;
  // The error a window shows to a learner that judges yaw and path (robust mode) or only the
  // yaw (paper mode), as sim::WindowMeasure::worst_deg and the paper's |yaw change|.
  double window_error(std::size_t window, bool yaw_only) const;
};

struct ScenarioLandscape {
  std::vector<std::size_t> failed;  // sorted
  std::vector<LandscapePoint> points;
  // The index of a combination (its working legs' periods; a failed leg's period is ignored),
  // or nothing when it is not one of the points.
  std::optional<std::size_t> find(const Periods& periods) const;
  std::size_t holding() const;
  // The point that holds with the smallest worst deviation, else the smallest worst deviation.
  std::size_t best() const;
};

struct LandscapeDataset {
  robot::RobotKind robot = robot::RobotKind::hexapod;
  std::vector<int> period_set;
  int windows = 0;
  long window_steps = 0;
  double threshold_deg = 0.0;
  nlohmann::json sim;  // the simulation options the combinations were walked with (record)
  std::vector<ScenarioLandscape> scenarios;
  // The scenario with these failed legs (any order), or nothing.
  const ScenarioLandscape* find(std::vector<std::size_t> failed) const;
};

// Rounding of the stored angles: 0.001 deg, far below what a window can resolve (a robot
// standing still reads ~0.01 deg of noise in its yaw from contact chatter).
inline constexpr double kLandscapeAngleResolutionDeg = 1e-3;

// The repository's dataset of `robot` (data/landscapes/<robot>, built by
// examples/landscape-every-<robot>.toml).
std::filesystem::path repository_dataset(robot::RobotKind robot);

// Writes PATH.csv.gz and PATH.json (PATH without extension) atomically. Points of a scenario in
// any order are written as given.
void write_landscape_dataset(const LandscapeDataset& dataset, const std::filesystem::path& path);

// Reads a dataset written by write_landscape_dataset: `path` names either file or their common
// stem. Throws BadInput (one line naming the file) when a file is missing, not gzip, cut short,
// edited (checksum), or does not match its manifest.
LandscapeDataset read_landscape_dataset(const std::filesystem::path& path);

}  // namespace multicpg::learning
