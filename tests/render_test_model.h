// A small MuJoCo model for rendering tests and benchmarks: a floor, a blue trunk on a free
// joint and one leg named with the R1_ prefix, as the robot MJCF names legs (robot/mjcf.h).
#pragma once

#include <mujoco/mujoco.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/render.h"

namespace multicpg::testing {

inline constexpr const char* kRenderTestModel = R"(
<mujoco model="render-test">
  <asset>
    <texture name="grid" type="2d" builtin="checker" rgb1=".25 .25 .25" rgb2=".35 .35 .35"
             width="256" height="256"/>
    <material name="grid" texture="grid" texrepeat="8 8"/>
  </asset>
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1" directional="true"/>
    <geom name="floor" type="plane" size="10 10 0.1" material="grid"/>
    <body name="trunk" pos="0 0 0.3">
      <freejoint/>
      <geom name="trunk_box" type="box" size="0.2 0.1 0.05" rgba="0.1 0.2 1 1"/>
      <body name="R1_leg" pos="0.2 -0.1 0">
        <geom name="shank" type="capsule" fromto="0 0 0 0.1 -0.15 -0.2" size="0.03"
              rgba="0.8 0.8 0.8 1"/>
      </body>
    </body>
  </worldbody>
</mujoco>)";

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

// The leg's shank in a fault's colour (red), as films draw a disabled leg.
inline std::vector<report::GeomColour> red_leg(const mjModel* m) {
  return {{mj_name2id(m, mjOBJ_GEOM, "shank"), {0.85F, 0.08F, 0.08F, 1.0F}}};
}

// MuJoCo 2.2 loads XML only from files, so the text goes through a virtual file system.
inline ModelPtr load_render_test_model(const char* xml = kRenderTestModel) {
  constexpr const char* kFile = "render-test.xml";
  constexpr int kErrorLength = 1000;
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  const int size = static_cast<int>(std::strlen(xml));
  if (mj_makeEmptyFileVFS(&vfs, kFile, size) != 0) throw std::runtime_error("VFS is full");
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, kFile)], xml, static_cast<std::size_t>(size));
  char error[kErrorLength] = "";
  mjModel* model = mj_loadXML(kFile, &vfs, error, kErrorLength);
  mj_deleteVFS(&vfs);
  if (model == nullptr) throw std::runtime_error(std::string("test model: ") + error);
  return ModelPtr(model);
}

}  // namespace multicpg::testing
