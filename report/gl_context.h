// An OpenGL context without a display, for MuJoCo's offscreen renderer: EGL (a GPU, or Mesa's
// llvmpipe) with OSMesa as the fallback, chosen once per process from MUJOCO_GL like MuJoCo's
// Python bindings do (egl | osmesa; unset: egl, then osmesa).
//
// The platform library is loaded at run time, not linked: MuJoCo's GL loader takes the first of
// eglGetProcAddress / OSMesaGetProcAddress it finds in the process, so only the platform in use
// may be globally visible. For the same reason the choice cannot change within a process.
#pragma once

#include <memory>
#include <string_view>

#include "common/enum_names.h"

namespace multicpg::report {

enum class GlBackend { egl, osmesa };
// Also MUJOCO_GL's values.
inline constexpr auto kGlBackendNames =
    enum_names<GlBackend>({{GlBackend::egl, "egl"}, {GlBackend::osmesa, "osmesa"}});

std::string_view to_string(GlBackend backend);

// One GL context of the process platform, current on the calling thread after construction.
class GlContext {
 public:
  GlContext(int width, int height);
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  ~GlContext();

  // Makes this context current on the calling thread (several renderers may coexist).
  void make_current();
  // The largest framebuffer side this context's OpenGL can render into (the smaller of its
  // largest renderbuffer and viewport), asked before MuJoCo makes its buffers: MuJoCo's answer to
  // a larger one is a fatal error.
  int max_framebuffer_side();
  GlBackend backend() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace multicpg::report
