// Films of simulated runs: every k-th controller step of a run rendered into an MP4,
// or its last step into a PNG. A leg turns red the step it fails, as the paper draws disabled
// legs; a caption in the corner says the step, time, periods and what the run is doing.
//
// A video is rendered on its own thread with its own GL context: capture() only
// copies the robot's pose, so the simulation runs on while earlier frames are drawn and encoded.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "report/render.h"
#include "report/video.h"
#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::report {

enum class FilmFormat { video, picture };

// .mp4 -> video, .png -> picture; anything else throws BadInput naming the allowed types.
FilmFormat film_format(const std::filesystem::path& out);

// Controller steps per frame: real time up to 1000 times faster (a 10^4-step run in 10 frames).
inline constexpr Limits<int> kFilmSpeedLimits{1, 1000};

struct FilmSpec {
  std::filesystem::path out;  // .mp4 or .png
  int width = kDefaultFrameWidth;
  int height = kDefaultFrameHeight;
  // Controller steps per video frame. The video plays at the controller's rate (27 fps at
  // 0.037 s), so 1 is real time and k is k times faster.
  int speed = 1;
  CameraSpec camera;
};

// What one frame shows: the pose and the overlay, copied from the state at capture.
struct FramePose {
  std::vector<mjtNum> qpos;
  // The run's own model while a fault reshapes the robot (sim/fault_effects.h); null: the shared
  // one. Never changed once made, so the film's thread may draw from it.
  std::shared_ptr<const mjModel> model;
  Colouring colours;  // the faults in force, each kind in its colour
  Overlay overlay;    // step, time, periods, faults in force, caption
};
FramePose frame_pose(const sim::SimModel& model, const sim::SimState& state,
                     const std::string& caption);
// Draws `pose` into `scratch` (an mjData of the model) and renders it from `camera`.
Image draw_frame(Renderer& renderer, const sim::SimModel& model, mjData* scratch,
                 const CameraSpec& camera, const FramePose& pose);
// One frame as films draw it, of `state` now (the Python module's render).
Image film_frame(Renderer& renderer, const sim::SimModel& model, const sim::SimState& state,
                 const CameraSpec& camera, const std::string& caption = {});

class Film {
 public:
  // Checks the spec and opens the renderer and, for a video, the encoder and the render thread
  // (BadInput for a bad path, size or speed; RuntimeFailure when no GL platform works).
  Film(const sim::SimModel& model, FilmSpec spec);
  Film(const Film&) = delete;
  Film& operator=(const Film&) = delete;
  // Without finish(): stops the render thread; the video is not written.
  ~Film();

  // Called after every controller step; queues the frames of a video (nothing for a
  // picture). `caption` is an extra overlay line (e.g. the learning trial), may be empty.
  // Throws RuntimeFailure when rendering or encoding an earlier frame failed.
  void capture(const sim::SimState& state, const std::string& caption = {});
  // A video: waits until every frame is rendered and encoded, and moves the file into place.
  void finish();
  // A picture: renders `state` into the PNG.
  void picture(const sim::SimState& state, const std::string& caption = {});

  FilmFormat format() const { return format_; }

  int frames() const;

 private:
  using Pose = FramePose;
  Pose pose(const sim::SimState& state, const std::string& caption) const;
  Image draw(Renderer& renderer, mjData* data, const Pose& pose) const;
  void stop_worker();
  void rethrow_failure();

  const sim::SimModel& model_;
  FilmSpec spec_;
  FilmFormat format_;
  std::optional<Renderer> renderer_;  // a picture's, on the calling thread
  std::optional<VideoWriter> video_;
  // A video's render thread and the poses it has still to draw.
  std::thread worker_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Pose> queue_;
  bool closing_ = false;
  std::exception_ptr failure_;
};

// Films a run through the one stepping loop (sim::Stepper), each frame captioned with what the
// robot is doing as the run itself reports it: walking, a fault, the detection, the learner's
// trial and its verdict, the end of an episode. `film` must outlive the observer.
class FilmObserver final : public sim::Observer {
 public:
  explicit FilmObserver(Film& film, std::string walking = "walking, measuring the deviation")
      : film_(film), caption_(std::move(walking)) {}
  void on_step(const sim::SimModel& model, const sim::SimState& state) override;
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override;
  const std::string& caption() const { return caption_; }

 private:
  Film& film_;
  std::string caption_;
};

}  // namespace multicpg::report
