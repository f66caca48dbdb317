// Reading a robot file (robot/robot_file.h; docs/robots.md "Your robot: robot files").
#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "robot/robot_file.h"

namespace multicpg::sim {

// Most bytes a robot file may have: a leg map of eight legs is about 3 kB.
inline constexpr std::uintmax_t kMaxRobotFileBytes = 1 << 20;
// Most bytes of its MJCF: the built-in robots' are about 30 kB.
inline constexpr std::uintmax_t kMaxModelBytes = 16 << 20;

// The robot file at `path`, its model read and checked: it compiles in MuJoCo and holds every
// name the leg map gives (make_sim_model). Throws BadInput, one line "FILE: KEY: what is wrong"
// for a missing or unknown key, a value of the wrong type, a leg count without a layout (4, 6 or
// 8), legs out of order, a name the model lacks, a joint without range, a model MuJoCo refuses
// (with MuJoCo's message).
robot::RobotFile load_robot_file(const std::filesystem::path& path);

// Whether geom `g` of `m` is a ground plane: a plane of the world body (a robot file's ground).
bool is_ground_plane(const mjModel* m, int g);

// True when the --robot text names a robot file rather than a built-in robot.
bool is_robot_file(const std::string& robot);

}  // namespace multicpg::sim
