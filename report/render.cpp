#include "report/render.h"

#include <algorithm>
#include <cstring>
#include <mutex>

#include "common/errors.h"
#include "sim/mujoco_guard.h"

namespace multicpg::report {
namespace {

// Scene capacity: a hexapod has about 60 geoms; contact points and decorations add some.
constexpr int kMaxSceneGeoms = 2000;
// No multisample anti-aliasing (MuJoCo's default is 4 samples): on Mesa's llvmpipe, the only GL
// on a machine without a GPU, it made a 640x480 frame 2-3x slower, and the frames look the same
// after H.264 (docs/benchmarks.md, ## Rendering).
constexpr int kOffscreenSamples = 0;
// Shadow map side in texels (MuJoCo's default is 4096): 1024 draws the same shadows at 640x480
// for 40 % less CPU per frame on llvmpipe (docs/benchmarks.md).
constexpr int kShadowMapSize = 1024;
// Several films render at once, each on its own thread; MuJoCo's GL function loading in
// mjr_makeContext is process-wide, so contexts are made and freed one at a time.
std::mutex& context_mutex() {
  static std::mutex m;
  return m;
}

void aim_camera(const mjModel* m, const mjData* d, const CameraSpec& spec, mjvCamera& camera,
                int& tracked_body) {
  camera.distance = spec.distance;
  camera.azimuth = spec.azimuth;
  camera.elevation = spec.elevation;
  const int body = report::tracked_body(m, spec);
  if (body < 0) {
    camera.type = mjCAMERA_FREE;
    std::copy(spec.lookat.begin(), spec.lookat.end(), camera.lookat);
    tracked_body = -1;
    return;
  }
  camera.type = mjCAMERA_TRACKING;
  camera.trackbodyid = body;
  // MuJoCo's tracking camera moves a fifth of the way to the target each frame; start on target.
  if (tracked_body != body) std::copy_n(d->subtree_com + 3 * body, 3, camera.lookat);
  tracked_body = body;
}

const mjModel* require_model(const mjModel* model) {
  if (model == nullptr) throw BadInput("renderer: no model");
  return model;
}

// Checked before the GL context is made (its buffer has the frame's size).
int frame_side(const char* key, int side) {
  require_in(key, side, kFrameSideLimits);
  return side;
}

}  // namespace

Renderer::Renderer(const mjModel* model, int width, int height)
    : model_(require_model(model)),
      width_(frame_side("width", width)),
      height_(frame_side("height", height)),
      gl_(width, height) {
  // MuJoCo ends the process for a buffer larger than OpenGL allows: ask OpenGL first.
  const int largest = gl_.max_framebuffer_side();
  if (width > largest || height > largest) {
    throw BadInput("a " + std::to_string(width) + "x" + std::to_string(height) +
                   " frame is larger than this OpenGL renders (" + std::to_string(largest) +
                   " px a side)");
  }
  mjv_defaultScene(&scene_);
  mjr_defaultContext(&context_);
  mjv_defaultOption(&option_);
  mjv_defaultCamera(&camera_);
  // The offscreen buffer size and quality come from the model: set them on a copy.
  mjModel* sized = nullptr;
  try {
    sim::mujoco_call([&] { mjv_makeScene(model, &scene_, kMaxSceneGeoms); });
    sim::mujoco_call([&] { sized = mj_copyModel(nullptr, model); });
    sized->vis.global.offwidth = std::max(width, model->vis.global.offwidth);
    sized->vis.global.offheight = std::max(height, model->vis.global.offheight);
    sized->vis.quality.offsamples = kOffscreenSamples;
    sized->vis.quality.shadowsize = kShadowMapSize;
    {
      const std::lock_guard lock(context_mutex());
      sim::mujoco_call([&] { mjr_makeContext(sized, &context_, mjFONTSCALE_100); });
    }
    mj_deleteModel(sized);
    sized = nullptr;
    sim::mujoco_call([&] { mjr_setBuffer(mjFB_OFFSCREEN, &context_); });
  } catch (const RuntimeFailure&) {
    if (sized != nullptr) mj_deleteModel(sized);
    mjr_freeContext(&context_);
    mjv_freeScene(&scene_);
    throw;
  }
  if (context_.currentBuffer != mjFB_OFFSCREEN) {
    mjr_freeContext(&context_);
    mjv_freeScene(&scene_);
    throw RuntimeFailure("renderer: the OpenGL context has no offscreen framebuffer");
  }
}

Renderer::~Renderer() {
  gl_.make_current();
  const std::lock_guard lock(context_mutex());
  mjr_freeContext(&context_);
  mjv_freeScene(&scene_);
}

void paint(mjvScene& scene, const Colouring& colours) {
  if (colours.empty()) return;
  for (int i = 0; i < scene.ngeom; ++i) {
    mjvGeom& g = scene.geoms[i];
    if (g.objtype != mjOBJ_GEOM) continue;
    for (const GeomColour& c : colours) {
      if (c.geom == g.objid) std::copy(c.rgba.begin(), c.rgba.end(), g.rgba);
    }
  }
}

int tracked_body(const mjModel* m, const CameraSpec& spec) {
  if (spec.track_robot) {
    for (int j = 0; j < m->njnt; ++j) {
      if (m->jnt_type[j] == mjJNT_FREE) return m->jnt_bodyid[j];
    }
    throw BadInput("camera: the model has no free joint (the robot's trunk)");
  }
  if (spec.track_body.empty()) return -1;
  const int body = mj_name2id(m, mjOBJ_BODY, spec.track_body.c_str());
  if (body <= 0) throw BadInput("camera: the model has no body named '" + spec.track_body + "'");
  return body;
}

Image render_frame(Renderer& renderer, const mjModel* model, mjData* data, const CameraSpec& camera,
                   const Colouring& colours, const Overlay& overlay) {
  const mjModel* own = renderer.model_;
  const bool same_parts = model != nullptr && model->nbody == own->nbody &&
                          model->ngeom == own->ngeom && model->nmesh == own->nmesh &&
                          model->ntex == own->ntex && model->nmat == own->nmat;
  if (!same_parts) throw BadInput("render_frame: the model is not the renderer's model");
  if (data == nullptr) throw BadInput("render_frame: no data");
  renderer.gl_.make_current();
  aim_camera(model, data, camera, renderer.camera_, renderer.tracked_body_);
  mjv_updateScene(model, data, &renderer.option_, nullptr, &renderer.camera_, mjCAT_ALL,
                  &renderer.scene_);
  paint(renderer.scene_, colours);

  const mjrRect viewport{0, 0, renderer.width_, renderer.height_};
  sim::mujoco_call([&] {
    mjr_setBuffer(mjFB_OFFSCREEN, &renderer.context_);
    mjr_render(viewport, &renderer.scene_, &renderer.context_);
  });
  if (!overlay.titles.empty()) {
    const char* titles = overlay.titles.c_str();
    const char* values = overlay.values.c_str();
    sim::mujoco_call([&] {
      mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, titles, values, &renderer.context_);
    });
  }

  Image image{renderer.width_, renderer.height_, {}};
  const std::size_t row = 3 * static_cast<std::size_t>(image.width);
  std::vector<unsigned char> bottom_up(row * static_cast<std::size_t>(image.height));
  unsigned char* pixels = bottom_up.data();
  sim::mujoco_call([&] { mjr_readPixels(pixels, nullptr, viewport, &renderer.context_); });
  // OpenGL rows run bottom to top; images run top to bottom.
  image.rgb.resize(bottom_up.size());
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(image.rgb.data() + row * static_cast<std::size_t>(y),
                bottom_up.data() + row * static_cast<std::size_t>(image.height - 1 - y), row);
  }
  return image;
}

}  // namespace multicpg::report
