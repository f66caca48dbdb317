// `--plot FILE.png` of walk, learn and tunnel: the run recorded as it goes (its trunk path and its
// feet's contact over the last steps) and drawn on the spot as one picture, with the tunnel and
// the learning trace where the run has them (report/figures.h, RunPicture).
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
  report::RunPicture& picture() { return picture_; }
  std::deque<std::vector<bool>>& contact() { return contact_; }
  long steps() const { return steps_; }

 private:
  report::RunPicture picture_;
  std::deque<std::vector<bool>> contact_;  // the last steps' contact, [step][leg]
  long steps_ = 0;                         // rows recorded
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
  // numbered across episodes.
  void learning(const learning::LearningResult& result, double threshold_deg);
  // Draws the picture (when --plot named a file), titled with the command line.
  void write();

 private:
  std::string path_;
  std::optional<PlotRecorder> recorder_;
};

}  // namespace multicpg::apps
