#include "apps/plot_output.h"

#include <filesystem>
#include <stdexcept>

#include "apps/replay_output.h"
#include "common/errors.h"
#include "common/table.h"
#include "learning/annealing.h"
#include "learning/model_learner.h"
#include "robot/leg_sets.h"
#include "sim/robot_width.h"
#include "sim/sim.h"

namespace multicpg::apps {
namespace {

// Steps the gait strip shows: 120 steps are 4.4 s at 27 Hz (paper §4), two to three tripod
// cycles and one slow-wave cycle (docs/controller.md "Gaits").
constexpr std::size_t kGaitStripSteps = 120;

}  // namespace

void add_plot_flag(CLI::App& cmd, std::string& path) {
  cmd.add_option("--plot", path,
                 "also draw the run to FILE.png: the trunk's path from above marked where the "
                 "fault came, the deviation was detected and the learned gait started (in the "
                 "tunnel with its walls, its axis and the body's reach), the learning trace, a "
                 "gait strip of the last steps");
}

void PlotRecorder::on_start(const sim::SimModel& model, const sim::SimState& state) {
  if (picture_.legs.empty()) {
    morphology_ = model.controller.morphology;
    for (const robot::Leg& leg : morphology_.legs) picture_.legs.push_back(leg.name);
  }
  on_step(model, state);
}

void PlotRecorder::on_step(const sim::SimModel& model, const sim::SimState& state) {
  const sim::Position p = sim::trunk_position(model, state);
  picture_.path.push_back({p.x, p.y});
  const sim::LateralReach reach = sim::lateral_reach(model, state);
  span_.push_back({reach.low, reach.high});
  std::vector<bool> feet(picture_.legs.size());
  for (std::size_t leg = 0; leg < feet.size(); ++leg)
    feet[leg] = sim::foot_contact(model, state, leg);
  contact_.push_back(std::move(feet));
  if (contact_.size() > kGaitStripSteps) contact_.pop_front();
  ++steps_;
}

void PlotRecorder::on_event(const sim::SimModel& model, const sim::SimState& /*state*/,
                            const body::Event& event) {
  using report::RunMarkKind;
  const auto episode = [&event](std::string text) {
    return event.episode > 1 ? text + " (episode " + std::to_string(event.episode) + ")" : text;
  };
  switch (event.kind) {
    case body::EventKind::fault: {
      std::string what;
      for (std::size_t leg : event.legs) {
        what += (what.empty() ? "" : "+") + model.controller.morphology.legs.at(leg).name;
      }
      if (what.empty()) what = "sensor";
      const bool leg_fault =
          event.fault && std::holds_alternative<body::LegFault>(event.fault->kind);
      what +=
          leg_fault || !event.fault ? " fails" : " " + std::string(kind_name(event.fault->kind));
      // Faults of one step share one mark.
      std::vector<report::RunMark>& marks = picture_.marks;
      if (!marks.empty() && marks.back().kind == RunMarkKind::fault && marks.back().at == here()) {
        marks.back().label += ", " + what;
      } else {
        marks.push_back({RunMarkKind::fault, here(), what});
      }
      break;
    }
    case body::EventKind::detection:
      picture_.marks.push_back({RunMarkKind::detection, here(),
                                episode("detected " + fixed(event.deviation_deg, 1) + "°")});
      break;
    case body::EventKind::trial_start:
      trial_start_ = here();
      trial_periods_ = event.periods;
      break;
    case body::EventKind::episode_end: {
      // The answer is the last trial's combination, or one set after the episode (here).
      const std::size_t at = event.periods == trial_periods_ ? trial_start_ : here();
      picture_.marks.push_back({RunMarkKind::learned, at,
                                episode(event.accepted ? "learned gait" : "kept gait (not held)")});
      last_episode_end_ = here();
      break;
    }
    default:
      break;
  }
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

void PlotOutput::learning(const learning::LearningResult& result, double threshold_deg,
                          const std::vector<std::size_t>& disabled) {
  if (!recorder_) return;
  report::RunPicture& picture = recorder_->picture();
  picture.threshold_deg = threshold_deg;
  picture.trials = {{0, result.initial_deviation_deg, true,
                     std::vector<int>(picture.legs.size(), learning::kStartPeriod)}};
  for (const learning::TrialRecord& t : result.trace) {
    std::optional<report::PredictedE> predicted;
    if (const std::optional<learning::ForecastE> e = learning::forecast_e(t.details))
      predicted = report::PredictedE{e->deg, e->low_deg, e->high_deg};
    picture.trials.push_back({static_cast<int>(picture.trials.size()), t.deviation_deg, t.accepted,
                              t.periods, predicted});
  }
  if (result.trace.empty()) {
    picture.no_trial_note = result.outcome == learning::Outcome::no_deviation
                                ? "No trial: the deviation stayed under the threshold (" +
                                      shortest(threshold_deg) + "°), nothing to learn"
                                : "No trial: nothing was learned";
  }
  learned_ = true;
  if (result.forecasts.empty()) return;
  report::ModelMapPicture map;
  map.title = command_title();
  // Each episode's learner has its own model: the map is the last one's.
  map.subtitle = "the last episode's model after trial " + std::to_string(result.trace.size());
  map.threshold_deg = threshold_deg;
  for (const learning::Forecast& f : result.forecasts) {
    map.rows.push_back({robot::period_map_text(recorder_->morphology(), f.periods, disabled),
                        f.hold,
                        {f.e_deg, f.e_low_deg, f.e_high_deg},
                        f.tried});
  }
  model_map_ = std::move(map);
}

report::RunPicture PlotOutput::picture() const {
  if (!recorder_) throw std::logic_error("PlotOutput::picture without --plot");
  report::RunPicture picture = recorder_->picture();
  if (picture.path.empty()) throw RuntimeFailure("no step of the run was recorded for " + path_);
  picture.title = command_title();
  // The body's reach where there are walls to touch (docs/cli.md "--plot").
  if (!picture.walls.empty()) picture.span = recorder_->span();
  // Paper mode ends with its last trial: the picture says so rather than look cut short.
  if (learned_ && recorder_->learned() && !recorder_->walked_after_learning()) {
    picture.subtitle = "the run ends with its last trial: no steps walked after learning";
  }
  const std::deque<std::vector<bool>>& contact = recorder_->contact();
  picture.contact.assign(contact.begin(), contact.end());
  picture.first_contact_step = recorder_->steps() - static_cast<long>(contact.size());
  return picture;
}

void PlotOutput::write() {
  if (!recorder_) return;
  report::plot_run_picture(picture(), path_);
  if (model_map_) report::plot_model_map(*model_map_, model_map_path(path_));
}

std::string model_map_path(const std::string& plot_path) {
  const std::filesystem::path p(plot_path);
  return (p.parent_path() / (p.stem().string() + "-model" + p.extension().string())).string();
}

}  // namespace multicpg::apps
