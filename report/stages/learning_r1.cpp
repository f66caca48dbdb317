// Figs. 8, 9, 10 and the trunk's path: one filmed learning run with R1 disabled.
#include <fmt/format.h>

#include <algorithm>

#include "common/atomic_file.h"
#include "common/table.h"
#include "experiments/learning_run.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "report/film.h"
#include "report/replay/page.h"
#include "report/stages/stage.h"
#include "robot/leg_sets.h"

namespace multicpg::report {
namespace {

namespace paper = experiments::paper;

// Steps walked with the learned periods after learning, for Figs. 9 and 10.
constexpr long kAfterLearningSteps = 400;
// Steps shown in Figs. 9 and 10: a little over one cycle of the slowest learned period (p = 9).
constexpr long kMotorFigureSteps = 180;
// Walks of the paths before and after learning.
constexpr long kPathSteps = 1200;

// Fig. 8 as a table: one row per trial, trial 0 = the window that detected the deviation.
Table trace_table(const robot::Morphology& morph, const learning::LearningResult& r,
                  const std::vector<std::size_t>& disabled, std::vector<TrialPoint>& points) {
  Table trace{{{"trial"}}, {}};
  for (const robot::Leg& leg : morph.legs) trace.columns.push_back({leg.name});
  trace.columns.push_back({"deviation (deg)"});
  trace.columns.push_back({"decision", Align::left});
  auto row = [&](int trial, const std::vector<int>& periods, double e, const std::string& what) {
    std::vector<std::string> cells{std::to_string(trial)};
    for (std::size_t i = 0; i < periods.size(); ++i) {
      const bool off = std::find(disabled.begin(), disabled.end(), i) != disabled.end();
      cells.push_back(std::to_string(periods[i]) + (off ? " (disabled)" : ""));
    }
    cells.push_back(fixed(e, 2));
    cells.push_back(what);
    trace.add_row(cells);
  };
  points = {
      {0, r.initial_deviation_deg, true, std::vector<int>(morph.size(), learning::kStartPeriod)}};
  row(0, points.front().periods, r.initial_deviation_deg, "deviation detected");
  for (const learning::TrialRecord& t : r.trace) {
    points.push_back({t.trial, t.deviation_deg, t.accepted, t.periods});
    row(t.trial, t.periods, t.deviation_deg, t.accepted ? "kept" : "rejected");
  }
  return trace;
}

}  // namespace

Section learning_r1_stage(const StageContext& ctx) {
  const sim::SimModel hexapod = sim::make_sim_model(robot::RobotKind::hexapod, ctx.options.sim);
  const robot::Morphology& morph = hexapod.controller.morphology;
  const std::size_t legs = morph.size();
  experiments::RunSpec spec;
  spec.robot.sim = ctx.options.sim;
  learning::CompensationOptions& options = spec.learning.emplace();
  options.mode = learning::Mode::paper;  // the paper's figures show the paper's algorithm
  options.seed = ctx.options.seed;
  spec.start = experiments::learning_start(options.mode);
  const std::vector<std::size_t> disabled{robot::leg_index(morph, "R1")};
  // R1 fails as the first measured window starts, after the robot walked healthy while its
  // CPGs settled: that window's deviation is the paper's "after 400 time steps" (§4.1).
  spec.faults = body::fail_at(disabled, learning::default_settle_steps(hexapod.controller));
  spec.record.steps = true;
  const std::filesystem::path video = ctx.dir("videos") / "learning-r1.mp4";
  Film film(hexapod, {video, kDefaultFrameWidth, kDefaultFrameHeight, ctx.sizes.film_speed, {}});
  FilmObserver film_observer(film);
  ReplayRecorder replay;
  sim::Observers observer({&film_observer, &replay});
  const experiments::LearningRun run =
      experiments::run_learning(hexapod, spec, kAfterLearningSteps, &observer);
  film.finish();
  const std::filesystem::path replay_page = ctx.dir("replays") / "learning-r1.html";
  write_replay(replay.recording(),
               "Learning with R1 disabled (paper Fig. 8), seed " + std::to_string(ctx.options.seed),
               replay_page);
  const learning::LearningResult& r = run.result;
  const std::filesystem::path figures = ctx.dir("figures");

  std::vector<TrialPoint> points;
  const Table trace = trace_table(morph, r, disabled, points);
  const FigureFiles fig8 =
      plot_learning_trace(points, leg_names(morph), options.search.threshold_deg, figures);

  // Figs. 9 and 10: the last steps, walking with the learned periods.
  const sim::WalkRecord& rec = run.record;
  const std::size_t end = rec.rows();
  const std::size_t begin = end - static_cast<std::size_t>(kMotorFigureSteps);
  MotorTrace motor;
  std::vector<std::vector<bool>> contact;
  for (std::size_t row = begin; row < end; ++row) {
    std::vector<std::array<double, 3>> m(legs);
    std::vector<bool> c(legs);
    for (std::size_t leg = 0; leg < legs; ++leg) {
      for (std::size_t j = 0; j < 3; ++j) m[leg][j] = rec.command[(row * legs + leg) * 3 + j];
      c[leg] = rec.contact[row * legs + leg] != 0;
    }
    motor.push_back(m);
    contact.push_back(c);
  }
  std::vector<std::string> notes;
  for (std::size_t leg = 0; leg < legs; ++leg) {
    notes.push_back(leg == 0 ? "disabled" : "p" + std::to_string(r.periods[leg]));
  }
  int r1_touches = 0;
  for (const auto& c : contact) r1_touches += c[0] ? 1 : 0;
  const FigureFiles fig9 =
      plot_motor_outputs(motor, leg_names(morph), notes, hexapod.control_dt, figures);
  const FigureFiles fig10 =
      plot_foot_contacts(contact, leg_names(morph), hexapod.control_dt, figures);

  // The trunk's path from above, R1 disabled: all periods 4 versus the learned ones.
  TrunkPaths paths;
  for (bool learned : {false, true}) {
    sim::WalkSpec spec;
    spec.start.periods = learned ? r.periods : std::vector<int>(legs, learning::kStartPeriod);
    spec.faults = body::fail_at(disabled, 0);
    spec.steps = kPathSteps;
    spec.record = false;
    const sim::WalkResult w = sim::walk(hexapod, spec);
    auto& path = learned ? paths.after : paths.before;
    for (std::size_t i = 0; i < w.record.rows(); ++i)
      path.push_back({w.record.x[i], w.record.y[i]});
  }
  const std::string learned = robot::period_map_text(morph, r.periods, disabled);
  paths.before_label = "all periods 4";
  paths.after_label = "learned: " + learned;
  const FigureFiles path_fig = plot_trunk_paths(paths, figures);

  write_file_atomic(figures / "learning-r1.json",
                    learning::to_json(r, morph, disabled).dump(2) + "\n");
  const std::string threshold = fixed(options.search.threshold_deg, 0) + "°";
  const bool detected = r.detection_step.has_value();
  const std::vector<Verdict> verdicts{
      {"R1 disabled, all periods 4: the first window deviates more than the threshold " +
           threshold + " (§4.1)",
       fixed(paper::kR1InitialDeg, 2) + "°",
       fixed(r.initial_deviation_deg, 2) + "°" + (detected ? ", detected" : ", not detected"),
       detected ? Reproduced::yes : Reproduced::no},
      {"Learning brings R1's deviation under " + threshold + " within " +
           std::to_string(paper::kMostTrials) +
           " trials (Fig. 8; partly = converged, but in more trials)",
       std::to_string(paper::kR1Trials) + " trials, " + fixed(paper::kR1FinalDeg, 2) + "°",
       std::string(learning::to_string(r.outcome)) + " after " + counted(r.trials, "trial") + ", " +
           fixed(r.final_deviation_deg, 2) + "°",
       r.converged() ? (r.trials <= paper::kMostTrials ? Reproduced::yes : Reproduced::partly)
                     : Reproduced::no}};
  Section section{
      "learning-r1",
      "Learning with R1 disabled (Figs. 8, 9, 10; the trunk's path)",
      "R1 disabled, all periods 4: " + fixed(paper::kR1InitialDeg, 2) +
          "° after the first 400 steps. Trial 1 L1 = 5: " + fixed(paper::kR1Trial1Deg, 2) +
          "°, kept; trial 2 R3 = 9: " + fixed(paper::kR1Trial2Deg, 2) +
          "°, rejected (P = " + fmt::format("{:.3g}", paper::kR1Trial2Acceptance) + "); after " +
          std::to_string(paper::kR1Trials) + " trials " + fixed(paper::kR1FinalDeg, 2) + "° with " +
          paper::combination_text(paper::kLearnedR1) +
          " (Fig. 8). Fig. 9: the 18 motor outputs, R1 constant, hind FTi inverted. Fig. 10: "
          "the disabled R1 still touches the ground intermittently.",
      "Seed " + std::to_string(ctx.options.seed) + ": " + fixed(r.initial_deviation_deg, 2) +
          "° detected, then " + std::string(learning::to_string(r.outcome)) + " after " +
          std::to_string(r.trials) + " trials at " + fixed(r.final_deviation_deg, 2) + "° with " +
          learned + ". R1's foot touched the ground in " + std::to_string(r1_touches) + " of the " +
          std::to_string(kMotorFigureSteps) +
          " steps of Fig. 10. The video shows the whole run at " +
          std::to_string(ctx.sizes.film_speed) + "× speed.",
      {ctx.image(fig8), ctx.image(fig9), ctx.image(fig10), ctx.image(path_fig)},
      {ctx.rel(video)},
      {ctx.rel(figures / "learning-r1.json")},
      {trace},
      {ctx.rel(replay_page)}};
  section.verdicts = verdicts;
  return section;
}

}  // namespace multicpg::report
