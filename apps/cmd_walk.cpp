// multicpg walk: walk a simulated robot with given CPG periods and disabled legs, and report the
// distance, speed and heading deviation per window (docs/learning.md "Deviation").
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/hardware_output.h"
#include "apps/options.h"
#include "apps/plot_output.h"
#include "apps/replay_output.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "body/fault_spec.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/body_runs.h"
#include "experiments/run_json.h"
#include "experiments/run_spec.h"
#include "hw/hardware_record.h"
#include "learning/compensation.h"
#include "sim/record_csv.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

// Default run: three 400-step windows.
constexpr long kDefaultSteps = 3 * sim::kDefaultWindow;

struct WalkOptions {
  RunFlags run;  // robot, start, faults and simulation flags
  long settle = 0;
  long steps = kDefaultSteps;
  long window = sim::kDefaultWindow;
  std::string csv;
  std::string replay;
  std::string plot;
  bool json = false;
};

void print_summary(std::ostream& out, const experiments::WalkRecord& w,
                   const std::optional<experiments::HardwareSetup>& setup) {
  const robot::Morphology& morph = experiments::morphology(w.spec->robot);
  out << std::fixed << std::setprecision(3) << morph.name;
  if (setup) {
    out << " on " << setup->file.name << " (" << hw::to_string(setup->file.protocol)
        << "): " << w.steps << " steps measured (" << w.duration_s << " s)";
  } else {
    out << ": " << w.steps << " steps measured (" << w.duration_s << " s simulated)";
  }
  if (w.settle > 0) out << " after " << w.settle << " settling steps";
  out << "; control step " << w.control_dt << " s";
  if (w.physics_dt) out << ", physics step " << std::setprecision(6) << *w.physics_dt << " s";
  out << "\nperiods: ";
  for (std::size_t i = 0; i < morph.size(); ++i) {
    out << (i == 0 ? "" : "  ") << morph.legs[i].name << " " << w.periods[i];
  }
  out << (w.spec->start.warmup > 0 ? " (warmed-up controller)" : " (cold controller)")
      << "\nfaults: ";
  if (w.spec->faults.empty()) out << "none";
  for (const body::Fault& f : w.spec->faults) {
    out << body::malfunction_text(morph, f) << (f.recover ? " recover" : " fail") << " at step "
        << f.step << "  ";
  }
  out << "\n";
  if (w.senses_position) {
    out << std::setprecision(3) << "distance " << w.measure.distance_m << " m (forward "
        << w.measure.forward_m << " m, lateral " << w.measure.lateral_m << " m), speed "
        << std::setprecision(2) << 100.0 * w.measure.distance_m / w.duration_s << " cm/s\n";
  }
  out << std::setprecision(2) << "per " << w.window << "-step window: yaw change"
      << (w.senses_position ? " and path angle" : " (no position sensed: no path angle)")
      << " (deg, + = left):\n";
  if (w.measure.windows.empty()) out << "  (no complete window)\n";
  for (std::size_t k = 0; k < w.measure.windows.size(); ++k) {
    const long first = w.settle + static_cast<long>(k) * w.window;
    out << "  steps " << std::setw(6) << first << "-" << std::left << std::setw(6)
        << first + w.window << std::right << std::setw(9) << w.measure.windows[k].yaw_deg;
    if (w.senses_position) out << std::setw(9) << w.measure.windows[k].path_deg;
    out << "\n";
  }
  out << "final yaw " << w.measure.final_yaw_deg << " deg\n";
  if (!w.hardware.is_null()) out << hw::hardware_summary(w.hardware) << "\n";
}

void run_walk(const WalkOptions& o) {
  const experiments::RunSpec spec = apps::run_spec(o.run, /*learn=*/false);
  const std::optional<experiments::HardwareSetup> setup = hardware_setup(spec, o.run);
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  try {
    body::validate_walk(spec.faults, o.settle, o.steps, o.window);
  } catch (const OptionError& e) {
    throw BadInput(flag_of(e.key(), o.run) + ": " + e.what());
  }
  // Every step streams to the CSV as it is made (docs/cli.md: memory flat in the walk's length);
  // the file takes its name only when the walk has ended well (common/atomic_file.h).
  ReplayOutput replay(o.replay);
  PlotOutput plot(o.plot);
  std::optional<AtomicFile> csv;
  std::optional<sim::RecordCsvWriter> rows;
  std::optional<hw::StepCsv> hardware_rows;
  if (!o.csv.empty()) {
    csv.emplace(o.csv);
    if (setup) {
      hardware_rows.emplace(csv->stream(), setup->file, morph);
    } else {
      rows.emplace(csv->stream(), morph, o.csv);
    }
  }
  sim::Observers observers({rows ? &*rows : nullptr, replay.observer(), plot.observer()});
  const sim::SimModel model = experiments::make_model(spec.robot);
  experiments::Watchers watchers;
  watchers.observer = &observers;
  watchers.record_joints = false;
  watchers.steps = hardware_rows ? &*hardware_rows : nullptr;
  const experiments::StoppedSink record = stopped_record(o.json, "");
  watchers.stopped = [&](const nlohmann::json& j) {
    if (csv) csv->commit();
    record(j);
  };
  const std::unique_ptr<experiments::RunBody> body =
      experiments::open_body(spec, model, setup ? &*setup : nullptr, watchers);
  const experiments::BodyWalk walked = experiments::guarded(*body, spec, watchers.stopped, [&] {
    experiments::BodyWalk w = experiments::walk_body(body->body(), o.settle, o.steps, o.window);
    body->finish("the walk ended");
    return w;
  });
  if (csv) csv->commit();
  replay.write();
  plot.write();
  experiments::WalkRecord w{&spec, o.settle, o.steps, o.window,        {}, model.control_dt, {},
                            true,  {},       0.0,     body->hardware()};
  w.periods = spec.start.periods.empty() ? std::vector<int>(morph.size(), learning::kStartPeriod)
                                         : spec.start.periods;
  if (!setup) w.physics_dt = model.physics_dt;
  w.senses_position = walked.last.has_position();
  w.measure = body::measure_walk(walked.boundaries, walked.last);
  w.duration_s = static_cast<double>(o.steps) * model.control_dt;
  if (o.json) {
    std::cout << experiments::walk_json(w).dump(2) << "\n";
    return;
  }
  print_summary(std::cout, w, setup);
  if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
  if (!o.plot.empty()) std::cout << "wrote " << o.plot << "\n";
}

}  // namespace

void register_walk(CLI::App& app) {
  auto opts = std::make_shared<WalkOptions>();
  CLI::App* cmd = app.add_subcommand(
      "walk", "walk a simulated robot; print distance, speed and yaw deviation per window");
  add_walk_flags(*cmd, opts->run);
  cmd->add_option("--settle", opts->settle,
                  "steps walked before measuring (delay lines fill after 126 steps for the "
                  "hexapod; p = 4 CPGs lock after about 740)")
      ->check(in(body::kStepLimits))
      ->capture_default_str();
  cmd->add_option("--steps", opts->steps, "controller steps measured")
      ->check(in(body::kRunStepsLimits))
      ->capture_default_str();
  cmd->add_option("--window", opts->window, "steps per yaw-deviation window (paper §4: 400)")
      ->check(in(learning::kWindowStepsLimits))
      ->capture_default_str();
  add_sim_flags(*cmd, opts->run.sim, opts->run.body);
  cmd->add_option("--csv", opts->csv,
                  "write every step: trunk position and yaw, each joint's command, target and "
                  "actual angle, each foot's contact");
  add_replay_flag(*cmd, opts->replay);
  add_plot_flag(*cmd, opts->plot);
  cmd->add_flag("--json", opts->json, "print one JSON object instead of the summary");
  add_hardware_flags(*cmd, opts->run);
  cmd->callback([opts] { run_walk(*opts); });
}

}  // namespace multicpg::apps
