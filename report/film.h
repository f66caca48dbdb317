// Films of simulated runs (issue 5): every k-th controller step of a run rendered into an MP4,
// or its last step into a PNG. A leg turns red the step it fails, as the paper draws disabled
// legs; a caption in the corner says the step, time, periods and what the run is doing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "report/render.h"
#include "report/video.h"
#include "sim/sim.h"
#include "sim/stepper.h"

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

// One frame as films draw it: the state from `camera`, failed legs red, the corner caption
// (step, time, periods, disabled legs and `caption` if not empty). `renderer` must be of
// `model`'s mjModel.
Image film_frame(Renderer& renderer, const sim::SimModel& model, const sim::SimState& state,
                 const CameraSpec& camera, const std::string& caption = {});

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

// Films a run through the one stepping loop (sim::Stepper), each frame captioned with what the
// robot is doing as the run itself reports it: walking, a fault, the detection, the learner's
// trial and its verdict, the end of an episode. `film` must outlive the observer.
class FilmObserver final : public sim::Observer {
 public:
  explicit FilmObserver(Film& film, std::string walking = "walking, measuring the deviation")
      : film_(film), caption_(std::move(walking)) {}
  void on_step(const sim::SimModel& model, const sim::SimState& state) override;
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const sim::Event& event) override;
  const std::string& caption() const { return caption_; }

 private:
  Film& film_;
  std::string caption_;
};

}  // namespace multicpg::report
