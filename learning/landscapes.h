// The landscape dataset (docs/learning.md "The landscape dataset"): for every leg-loss scenario
// of a robot, every combination of the working legs' periods with what it measured over its
// windows, walked one of two ways (experiments/landscape.h): periods alone, every window; or as
// the default robust run walks a trial, with the steering reflex, until the first window over the
// threshold. The learners' ground truth: the benchmark replays learners against it
// (learning/benchmark.h) and the prior-based learner learns from the scenarios other than the one
// under test.
//
// On disk, two files side by side:
//   NAME.csv.gz  gzip of a CSV, one row per combination, grouped by scenario:
//     scenario,<leg>...,w1_yaw,w1_path[,w1_effort],...,wN_yaw,wN_path[,wN_effort],worst,holds
//   scenario "R1+R3" (failed legs, robot/leg_sets.h); each leg's period, "x" for a failed leg;
//   each window's yaw change and path angle in degrees (body::WindowMeasure) to 0.001 deg and, with
//   the reflex, its effort (mean swing cut, 0..1) to 0.0001; a window not walked (after the first
//   over the threshold, reflex datasets only) has empty cells; worst = the largest window error
//   by the dataset's criterion (learning/criterion.h); holds = 1 when all N windows were walked
//   and held (body::holds), decided before the values were rounded.
//   NAME.json    the manifest: format and version, robot, period set, windows, window steps,
//   threshold, the simulation options it was walked with, how it was walked ("steering": "off" or
//   "reflex" with the reflex's parameters), each scenario's count and share of holding
//   combinations (with the reflex, also the windows walked before its combinations), and the
//   checksum of the CSV's text (common/checksum.h), so an edited or cut file is refused.
//   Version 1 manifests (before the reflex) read as "steering": "off".
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "body/deviation.h"
#include "learning/annealing.h"
#include "learning/criterion.h"
#include "learning/steering.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// One combination of a scenario.
struct LandscapePoint {
  Periods periods;  // every leg; a failed leg's is kStartPeriod
  // Each window walked, in order: yaw change, path angle and the reflex's effort (0 without it).
  std::vector<body::WindowMeasure> windows;
  double worst_deg = 0.0;  // the largest error of its windows by the dataset's criterion
  bool holds = false;      // every one of the dataset's windows walked and under the threshold
};

struct ScenarioLandscape {
  std::vector<std::size_t> failed;  // sorted
  std::vector<LandscapePoint> points;
  // With the reflex: the windows walked with every leg at 4 before the combinations (the last one
  // deviated and started learning, or every one held: the reflex alone holds).
  std::vector<body::WindowMeasure> start_windows;
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
  // The robot file whose body walked them (its record: path, name, checksums); null: the
  // built-in robot of `robot`'s layout. A record only: a prior learns from the dataset on any
  // body of that layout (docs/learning.md "The prior on other bodies").
  nlohmann::json robot_file;
  // How it was walked: empty = periods alone, every window; else with the steering reflex of
  // these parameters, each combination until its first window over the threshold.
  std::optional<SteeringParams> reflex;
  long monitor_windows = 0;  // with the reflex: the start walk's limit (CompensationOptions)
  std::vector<ScenarioLandscape> scenarios;
  // The scenario with these failed legs (any order), or nothing.
  const ScenarioLandscape* find(std::vector<std::size_t> failed) const;
  // What a window's error is made of: robust mode's, with the reflex's effort when it steered.
  Criterion criterion() const;
  // "periods alone" or "the steering reflex": for messages and records.
  std::string walked() const;
};

// Rounding of the stored angles: 0.001 deg, far below what a window can resolve (a robot
// standing still reads ~0.01 deg of noise in its yaw from contact chatter); and of the reflex's
// effort, a share of a side's swing: 0.0001 (0.001 deg of E at the default scale).
inline constexpr double kLandscapeAngleResolutionDeg = 1e-3;
inline constexpr double kLandscapeEffortResolution = 1e-4;

// Where the repository's datasets are looked for, in this order (docs/python.md "Datasets"),
// each a directory holding landscapes/: $MULTICPG_DATA when set; the data installed beside the
// running code (the Python package's data/, which setup.py ships, or <prefix>/share/multicpg of
// an installed program); the source tree's data/, for the program built in place.
inline constexpr const char* kDataEnv = "MULTICPG_DATA";
std::vector<std::filesystem::path> dataset_search_path();

// The repository's dataset of `robot` walked that way (landscapes/<robot> for periods alone,
// <robot>-reflex with the reflex; built by examples/landscape-every-<robot>*.toml): the first one
// on dataset_search_path() with its manifest. Throws BadInput naming every place it looked when
// none has it.
std::filesystem::path repository_dataset(robot::RobotKind robot, bool reflex);

// Writes PATH.csv.gz and PATH.json (PATH without extension) atomically. Points of a scenario in
// any order are written as given.
void write_landscape_dataset(const LandscapeDataset& dataset, const std::filesystem::path& path);

// Reads a dataset written by write_landscape_dataset: `path` names either file or their common
// stem. Throws BadInput (one line naming the file, and the line or field) when a file is missing,
// no regular file, not gzip, cut short, edited (checksum), or its content is not what the writer
// writes: a field of the wrong type or out of its range, a period outside the period set, a cell
// that is not a number, a combination missing or repeated, a window not walked where it should
// have been, holds or worst that its windows contradict.
LandscapeDataset read_landscape_dataset(const std::filesystem::path& path);

// The bytes of a dataset's two files, read as read_landscape_dataset reads them (the same size
// limits); throws BadInput naming a file it cannot read.
struct LandscapeFiles {
  std::string manifest;  // the manifest's JSON text
  std::string csv_gzip;  // the gzip CSV
};
LandscapeFiles read_landscape_files(const std::filesystem::path& path);

// read_landscape_dataset of files already read; `path` names them in messages.
LandscapeDataset parse_landscape_dataset(const std::filesystem::path& path,
                                         const LandscapeFiles& files);

}  // namespace multicpg::learning
