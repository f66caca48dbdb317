// `--plot FILE.png` of walk, learn and tunnel: the run recorded as it goes (its trunk path, the
// body's reach, its feet's contact over the last steps, where faults, detections and learned gaits
// came) and drawn on the spot as one picture, with the tunnel and the learning trace where the
// run has them (report/figures.h, RunPicture).
#pragma once

#include <CLI/CLI.hpp>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "learning/compensation.h"
#include "report/figures.h"
#include "sim/stepper.h"

namespace multicpg::apps {

// Adds --plot, bound to `path`.
void add_plot_flag(CLI::App& cmd, std::string& path);

// The run as --plot records it: its trunk path and its feet's contact over the last steps. At
// namespace scope, not nested in PlotOutput: clang cannot use a nested class's default member
// initialisers (steps_) before the enclosing class is complete, which std::optional needs.
class PlotRecorder final : public sim::Observer {
 public:
  void on_start(const sim::SimModel& model, const sim::SimState& state) override;
  void on_step(const sim::SimModel& model, const sim::SimState& state) override;
  // Marks where a fault came, where the deviation was detected and where the gait an episode
  // ended with started (its trial's start; where it was set, when set after the episode).
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override;
  report::RunPicture& picture() { return picture_; }
  const report::RunPicture& picture() const { return picture_; }
  const std::deque<std::vector<bool>>& contact() const { return contact_; }
  // The body's lateral reach at each path point (sim/robot_width.h).
  const std::vector<report::LateralSpan>& span() const { return span_; }
  // The robot's legs, as the run's model has them (empty before the run starts).
  const robot::Morphology& morphology() const { return morphology_; }
  long steps() const { return steps_; }
  // Whether a learning episode ended, and whether the run walked on after the last one.
  bool learned() const { return last_episode_end_.has_value(); }
  bool walked_after_learning() const {
    return last_episode_end_ && *last_episode_end_ + 1 < picture_.path.size();
  }

 private:
  std::size_t here() const { return picture_.path.empty() ? 0 : picture_.path.size() - 1; }

  report::RunPicture picture_;
  robot::Morphology morphology_{};
  std::deque<std::vector<bool>> contact_;  // the last steps' contact, [step][leg]
  std::vector<report::LateralSpan> span_;
  long steps_ = 0;  // rows recorded
  // The episode's last trial: where it started and the combination it set.
  std::size_t trial_start_ = 0;
  std::vector<int> trial_periods_;
  std::optional<std::size_t> last_episode_end_;  // path index of the last episode's end
};

class PlotOutput {
 public:
  // Checks the path before any work (BadInput naming --plot).
  explicit PlotOutput(std::string path);
  // The recorder to attach to the run; null without --plot.
  sim::Observer* observer() { return recorder_ ? &*recorder_ : nullptr; }
  // The tunnel the run walked: its walls and its axis, the course (metres, robot/mjcf.h).
  void tunnel(double length_m, double width_m);
  // The learning the run did: trial 0 (the detection window, all periods 4) and every trial,
  // numbered across episodes, with a model's forecast of each; a model-based learner's map after
  // its last trial, for the picture beside (model_map_path). `disabled`: the failed legs.
  void learning(const learning::LearningResult& result, double threshold_deg,
                const std::vector<std::size_t>& disabled);
  // The picture as write() draws it (only with --plot): the run so far, titled with the command
  // line, the body's reach with the tunnel, a subtitle when the run ended with its last trial.
  report::RunPicture picture() const;
  // The model's map learning() made, if the run's learner has a model.
  const std::optional<report::ModelMapPicture>& model_map() const { return model_map_; }
  // Draws the picture (when --plot named a file), and the model's map beside it when there is
  // one.
  void write();

 private:
  std::string path_;
  std::optional<PlotRecorder> recorder_;
  bool learned_ = false;  // learning() was told a result
  std::optional<report::ModelMapPicture> model_map_;
};

// Where --plot FILE.png draws a model-based learner's map: FILE-model.png beside it.
std::string model_map_path(const std::string& plot_path);

}  // namespace multicpg::apps
