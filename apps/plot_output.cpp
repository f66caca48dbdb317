#include "apps/plot_output.h"

#include "apps/replay_output.h"
#include "common/errors.h"
#include "learning/annealing.h"
#include "sim/sim.h"

namespace multicpg::apps {
namespace {

// Steps the gait strip shows: 120 steps are 4.4 s at 27 Hz (paper §4), two to three tripod
// cycles and one slow-wave cycle (docs/controller.md "Gaits").
constexpr std::size_t kGaitStripSteps = 120;

}  // namespace

void add_plot_flag(CLI::App& cmd, std::string& path) {
  cmd.add_option("--plot", path,
                 "also draw the run to FILE.png: the trunk's path from above (with the tunnel "
                 "and its axis), the learning trace, a gait strip of the last steps");
}

void PlotRecorder::on_start(const sim::SimModel& model, const sim::SimState& state) {
  if (picture_.legs.empty()) {
    for (const robot::Leg& leg : model.controller.morphology.legs)
      picture_.legs.push_back(leg.name);
  }
  on_step(model, state);
}

void PlotRecorder::on_step(const sim::SimModel& model, const sim::SimState& state) {
  const sim::Position p = sim::trunk_position(model, state);
  picture_.path.push_back({p.x, p.y});
  std::vector<bool> feet(picture_.legs.size());
  for (std::size_t leg = 0; leg < feet.size(); ++leg)
    feet[leg] = sim::foot_contact(model, state, leg);
  contact_.push_back(std::move(feet));
  if (contact_.size() > kGaitStripSteps) contact_.pop_front();
  ++steps_;
}

PlotOutput::PlotOutput(std::string path) : path_(std::move(path)) {
  if (path_.empty()) return;
  try {
    report::check_run_picture_path(path_);
  } catch (const BadInput& e) {
    throw BadInput(std::string("--plot: ") + e.what());
  }
  recorder_.emplace();
}

void PlotOutput::tunnel(double length_m, double width_m) {
  if (!recorder_) return;
  const double half = width_m / 2.0;
  recorder_->picture().walls = {{{0.0, half}, {length_m, half}}, {{0.0, -half}, {length_m, -half}}};
  recorder_->picture().course = {{0.0, 0.0}, {length_m, 0.0}};
}

void PlotOutput::learning(const learning::LearningResult& result, double threshold_deg) {
  if (!recorder_) return;
  report::RunPicture& picture = recorder_->picture();
  picture.threshold_deg = threshold_deg;
  picture.trials = {{0, result.initial_deviation_deg, true,
                     std::vector<int>(picture.legs.size(), learning::kStartPeriod)}};
  for (const learning::TrialRecord& t : result.trace) {
    picture.trials.push_back(
        {static_cast<int>(picture.trials.size()), t.deviation_deg, t.accepted, t.periods});
  }
}

void PlotOutput::write() {
  if (!recorder_) return;
  report::RunPicture& picture = recorder_->picture();
  if (picture.path.empty()) throw RuntimeFailure("no step of the run was recorded for " + path_);
  picture.title = command_title();
  const std::deque<std::vector<bool>>& contact = recorder_->contact();
  picture.contact.assign(contact.begin(), contact.end());
  picture.first_contact_step = recorder_->steps() - static_cast<long>(contact.size());
  report::plot_run_picture(picture, path_);
}

}  // namespace multicpg::apps
