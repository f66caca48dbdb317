// MuJoCo models from text: MJCF (or a URDF, through MuJoCo's own reader) compiled from memory, with
// the files it refers to beside it, and the owners of MuJoCo's models and data.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>
#include <vector>

#include "robot/mjcf.h"

namespace multicpg::sim {

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// Compiles MJCF text (through MuJoCo's in-memory file system). Throws RuntimeFailure if MuJoCo
// rejects it.
std::unique_ptr<mjModel, MjModelDeleter> compile_mjcf(
    const std::string& xml, const std::vector<robot::ModelFile>& files = {});

// The MJCF of a URDF, as MuJoCo's own loader reads it. Throws RuntimeFailure with MuJoCo's
// message if it refuses the URDF.
std::string urdf_as_mjcf(const std::string& urdf);

}  // namespace multicpg::sim
