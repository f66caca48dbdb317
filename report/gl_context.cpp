#include "report/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.h"

namespace multicpg::report {
namespace {

constexpr const char* kBackendEnv = "MUJOCO_GL";
constexpr const char* kEglLibrary = "libEGL.so.1";
// Debian 12's libosmesa6 ships libOSMesa.so.8; older Mesa used .so.6.
constexpr std::array<const char*, 2> kOsMesaLibraries{"libOSMesa.so.8", "libOSMesa.so.6"};
constexpr int kColourBits = 8;
constexpr int kDepthBits = 24;
constexpr int kStencilBits = 8;
constexpr int kMaxEglDevices = 16;
constexpr int kBytesPerOsMesaPixel = 4;  // OSMESA_RGBA, GL_UNSIGNED_BYTE

template <class F>
F symbol(void* library, const char* name) {
  return reinterpret_cast<F>(::dlsym(library, name));
}

std::string hex(unsigned value) {
  std::ostringstream s;
  s << "0x" << std::hex << value;
  return s.str();
}

struct Egl {
  PFNEGLGETPROCADDRESSPROC get_proc_address = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLTERMINATEPROC terminate = nullptr;
  PFNEGLCHOOSECONFIGPROC choose_config = nullptr;
  PFNEGLBINDAPIPROC bind_api = nullptr;
  PFNEGLCREATECONTEXTPROC create_context = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
  PFNEGLCREATEPBUFFERSURFACEPROC create_pbuffer = nullptr;
  PFNEGLDESTROYSURFACEPROC destroy_surface = nullptr;
  PFNEGLMAKECURRENTPROC make_current = nullptr;
  PFNEGLGETERRORPROC get_error = nullptr;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
};

using OsMesaCreate = OSMesaContext (*)(GLenum, GLint, GLint, GLint, OSMesaContext);
using OsMesaMakeCurrent = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using OsMesaDestroy = void (*)(OSMesaContext);
using OsMesaGetProcAddress = void* (*)(const char*);
using GlGetIntegerv = void (*)(GLenum, GLint*);
// GL 3.0 / ARB_framebuffer_object (GL/glext.h, which gl.h does not include).
constexpr GLenum kGlMaxRenderbufferSize = 0x84E8;

struct OsMesa {
  OsMesaCreate create = nullptr;
  OsMesaMakeCurrent make_current = nullptr;
  OsMesaDestroy destroy = nullptr;
  OsMesaGetProcAddress get_proc_address = nullptr;
};

struct Platform {
  GlBackend backend = GlBackend::egl;
  Egl egl;
  OsMesa osmesa;
};

// Picks a config on `display` that can render RGBA with depth and stencil into a pbuffer.
bool init_display(Egl& egl, EGLDisplay display) {
  if (display == EGL_NO_DISPLAY) return false;
  EGLint major = 0;
  EGLint minor = 0;
  if (egl.initialize(display, &major, &minor) != EGL_TRUE) return false;
  const std::array<EGLint, 17> attributes{
      EGL_RED_SIZE,     kColourBits,    EGL_GREEN_SIZE,      kColourBits,    EGL_BLUE_SIZE,
      kColourBits,      EGL_ALPHA_SIZE, kColourBits,         EGL_DEPTH_SIZE, kDepthBits,
      EGL_STENCIL_SIZE, kStencilBits,   EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
      EGL_PBUFFER_BIT,  EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (egl.choose_config(display, attributes.data(), &config, 1, &count) != EGL_TRUE || count < 1) {
    egl.terminate(display);
    return false;
  }
  egl.display = display;
  egl.config = config;
  return true;
}

// Loads libEGL privately and finds a display: Mesa's surfaceless platform (llvmpipe without a
// GPU), else the first EGL device that works (NVIDIA). Throws RuntimeFailure saying why not.
Egl load_egl() {
  void* library = ::dlopen(kEglLibrary, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) throw RuntimeFailure(std::string("cannot load ") + kEglLibrary);
  Egl egl;
  egl.get_proc_address = symbol<PFNEGLGETPROCADDRESSPROC>(library, "eglGetProcAddress");
  egl.initialize = symbol<PFNEGLINITIALIZEPROC>(library, "eglInitialize");
  egl.terminate = symbol<PFNEGLTERMINATEPROC>(library, "eglTerminate");
  egl.choose_config = symbol<PFNEGLCHOOSECONFIGPROC>(library, "eglChooseConfig");
  egl.bind_api = symbol<PFNEGLBINDAPIPROC>(library, "eglBindAPI");
  egl.create_context = symbol<PFNEGLCREATECONTEXTPROC>(library, "eglCreateContext");
  egl.destroy_context = symbol<PFNEGLDESTROYCONTEXTPROC>(library, "eglDestroyContext");
  egl.create_pbuffer = symbol<PFNEGLCREATEPBUFFERSURFACEPROC>(library, "eglCreatePbufferSurface");
  egl.destroy_surface = symbol<PFNEGLDESTROYSURFACEPROC>(library, "eglDestroySurface");
  egl.make_current = symbol<PFNEGLMAKECURRENTPROC>(library, "eglMakeCurrent");
  egl.get_error = symbol<PFNEGLGETERRORPROC>(library, "eglGetError");
  if (egl.get_proc_address == nullptr || egl.initialize == nullptr || egl.terminate == nullptr ||
      egl.choose_config == nullptr || egl.bind_api == nullptr || egl.create_context == nullptr ||
      egl.destroy_context == nullptr || egl.create_pbuffer == nullptr ||
      egl.destroy_surface == nullptr || egl.make_current == nullptr || egl.get_error == nullptr) {
    throw RuntimeFailure(std::string(kEglLibrary) + " lacks EGL 1.4 entry points");
  }
  egl.get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      egl.get_proc_address("eglGetPlatformDisplayEXT"));
  egl.query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl.get_proc_address("eglQueryDevicesEXT"));
  if (egl.get_platform_display == nullptr) {
    throw RuntimeFailure("EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
  }
  if (init_display(egl, egl.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                                 nullptr))) {
    return egl;
  }
  if (egl.query_devices != nullptr) {
    std::array<EGLDeviceEXT, kMaxEglDevices> devices{};
    EGLint count = 0;
    if (egl.query_devices(kMaxEglDevices, devices.data(), &count) == EGL_TRUE) {
      for (EGLint i = 0; i < count; ++i) {
        if (init_display(egl,
                         egl.get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr))) {
          return egl;
        }
      }
    }
  }
  throw RuntimeFailure("EGL: no surfaceless or device display could be initialised (error " +
                       hex(static_cast<unsigned>(egl.get_error())) + ")");
}

OsMesa load_osmesa() {
  void* library = nullptr;
  for (const char* name : kOsMesaLibraries) {
    // Global, so MuJoCo's loader finds OSMesaGetProcAddress.
    library = ::dlopen(name, RTLD_NOW | RTLD_GLOBAL);
    if (library != nullptr) break;
  }
  if (library == nullptr) throw RuntimeFailure("cannot load libOSMesa (install libosmesa6)");
  OsMesa osmesa;
  osmesa.create = symbol<OsMesaCreate>(library, "OSMesaCreateContextExt");
  osmesa.make_current = symbol<OsMesaMakeCurrent>(library, "OSMesaMakeCurrent");
  osmesa.destroy = symbol<OsMesaDestroy>(library, "OSMesaDestroyContext");
  osmesa.get_proc_address = symbol<OsMesaGetProcAddress>(library, "OSMesaGetProcAddress");
  if (osmesa.create == nullptr || osmesa.make_current == nullptr || osmesa.destroy == nullptr ||
      osmesa.get_proc_address == nullptr) {
    throw RuntimeFailure(
        "libOSMesa lacks OSMesaCreateContextExt/MakeCurrent/DestroyContext/GetProcAddress");
  }
  return osmesa;
}

// EGL is probed with its symbols private and published only once it works, so a failed probe
// cannot divert MuJoCo's loader away from OSMesa.
bool try_egl(Platform& platform, std::string& why) {
  try {
    platform.egl = load_egl();
  } catch (const RuntimeFailure& e) {
    why = e.what();
    return false;
  }
  if (::dlopen(kEglLibrary, RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL) == nullptr) {
    why = std::string("cannot publish ") + kEglLibrary + " symbols";
    return false;
  }
  platform.backend = GlBackend::egl;
  return true;
}

bool try_osmesa(Platform& platform, std::string& why) {
  try {
    platform.osmesa = load_osmesa();
  } catch (const RuntimeFailure& e) {
    why = e.what();
    return false;
  }
  platform.backend = GlBackend::osmesa;
  return true;
}

Platform load_platform() {
  const char* env = std::getenv(kBackendEnv);
  const std::string choice = env == nullptr ? "" : env;
  Platform platform;
  std::string egl_why;
  std::string osmesa_why;
  const std::optional<GlBackend> chosen = kGlBackendNames.find(choice);
  if (chosen == GlBackend::egl) {
    if (!try_egl(platform, egl_why)) throw RuntimeFailure("MUJOCO_GL=egl: " + egl_why);
  } else if (chosen == GlBackend::osmesa) {
    if (!try_osmesa(platform, osmesa_why)) throw RuntimeFailure("MUJOCO_GL=osmesa: " + osmesa_why);
  } else if (choice.empty()) {
    if (!try_egl(platform, egl_why) && !try_osmesa(platform, osmesa_why)) {
      throw RuntimeFailure("no headless OpenGL: " + egl_why + "; " + osmesa_why);
    }
  } else {
    throw BadInput("MUJOCO_GL='" + choice + "' is not supported for headless rendering; use " +
                   kGlBackendNames.list(" or "));
  }
  return platform;
}

const Platform& platform() {
  // A throwing initialiser is retried on the next call.
  static const Platform loaded = load_platform();
  return loaded;
}

}  // namespace

std::string_view to_string(GlBackend backend) {
  return kGlBackendNames.name(backend);
}

struct GlContext::Impl {
  GlBackend backend;
  EGLContext egl_context = EGL_NO_CONTEXT;
  EGLSurface egl_surface = EGL_NO_SURFACE;
  OSMesaContext osmesa_context = nullptr;
  std::vector<unsigned char> osmesa_buffer;  // OSMesa's default framebuffer
  int width;
  int height;
};

GlContext::GlContext(int width, int height) : impl_(std::make_unique<Impl>()) {
  if (width <= 0 || height <= 0) {
    throw BadInput("render size must be positive, got " + std::to_string(width) + "x" +
                   std::to_string(height));
  }
  const Platform& p = platform();
  impl_->backend = p.backend;
  impl_->width = width;
  impl_->height = height;
  if (p.backend == GlBackend::egl) {
    const Egl& egl = p.egl;
    if (egl.bind_api(EGL_OPENGL_API) != EGL_TRUE) {
      throw RuntimeFailure("EGL: desktop OpenGL is not available (eglBindAPI failed)");
    }
    const std::array<EGLint, 5> size{EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
    impl_->egl_surface = egl.create_pbuffer(egl.display, egl.config, size.data());
    if (impl_->egl_surface == EGL_NO_SURFACE) {
      throw RuntimeFailure("EGL: cannot create a pbuffer (error " +
                           hex(static_cast<unsigned>(egl.get_error())) + ")");
    }
    impl_->egl_context = egl.create_context(egl.display, egl.config, EGL_NO_CONTEXT, nullptr);
    if (impl_->egl_context == EGL_NO_CONTEXT) {
      egl.destroy_surface(egl.display, impl_->egl_surface);
      throw RuntimeFailure("EGL: cannot create an OpenGL context (error " +
                           hex(static_cast<unsigned>(egl.get_error())) + ")");
    }
  } else {
    impl_->osmesa_context = p.osmesa.create(OSMESA_RGBA, kDepthBits, kStencilBits, 0, nullptr);
    if (impl_->osmesa_context == nullptr) throw RuntimeFailure("OSMesa: cannot create a context");
    impl_->osmesa_buffer.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                                kBytesPerOsMesaPixel);
  }
  make_current();
}

GlContext::~GlContext() {
  const Platform& p = platform();
  if (impl_->backend == GlBackend::egl) {
    p.egl.make_current(p.egl.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    p.egl.destroy_context(p.egl.display, impl_->egl_context);
    p.egl.destroy_surface(p.egl.display, impl_->egl_surface);
  } else {
    // Unbound first, as for EGL, so the context is not current while it is destroyed.
    p.osmesa.make_current(nullptr, nullptr, 0, 0, 0);
    p.osmesa.destroy(impl_->osmesa_context);
  }
}

void GlContext::make_current() {
  const Platform& p = platform();
  if (impl_->backend == GlBackend::egl) {
    if (p.egl.make_current(p.egl.display, impl_->egl_surface, impl_->egl_surface,
                           impl_->egl_context) != EGL_TRUE) {
      throw RuntimeFailure("EGL: cannot make the context current (error " +
                           hex(static_cast<unsigned>(p.egl.get_error())) + ")");
    }
  } else if (p.osmesa.make_current(impl_->osmesa_context, impl_->osmesa_buffer.data(),
                                   GL_UNSIGNED_BYTE, impl_->width, impl_->height) != GL_TRUE) {
    throw RuntimeFailure("OSMesa: cannot make the context current");
  }
}

int GlContext::max_framebuffer_side() {
  make_current();
  const Platform& p = platform();
  const auto get = reinterpret_cast<GlGetIntegerv>(
      impl_->backend == GlBackend::egl
          ? reinterpret_cast<void*>(p.egl.get_proc_address("glGetIntegerv"))
          : p.osmesa.get_proc_address("glGetIntegerv"));
  if (get == nullptr) throw RuntimeFailure("OpenGL: no glGetIntegerv");
  GLint renderbuffer = 0;
  std::array<GLint, 2> viewport{};
  get(kGlMaxRenderbufferSize, &renderbuffer);
  get(GL_MAX_VIEWPORT_DIMS, viewport.data());
  return std::min({renderbuffer, viewport[0], viewport[1]});
}

GlBackend GlContext::backend() const {
  return impl_->backend;
}

}  // namespace multicpg::report
