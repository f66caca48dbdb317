// multicpg walk: walk a simulated robot with given CPG periods and disabled legs, and report the
// distance, speed and heading deviation per window (docs/learning.md "Deviation").
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/hardware_flags.h"
#include "apps/options.h"
#include "apps/plot_output.h"
#include "apps/replay_output.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "body/course_json.h"
#include "body/fault_spec.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/run_json.h"
#include "experiments/run_spec.h"
#include "learning/compensation.h"
#include "robot/leg_sets.h"
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
  hw::HardwareFlags hardware;  // walk a real robot
};

struct Run {
  const robot::Morphology* morph;
  sim::WalkSpec spec;
  double control_dt;
  double physics_dt;
};

nlohmann::json to_json(const Run& run, const sim::WalkResult& result) {
  const robot::Morphology& morph = *run.morph;
  const nlohmann::json periods = robot::period_map_json(morph, run.spec.start.periods);
  nlohmann::json faults = nlohmann::json::array();
  for (const body::Fault& f : run.spec.faults) {
    // A fault's one shape (sim/course_json.h), its legs named as --disable names them.
    nlohmann::json fault = f;
    fault["legs"] = robot::leg_set_name(morph, f.legs);
    faults.push_back(fault);
  }
  nlohmann::json windows = nlohmann::json::array();
  for (const body::WindowMeasure& m : result.windows) {
    windows.push_back({{"yaw_deg", m.yaw_deg}, {"path_deg", m.path_deg}});
  }
  return {{"robot", morph.name},
          {"periods", periods},
          {"faults", faults},
          {"warmup", run.spec.start.warmup},
          {"settle", run.spec.settle},
          {"steps", run.spec.steps},
          {"window", run.spec.window},
          {"control_dt_s", run.control_dt},
          {"physics_dt_s", run.physics_dt},
          {"duration_s", result.duration_s},
          {"distance_m", result.distance_m},
          {"forward_m", result.forward_m},
          {"lateral_m", result.lateral_m},
          {"speed_m_s", result.speed_m_s},
          {"window_deviations_deg", result.window_deviations_deg},
          {"windows", windows},
          {"final_yaw_deg", result.final_yaw_deg}};
}

void print_summary(std::ostream& out, const Run& run, const sim::WalkResult& r) {
  const robot::Morphology& morph = *run.morph;
  const sim::WalkSpec& s = run.spec;
  out << std::fixed << std::setprecision(3) << morph.name << ": " << s.steps << " steps measured ("
      << r.duration_s << " s simulated)";
  if (s.settle > 0) out << " after " << s.settle << " settling steps";
  out << "; control step " << run.control_dt << " s, physics step " << std::setprecision(6)
      << run.physics_dt << " s\n";
  out << "periods: ";
  for (std::size_t i = 0; i < morph.size(); ++i) {
    out << (i == 0 ? "" : "  ") << morph.legs[i].name << " " << s.start.periods[i];
  }
  out << (s.start.warmup > 0 ? " (warmed-up controller)" : " (cold controller)") << "\nfaults: ";
  if (s.faults.empty()) out << "none";
  for (const body::Fault& f : s.faults) {
    out << body::malfunction_text(morph, f) << (f.recover ? " recover" : " fail") << " at step "
        << f.step << "  ";
  }
  out << "\n";
  out << std::setprecision(3) << "distance " << r.distance_m << " m (forward " << r.forward_m
      << " m, lateral " << r.lateral_m << " m), speed " << std::setprecision(2)
      << 100.0 * r.speed_m_s << " cm/s\n";
  out << "per " << s.window << "-step window: yaw change and path angle (deg, + = left):\n";
  if (r.windows.empty()) out << "  (no complete window)\n";
  for (std::size_t w = 0; w < r.windows.size(); ++w) {
    const long first = s.settle + static_cast<long>(w) * s.window;
    out << "  steps " << std::setw(6) << first << "-" << std::left << std::setw(6)
        << first + s.window << std::right << std::setw(9) << r.windows[w].yaw_deg << std::setw(9)
        << r.windows[w].path_deg << "\n";
  }
  out << "final yaw " << r.final_yaw_deg << " deg\n";
}

// walk --hardware: the same walk on a real robot (docs/hardware.md): the yaw change of each
// window, the path angle only where the robot senses its position.
void run_walk_on_hardware(const WalkOptions& o, const experiments::RunSpec& spec) {
  if (!o.replay.empty()) throw BadInput("--replay records the simulation; not with --hardware");
  if (!o.plot.empty()) throw BadInput("--plot draws the simulation; not with --hardware");
  const hw::HardwareSetup setup = hardware_setup(spec, o.hardware, o.run);
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  std::optional<AtomicFile> csv;
  std::optional<hw::StepCsv> rows;
  if (!o.csv.empty()) {
    csv.emplace(o.csv);
    rows.emplace(csv->stream(), setup.file, morph);
  }
  const hw::StoppedSink record = stopped_record(o.json, "");
  const auto stopped = [&](const nlohmann::json& j) {
    if (csv) csv->commit();
    record(j);
  };
  const hw::HardwareWalk w = hw::walk_on_hardware(spec, setup, o.settle, o.steps, o.window, stopped,
                                                  rows ? &*rows : nullptr);
  if (csv) csv->commit();
  const bool path = setup.file.senses_position();
  nlohmann::json windows = nlohmann::json::array();
  for (const body::WindowMeasure& m : w.windows) {
    windows.push_back({{"yaw_deg", m.yaw_deg},
                       {"path_deg", path ? nlohmann::json(m.path_deg) : nlohmann::json()}});
  }
  if (o.json) {
    nlohmann::json json{
        {"robot", morph.name},
        {"periods",
         robot::period_map_json(morph, spec.start.periods.empty()
                                           ? std::vector<int>(morph.size(), learning::kStartPeriod)
                                           : spec.start.periods)},
        {"settle", o.settle},
        {"steps", w.steps},
        {"window", o.window},
        {"windows", windows},
        {"final_yaw_deg", w.final_yaw_deg},
        {"hardware", w.hardware}};
    experiments::record_robot_file(json, spec.robot);
    std::cout << json.dump(2) << "\n";
    return;
  }
  std::cout << std::fixed << std::setprecision(3) << morph.name << " on " << setup.file.name << " ("
            << hw::to_string(setup.file.protocol) << "): " << w.steps << " steps measured";
  if (o.settle > 0) std::cout << " after " << o.settle << " settling steps";
  std::cout << "\nper " << o.window << "-step window: yaw change"
            << (path ? " and path angle" : " (no position sensed: no path angle)")
            << " (deg, + = left):\n";
  if (w.windows.empty()) std::cout << "  (no complete window)\n";
  for (std::size_t k = 0; k < w.windows.size(); ++k) {
    const long first = o.settle + static_cast<long>(k) * o.window;
    std::cout << "  steps " << std::setw(6) << first << "-" << std::left << std::setw(6)
              << first + o.window << std::right << std::setw(9) << w.windows[k].yaw_deg;
    if (path) std::cout << std::setw(9) << w.windows[k].path_deg;
    std::cout << "\n";
  }
  std::cout << "final yaw " << w.final_yaw_deg << " deg\n" << hardware_summary(w.hardware) << "\n";
}

void run_walk(const WalkOptions& o) {
  const experiments::RunSpec run_spec = apps::run_spec(o.run, /*learn=*/false);
  if (o.hardware.given() || o.hardware.lock_step) {
    run_walk_on_hardware(o, run_spec);
    return;
  }
  const robot::Morphology& morph = experiments::morphology(run_spec.robot);
  Run run{&morph, {}, 0.0, 0.0};
  sim::WalkSpec& spec = run.spec;
  spec.start = run_spec.start;
  spec.faults = run_spec.faults;
  spec.settle = o.settle;
  spec.steps = o.steps;
  spec.window = o.window;
  // Every step streams to the CSV as it is made (docs/cli.md: memory flat in the walk's length);
  // the file takes its name only when the walk has ended well (common/atomic_file.h).
  spec.keep_record = false;
  ReplayOutput replay(o.replay);
  PlotOutput plot(o.plot);
  std::optional<AtomicFile> csv;
  std::optional<sim::RecordCsvWriter> rows;
  if (!o.csv.empty()) {
    csv.emplace(o.csv);
    rows.emplace(csv->stream(), morph, o.csv);
  }
  sim::Observers observers({rows ? &*rows : nullptr, replay.observer(), plot.observer()});
  spec.observer = &observers;

  const sim::SimModel model = experiments::make_model(run_spec.robot);
  run.control_dt = model.control_dt;
  run.physics_dt = model.physics_dt;
  sim::WalkResult result;
  try {
    result = sim::walk(model, spec);
  } catch (const OptionError& e) {
    throw BadInput(flag_of(e.key(), o.run) + ": " + e.what());
  }
  if (csv) csv->commit();
  replay.write();
  plot.write();
  if (o.json) {
    nlohmann::json json = to_json(run, result);
    experiments::record_robot_file(json, run_spec.robot);
    std::cout << json.dump(2) << "\n";
  } else {
    print_summary(std::cout, run, result);
    if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
    if (!o.plot.empty()) std::cout << "wrote " << o.plot << "\n";
  }
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
  add_hardware_flags(*cmd, opts->hardware);
  cmd->callback([opts] { run_walk(*opts); });
}

}  // namespace multicpg::apps
