#include "report/viewer.h"

#define GLFW_INCLUDE_NONE  // MuJoCo draws; the viewer makes no GL calls of its own
#include <GLFW/glfw3.h>
#include <dlfcn.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

#include "common/errors.h"
#include "report/fault_colours.h"
#include "report/render.h"
#include "robot/leg_sets.h"
#include "sim/walk.h"

namespace multicpg::report {
namespace {

constexpr int kWindowWidth = 1024;
constexpr int kWindowHeight = 768;
// Scene capacity, as the headless renderer: a robot has under 100 geoms, contacts add some.
constexpr int kMaxSceneGeoms = 2000;
// A scroll click zooms like a drag over 5 % of the window height, as in MuJoCo's samples.
constexpr double kScrollZoom = 0.05;
constexpr const char* kGlLibrary = "libGL.so.1";
constexpr const char* kHeadlessHint =
    "use `multicpg render --out FILE.mp4` to make a video headless";

// GLFW reports errors through a callback; the last one goes into our one-line message instead
// of being printed.
std::string glfw_error;

void record_glfw_error(int /*code*/, const char* description) {
  glfw_error = description == nullptr ? "unknown GLFW error" : description;
  std::replace(glfw_error.begin(), glfw_error.end(), '\n', ' ');
}

[[noreturn]] void no_display(const std::string& why) {
  throw BadInput("no display: multicpg view needs a graphical session (" + why + "); " +
                 kHeadlessHint);
}

bool env_set(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

// GLFW for the viewer's lifetime; a display that cannot be opened is bad input, not a crash.
struct GlfwSession {
  GlfwSession() {
    if (!env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY")) no_display("DISPLAY is not set");
    glfwSetErrorCallback(record_glfw_error);
    if (glfwInit() != GLFW_TRUE) no_display("cannot open the display: " + glfw_error);
  }
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
  ~GlfwSession() { glfwTerminate(); }
};

struct WindowDeleter {
  void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

// MuJoCo's GL loader binds, once per process, to the first of eglGetProcAddress,
// OSMesaGetProcAddress and glXGetProcAddressARB it finds among the loaded symbols. GLFW loads
// libGL privately, so its GLX entry points are published here; a headless platform already
// loaded would win and MuJoCo would not draw into the window, so that is refused.
void publish_glx() {
  if (::dlsym(RTLD_DEFAULT, "eglGetProcAddress") != nullptr ||
      ::dlsym(RTLD_DEFAULT, "OSMesaGetProcAddress") != nullptr) {
    throw RuntimeFailure(
        "view: a headless GL platform (EGL or OSMesa) is already loaded in this process, so "
        "MuJoCo would not draw into the window");
  }
  // Never closed: MuJoCo keeps the loaded entry points for the life of the process.
  if (::dlopen(kGlLibrary, RTLD_NOW | RTLD_GLOBAL) == nullptr) {
    throw RuntimeFailure(std::string("view: cannot load ") + kGlLibrary + " (install libgl1)");
  }
}

WindowPtr open_window(const std::string& title) {
  WindowPtr window(glfwCreateWindow(kWindowWidth, kWindowHeight, title.c_str(), nullptr, nullptr));
  if (!window) no_display("cannot open an OpenGL window: " + glfw_error);
  glfwMakeContextCurrent(window.get());
  glfwSwapInterval(1);  // no tearing; the simulation keeps its own clock
  return window;
}

class Viewer {
 public:
  Viewer(const sim::SimModel& model, const ViewerSpec& spec)
      : model_(model),
        spec_(spec),
        window_(open_window("multicpg view: " + model.controller.morphology.name)),
        stepper_(model, spec.start, spec.faults),
        state_(stepper_.state()),
        synchronised_(neural::follows_master(state_.controller, kFirstClient)) {
    const mjModel* m = model_.mj.get();
    const CameraSpec view;  // the viewpoint of the rendered videos
    const int trunk = tracked_body(m, view);
    mjv_defaultCamera(&camera_);
    camera_.type = mjCAMERA_TRACKING;
    camera_.trackbodyid = trunk;
    camera_.distance = view.distance;
    camera_.azimuth = view.azimuth;
    camera_.elevation = view.elevation;
    // The tracking camera eases toward its body; start on it rather than swoop in.
    std::copy_n(state_.data->subtree_com + 3 * trunk, 3, camera_.lookat);
    publish_glx();

    mjv_defaultOption(&option_);
    mjv_defaultScene(&scene_);
    mjr_defaultContext(&context_);
    mjv_makeScene(m, &scene_, kMaxSceneGeoms);
    mjr_makeContext(m, &context_, mjFONTSCALE_150);

    glfwSetWindowUserPointer(window_.get(), this);
    glfwSetKeyCallback(window_.get(), [](GLFWwindow* w, int key, int, int action, int) {
      of(w).on_key(key, action);
    });
    glfwSetMouseButtonCallback(window_.get(), [](GLFWwindow* w, int button, int action, int) {
      of(w).on_button(button, action);
    });
    glfwSetCursorPosCallback(window_.get(),
                             [](GLFWwindow* w, double x, double y) { of(w).on_cursor(x, y); });
    glfwSetScrollCallback(window_.get(),
                          [](GLFWwindow* w, double, double dy) { of(w).on_scroll(dy); });
  }

  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  ~Viewer() {
    glfwMakeContextCurrent(window_.get());
    mjr_freeContext(&context_);
    mjv_freeScene(&scene_);
  }

  // Real time: one controller step per control_dt of wall time, or as fast as the machine
  // allows when it cannot keep up (never a burst of catch-up steps).
  long run() {
    using Clock = std::chrono::steady_clock;
    const auto period = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(model_.control_dt));
    Clock::time_point due = Clock::now();
    while (glfwWindowShouldClose(window_.get()) == GLFW_FALSE && !done()) {
      const Clock::time_point now = Clock::now();
      if (paused_) {
        due = now;
        for (; single_steps_ > 0 && !done(); --single_steps_) advance();
      } else {
        single_steps_ = 0;
        if (now >= due) {
          advance();
          due = std::max(due + period, now);
        }
      }
      draw();
      if (paused_) {
        glfwWaitEvents();
      } else {
        const double wait = std::chrono::duration<double>(due - Clock::now()).count();
        if (wait > 0.0) {
          glfwWaitEventsTimeout(wait);
        } else {
          glfwPollEvents();
        }
      }
    }
    return state_.step;
  }

 private:
  static constexpr std::size_t kFirstClient = 1;  // leg 0 (R1) is the master (paper §2.2)

  static Viewer& of(GLFWwindow* w) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

  bool done() const { return spec_.steps > 0 && stepper_.step_count() >= spec_.steps; }

  // One controller step, with the fault timeline.
  void advance() { stepper_.step(); }

  // Callbacks only change flags, the camera and the controller's switches: a step may throw,
  // and exceptions must not cross GLFW's C frames, so steps are taken in run().
  void on_key(int key, int action) {
    if (action == GLFW_RELEASE) return;
    const bool press = action == GLFW_PRESS;  // not a key repeat
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) {
      glfwSetWindowShouldClose(window_.get(), GLFW_TRUE);
    } else if (key == GLFW_KEY_SPACE && press) {
      paused_ = !paused_;
    } else if (key == GLFW_KEY_RIGHT && paused_) {
      ++single_steps_;
    } else if (key == GLFW_KEY_S && press) {
      synchronised_ = !synchronised_;
      neural::set_synchronised(state_.controller, synchronised_);
    } else if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9 && press) {
      const auto leg = static_cast<std::size_t>(key - GLFW_KEY_1);
      // Through the stepper, so the fault is kept and told like a scheduled one. Failing the
      // last working leg is refused (BadInput): the overlay shows why until the next leg key.
      refused_.clear();
      try {
        if (leg < model_.legs.size()) {
          stepper_.apply_now(body::Fault{0, {leg}, stepper_.faults().failed(leg)});
        }
      } catch (const BadInput& e) {
        refused_ = e.what();
      }
    }
  }

  void on_button(int button, int action) {
    const bool down = action == GLFW_PRESS;
    if (button == GLFW_MOUSE_BUTTON_LEFT) rotating_ = down;
    if (button == GLFW_MOUSE_BUTTON_RIGHT) zooming_ = down;
    glfwGetCursorPos(window_.get(), &cursor_x_, &cursor_y_);
  }

  // Drags move the camera by the cursor's travel relative to the window height, as MuJoCo's
  // simulate does.
  void on_cursor(double x, double y) {
    const double dx = x - cursor_x_;
    const double dy = y - cursor_y_;
    cursor_x_ = x;
    cursor_y_ = y;
    if (!rotating_ && !zooming_) return;
    int height = 0;
    glfwGetWindowSize(window_.get(), nullptr, &height);
    if (height <= 0) return;
    const int action = zooming_ ? mjMOUSE_ZOOM : mjMOUSE_ROTATE_V;
    mjv_moveCamera(model_.mj.get(), action, dx / height, dy / height, &scene_, &camera_);
  }

  void on_scroll(double dy) {
    mjv_moveCamera(model_.mj.get(), mjMOUSE_ZOOM, 0.0, -kScrollZoom * dy, &scene_, &camera_);
  }

  // The right column of the status overlay, one line per title.
  std::string status_values() const {
    const robot::Morphology& morph = model_.controller.morphology;
    std::ostringstream values;
    values << state_.step << "\n"
           << std::fixed << std::setprecision(2) << state_.data->time << " s\n";
    for (std::size_t i = 0; i < morph.size(); ++i) {
      values << (i == 0 ? "" : "  ") << morph.legs[i].name << " "
             << state_.controller.legs[i].cpg.period;
    }
    values << "\n"
           << faults_caption(morph, state_.faults.schedule.in_force()) << "\n"
           << (synchronised_ ? "synchronised" : "free") << "\n"
           << (paused_ ? "paused" : "running");
    if (!refused_.empty()) values << "\n" << refused_;
    return values.str();
  }

  void draw() {
    const mjModel* m = sim::physics_model(model_, state_);
    const robot::Morphology& morph = model_.controller.morphology;

    mjrRect viewport{0, 0, 0, 0};
    glfwGetFramebufferSize(window_.get(), &viewport.width, &viewport.height);
    mjv_updateScene(m, state_.data.get(), &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
    paint(scene_, fault_colours(model_, state_.faults.schedule.in_force()));
    mjr_render(viewport, &scene_, &context_);

    const std::string values = status_values();
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport,
                refused_.empty() ? "Step\nTime\nPeriods\nFaults\nClients\nStatus"
                                 : "Step\nTime\nPeriods\nFaults\nClients\nStatus\nRefused",
                values.c_str(), &context_);
    const std::string keys = "Space\nRight\n1-" + std::to_string(morph.size()) + "\nS\nEsc, Q";
    const std::string actions = "pause / resume\none step while paused\ndisable / enable leg " +
                                morph.legs.front().name + ".." + morph.legs.back().name +
                                "\nsynchronise / free the clients\nquit";
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, viewport, keys.c_str(), actions.c_str(),
                &context_);
    glfwSwapBuffers(window_.get());
  }

  const sim::SimModel& model_;
  const ViewerSpec& spec_;
  GlfwSession glfw_;
  WindowPtr window_;
  sim::Stepper stepper_;  // the one stepping loop: start, faults
  sim::SimState& state_;
  bool synchronised_;
  std::string refused_;  // why the last leg key did nothing (BadInput's line), or empty
  mjvCamera camera_{};
  mjvOption option_{};
  mjvScene scene_{};
  mjrContext context_{};
  bool paused_ = false;
  long single_steps_ = 0;  // Right presses not yet stepped
  bool rotating_ = false;  // left button held
  bool zooming_ = false;   // right button held
  double cursor_x_ = 0.0;
  double cursor_y_ = 0.0;
};

}  // namespace

long run_viewer(const sim::SimModel& model, const ViewerSpec& spec) {
  Viewer viewer(model, spec);
  return viewer.run();
}

}  // namespace multicpg::report
