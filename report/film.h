// Films of simulated runs (issue 5): every k-th controller step of a run rendered into an MP4,
// or its last step into a PNG. A leg turns red the step it fails, as the paper draws disabled
// legs; a caption in the corner says the step, time, periods and what the run is doing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

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
  // Checks the spec and opens the renderer and, for a video, the encoder (BadInput for a bad
  // path, size or speed).
  Film(const sim::SimModel& model, FilmSpec spec);

  // Called after every controller step; renders the frames of a video (nothing for a
  // picture). `caption` is an extra overlay line (e.g. the learning trial), may be empty.
  void capture(const sim::SimState& state, const std::string& caption = {});
  // A video: waits for the encoder and moves the file into place.
  void finish();
  // A picture: renders `state` into the PNG.
  void picture(const sim::SimState& state, const std::string& caption = {});

  FilmFormat format() const { return format_; }

  int frames() const;

 private:
  Image frame(const sim::SimState& state, const std::string& caption);

  const sim::SimModel& model_;
  FilmSpec spec_;
  FilmFormat format_;
  Renderer renderer_;
  std::optional<VideoWriter> video_;
};

// A step hook for experiments::run_learning that films the run, each frame captioned with
// what the robot is doing: walking while the deviation is measured, then the trial number (a
// trial starts whenever the periods change). `film` must outlive the run.
experiments::StepHook film_learning(Film& film);

}  // namespace multicpg::report
