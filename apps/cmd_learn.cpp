// multicpg learn: a leg fails and the robot learns leg periods that walk straight again
// (paper §3-§4, Fig. 8; docs/learning.md "Online compensation").
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "apps/commands.h"
#include "apps/learning_options.h"
#include "apps/options.h"
#include "apps/replay_output.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/learning_run.h"
#include "experiments/run_json.h"
#include "experiments/scenarios.h"
#include "robot/leg_sets.h"
#include "sim/fault_spec.h"
#include "sim/record_csv.h"

namespace multicpg::apps {
namespace {

struct LearnOptions {
  RunFlags run;  // robot, faults, learning and simulation flags
  bool json = false;
  std::string out;
  std::string replay;
};

std::string period_cells(const std::vector<int>& periods,
                         const std::vector<std::size_t>& disabled) {
  std::ostringstream row;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    const bool off = std::find(disabled.begin(), disabled.end(), i) != disabled.end();
    row << std::setw(4) << (std::to_string(periods[i]) + (off ? "x" : ""));
  }
  return row.str();
}

// The trace as the paper's Fig. 8: trial, periods (x = disabled), deviation, kept or rejected.
void print_trace(std::ostream& out, const robot::Morphology& morph,
                 const experiments::LearningRun& run, const std::vector<std::size_t>& disabled) {
  const learning::LearningResult& r = run.result;
  out << "trial";
  for (const robot::Leg& leg : morph.legs) out << std::setw(4) << leg.name;
  out << "  deviation  decision\n";
  std::vector<int> start(morph.size(), learning::kStartPeriod);
  out << std::setw(5) << 0 << period_cells(start, disabled) << std::fixed << std::setprecision(2)
      << std::setw(10) << r.initial_deviation_deg << "°  ";
  if (r.detection_step) {
    out << "deviation detected at step " << *r.detection_step << ": CPGs desynchronised\n";
  } else {
    out << "no window deviated more than the threshold\n";
  }
  for (const learning::TrialRecord& t : r.trace) {
    out << std::setw(5) << t.trial << period_cells(t.periods, disabled) << std::setw(10)
        << t.deviation_deg << "°  " << (t.accepted ? "kept" : "rejected");
    if (t.acceptance_probability < 1.0) {
      out << " (P = " << std::setprecision(3) << std::scientific << t.acceptance_probability
          << std::fixed << std::setprecision(2) << ")";
    }
    out << "\n";
  }
}

// Robust runs: one line per learning episode, then the windows walked after the last one.
void print_episodes(std::ostream& out, const robot::Morphology& morph,
                    const learning::LearningResult& r, const std::vector<std::size_t>& failing) {
  if (r.mode != learning::Mode::robust) return;
  out << std::fixed << std::setprecision(2);
  for (std::size_t i = 0; i < r.episodes.size(); ++i) {
    const learning::Episode& e = r.episodes[i];
    out << "episode " << i + 1 << ": detected " << e.detection_deg << "° at step "
        << e.detection_step << ", " << e.trials << " trials, "
        << robot::period_map_text(morph, e.periods, failing) << ", "
        << (e.held ? "held" : (e.interrupted ? "interrupted by a fault" : "not held")) << "\n";
  }
  out << "windows after the last fault or episode (yaw / path angle, deg):";
  for (const sim::WindowMeasure& m : r.final_windows) {
    out << "  " << m.yaw_deg << " / " << m.path_deg;
  }
  out << "\n";
}

std::string trace_csv(const robot::Morphology& morph, const learning::LearningResult& r) {
  std::ostringstream f;
  f << "trial";
  for (const robot::Leg& leg : morph.legs) f << "," << leg.name;
  f << ",deviation_deg,accepted,acceptance_probability\n";
  f.precision(10);
  for (const learning::TrialRecord& t : r.trace) {
    f << t.trial;
    for (int p : t.periods) f << "," << p;
    f << "," << t.deviation_deg << "," << (t.accepted ? 1 : 0) << "," << t.acceptance_probability
      << "\n";
  }
  return f.str();
}

void run_learn(const LearnOptions& o) {
  const experiments::RunSpec spec = run_spec(o.run, /*learn=*/true);
  const robot::Morphology& morph = experiments::morphology(spec);
  const learning::CompensationOptions& options = *spec.learning;
  const std::vector<std::size_t> failing = sim::failing_legs(spec.faults);
  const std::filesystem::path dir(o.out);
  // steps.csv streams as the robot walks (memory flat in the run's length) and takes its name
  // only when the run has ended well (common/atomic_file.h).
  ReplayOutput replay(o.replay);
  std::optional<AtomicFile> steps;
  std::optional<sim::RecordCsvWriter> rows;
  if (!o.out.empty()) {
    ensure_writable_dir(o.out);
    steps.emplace(dir / "steps.csv");
    rows.emplace(steps->stream(), morph, (dir / "steps.csv").string());
  }
  const sim::SimModel model = experiments::make_run_model(spec);

  sim::Observers observers({rows ? &*rows : nullptr, replay.observer()});
  const experiments::LearningRun run = experiments::run_learning(model, spec, 0, &observers);
  const learning::LearningResult& r = run.result;
  const nlohmann::json json = experiments::learn_json(spec, r);

  if (!o.out.empty()) {
    write_file_atomic(dir / "learning.json", json.dump(2) + "\n");
    write_file_atomic(dir / "trace.csv", trace_csv(morph, r));
    steps->commit();
  }
  replay.write();
  if (o.json) {
    std::cout << json.dump(2) << "\n";
    return;
  }
  std::cout << morph.name << ", " << learning::to_string(options.mode) << " mode";
  if (options.mode == learning::Mode::robust) {
    std::cout << " (steering " << learning::to_string(options.steering) << ", "
              << options.hold_windows << " windows to hold)";
  }
  std::cout << ", faults";
  for (const sim::Fault& f : spec.faults) {
    std::cout << " " << sim::malfunction_text(morph, f) << (f.recover ? " recover" : " fail")
              << "@" << f.step;
  }
  std::cout << ", beta " << options.annealing.beta << ", threshold "
            << options.annealing.threshold_deg << "°, window " << options.window_steps
            << ", settle " << r.settle_steps << ", seed " << options.seed << "\n\n";
  print_trace(std::cout, morph, run, failing);
  print_episodes(std::cout, morph, r, failing);
  std::cout << "\n" << learning::to_string(r.outcome);
  if (r.detection_step) {
    std::cout << " after " << r.trials
              << " trials: " << robot::period_map_text(morph, r.periods, failing) << " (deviation "
              << std::fixed << std::setprecision(2) << r.initial_deviation_deg << "° -> "
              << r.final_deviation_deg << "°)";
  }
  std::cout << "\n";
  if (!o.out.empty()) std::cout << "wrote " << o.out << "/{learning.json,trace.csv,steps.csv}\n";
  if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
}

}  // namespace

void register_learn(CLI::App& app) {
  auto opts = std::make_shared<LearnOptions>();
  CLI::App* cmd = app.add_subcommand(
      "learn", "disable legs and learn periods that walk straight again (paper Fig. 8)");
  add_robot_flag(*cmd, opts->run);
  add_fault_flags(*cmd, opts->run);
  add_learning_flags(*cmd, opts->run.learning);
  add_sim_flags(*cmd, opts->run.sim, opts->run.body);
  cmd->add_flag("--json", opts->json, "print one JSON object instead of the table");
  cmd->add_option("--out", opts->out,
                  "directory for learning.json, trace.csv and steps.csv (the per-step record)");
  add_replay_flag(*cmd, opts->replay);
  cmd->callback([opts] { run_learn(*opts); });
}

}  // namespace multicpg::apps
