// Films of simulated runs (issue 5): every k-th controller step of a run rendered into an MP4,
// or its last step into a PNG. A leg turns red the step it fails, as the paper draws disabled
// legs; a caption in the corner says the step, time, periods and what the run is doing.
//
// A video is rendered on its own thread with its own GL context (issue 12): capture() only
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

#include "experiments/learning_run.h"
#include "report/render.h"
#include "report/video.h"
#include "sim/sim.h"

namespace multicpg::report {

enum class FilmFormat { video, picture };

// .mp4 -> video, .png -> picture; anything else throws BadInput naming the allowed types.
FilmFormat film_format(const std::filesystem::path& out);

struct FilmSpec {
  std::filesystem::path out;  // .mp4 or .png
  int width = kDefaultFrameWidth;
  int height = kDefaultFrameHeight;
  // Controller steps per video frame. The video plays at the controller's rate (27 fps at
  // 0.037 s), so 1 is real time and k is k times faster.
  int speed = 1;
  CameraSpec camera;
};

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
  // What one frame shows: the pose and the overlay, copied from the state at capture.
  struct Pose {
    std::vector<mjtNum> qpos;
    std::vector<std::string> red;
    Overlay overlay;
  };
  Pose pose(const sim::SimState& state, const std::string& caption) const;
  Image draw(Renderer& renderer, mjData* data, const Pose& pose) const;
  void render_video();
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

// A step hook for experiments::run_learning that films the run, each frame captioned with
// what the robot is doing: walking while the deviation is measured, then the trial number (a
// trial starts whenever the periods change). `film` must outlive the run.
experiments::StepHook film_learning(Film& film);

}  // namespace multicpg::report
