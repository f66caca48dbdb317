// A robot file in the simulation (robot/robot_file.h; docs/robots.md "Your robot: robot files"):
// read and checked against its model, and its SimModel: the file's model as written, with the
// motors, ground, terrain and walls its world adds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "robot/robot_file.h"
#include "sim/sim_model.h"

namespace multicpg::sim {

// Most bytes a robot file may have: a leg map of eight legs is about 3 kB.
inline constexpr std::uintmax_t kMaxRobotFileBytes = 1 << 20;
inline constexpr std::string_view kMaxRobotFileText = "1 MiB";
// Most bytes of its MJCF: the built-in robots' are about 30 kB.
inline constexpr std::uintmax_t kMaxModelBytes = 16 << 20;
inline constexpr std::string_view kMaxModelText = "16 MiB";

// The robot file at `path`, its model read and checked: it compiles in MuJoCo and holds every
// name the leg map gives (make_sim_model). Throws BadInput, one line "FILE: KEY: what is wrong"
// for a missing or unknown key, a value of the wrong type, a leg count without a layout (4, 6 or
// 8), legs out of order, a name the model lacks, a joint without range, a model MuJoCo refuses
// (with MuJoCo's message).
robot::RobotFile load_robot_file(const std::filesystem::path& path);

// The robot of a robot file (load_robot_file) with its layout's controller,
// servos and fault geometry. Its model is walked as written on its flat ground or options'
// terrain, inside the tunnel's walls with options.scene.tunnel, at options' physics step. Throws
// OptionError ("scene.terrain") for other ground under a model with contact pairs, and with the
// file's key ("legs[0].TC.joint", "yaw", ...) for a name of the
// leg map that its model lacks; RuntimeFailure if MuJoCo rejects the model.
SimModel make_sim_model(const robot::RobotFile& file, const SimOptions& options = {});

// True when the --robot text names a robot file rather than a built-in robot.
bool is_robot_file(const std::string& robot);

}  // namespace multicpg::sim
