// Headless pictures of a MuJoCo model: one renderer per model and frame size, a
// camera that follows the robot, and the disabled legs drawn in red as in the paper's figures.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/limits.h"
#include "report/gl_context.h"
#include "report/image.h"

namespace multicpg::report {

using Rgba = std::array<float, 4>;

// A geom drawn in a colour of its own (a fault's, report/fault_colours.h).
struct GeomColour {
  int geom = -1;
  Rgba rgba{};
};
using Colouring = std::vector<GeomColour>;

// Recolours the scene's geoms (call after mjv_updateScene).
void paint(mjvScene& scene, const Colouring& colours);

inline constexpr int kDefaultFrameWidth = 640;
inline constexpr int kDefaultFrameHeight = 480;
// Frame sides a user may ask for: a thumbnail to 4K's 4096 px, which every GL driver's
// offscreen buffer holds.
inline constexpr Limits<int> kFrameSideLimits{16, 4096};

// Where the camera looks from. It follows a body's subtree centre of mass smoothly (MuJoCo's
// tracking camera): the robot's trunk, or the body named; with neither it looks at `lookat`.
struct CameraSpec {
  bool track_robot = true;   // the trunk: the body of the model's free joint (any robot file's)
  std::string track_body;    // without track_robot: this body, if named
  double distance = 1.5;     // m
  double azimuth = 45.0;     // deg: 0 looks along +x (the walking direction), 90 along +y
  double elevation = -30.0;  // deg, negative = looking down
  std::array<double, 3> lookat{0.0, 0.0, 0.0};  // m, used without a track body
};

// Text drawn in the top-left corner: two columns, lines separated by '\n' (mjr_overlay).
struct Overlay {
  std::string titles;
  std::string values;
};

// The GL context, MuJoCo render context and scene for one model at one frame size.
class Renderer {
 public:
  // Throws BadInput for a null model or bad size, RuntimeFailure when no GL platform works.
  explicit Renderer(const mjModel* model, int width = kDefaultFrameWidth,
                    int height = kDefaultFrameHeight);
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  ~Renderer();

  int width() const { return width_; }
  int height() const { return height_; }
  GlBackend backend() const { return gl_.backend(); }

 private:
  friend Image render_frame(Renderer&, const mjModel*, mjData*, const CameraSpec&, const Colouring&,
                            const Overlay&);
  const mjModel* model_;
  int width_;
  int height_;
  GlContext gl_;
  mjvScene scene_;
  mjrContext context_;
  mjvOption option_;
  mjvCamera camera_;
  int tracked_body_ = -1;  // body the camera followed last frame, to start tracking without a swoop
};

// Renders the current state of `data` (after mj_forward or mj_step), the geoms of `colours` in
// their colours (report/fault_colours.h). `model` must be the renderer's model or a copy of it
// that a fault reshaped (the same bodies, geoms and visual assets: sim/fault_effects.h); another
// model or an unknown track body throws BadInput.
// The body a camera of `spec` follows in `m` (-1: none). Throws BadInput for a model without a
// free joint or without the body named.
int tracked_body(const mjModel* m, const CameraSpec& spec);

Image render_frame(Renderer& renderer, const mjModel* model, mjData* data, const CameraSpec& camera,
                   const Colouring& colours, const Overlay& overlay = {});

}  // namespace multicpg::report
