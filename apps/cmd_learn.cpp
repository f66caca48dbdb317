// multicpg learn: a leg fails and the robot learns leg periods that walk straight again
// (paper §3-§4, Fig. 8; docs/learning.md "Online compensation").
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "apps/commands.h"
#include "apps/hardware_output.h"
#include "apps/learning_options.h"
#include "apps/learning_output.h"
#include "apps/options.h"
#include "apps/plot_output.h"
#include "apps/replay_output.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "body/fault_spec.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/learning_run.h"
#include "experiments/run_json.h"
#include "experiments/scenarios.h"
#include "hw/hardware_record.h"
#include "learning/learners.h"
#include "robot/leg_sets.h"
#include "sim/record_csv.h"

namespace multicpg::apps {
namespace {

struct LearnOptions {
  RunFlags run;  // robot, faults, learning and simulation flags
  bool json = false;
  std::string out;
  std::string replay;
  std::string plot;
};

// trace.csv: the neutral columns, then the learner's own details (learning/learner.h).
std::string trace_csv(const robot::Morphology& morph, const learning::LearnerChoice& learner,
                      const learning::LearningResult& r) {
  const std::vector<std::string> details = learning::detail_columns(learner.name, r.trace);
  std::ostringstream f;
  f << "trial";
  for (const robot::Leg& leg : morph.legs) f << "," << leg.name;
  f << ",deviation_deg,accepted";
  for (const std::string& key : details) f << "," << key;
  f << "\n";
  f.precision(10);
  for (const learning::TrialRecord& t : r.trace) {
    f << t.trial;
    for (int p : t.periods) f << "," << p;
    f << "," << t.deviation_deg << "," << (t.accepted ? 1 : 0);
    for (const std::string& key : details) f << "," << learning::detail_number(t, key);
    f << "\n";
  }
  return f.str();
}

void run_learn(const LearnOptions& o) {
  const experiments::RunSpec spec = run_spec(o.run, /*learn=*/true);
  const std::optional<experiments::HardwareSetup> setup = hardware_setup(spec, o.run);
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  const std::filesystem::path dir(o.out);
  // The per-step record streams as the robot walks (memory flat in the run's length) and takes
  // its name only when the run has ended (common/atomic_file.h): the simulation's steps.csv, a
  // real robot's hardware.csv.
  ReplayOutput replay(o.replay);
  PlotOutput plot(o.plot);
  const std::string steps_file = setup ? "hardware.csv" : "steps.csv";
  std::optional<AtomicFile> steps;
  std::optional<sim::RecordCsvWriter> rows;
  std::optional<hw::StepCsv> hardware_rows;
  if (!o.out.empty()) {
    ensure_writable_dir(o.out);
    steps.emplace(dir / steps_file);
    if (setup) {
      hardware_rows.emplace(steps->stream(), setup->file, morph);
    } else {
      rows.emplace(steps->stream(), morph, (dir / steps_file).string());
    }
  }
  const sim::SimModel model = experiments::make_model(spec.robot);

  // The table streams as the robot learns: the header now, each trial as it is decided
  // (--json prints one object at the end instead).
  std::optional<LearningStream> stream;
  if (!o.json) {
    if (setup) {
      std::cout << "on " << setup->file.name << " (" << hw::to_string(setup->file.protocol) << ", "
                << setup->file.path.string() << ")\n";
    }
    print_learning_header(std::cout, spec,
                          learning::start_settle_steps(*spec.learning, model.controller));
    stream.emplace(std::cout, std::cerr, spec);
  }
  sim::Observers observers(
      {rows ? &*rows : nullptr, replay.observer(), plot.observer(), stream ? &*stream : nullptr});
  // A run on a real robot that a fault or a signal stops keeps its record so far in --out and
  // --json (docs/hardware.md "Outputs").
  const experiments::StoppedSink record = stopped_record(o.json, "");
  experiments::Watchers watchers;
  watchers.observer = &observers;
  watchers.steps = hardware_rows ? &*hardware_rows : nullptr;
  watchers.stopped = [&](const nlohmann::json& j) {
    if (!o.out.empty()) {
      write_file_atomic(dir / "learning.json", j.dump(2) + "\n");
      steps->commit();
    }
    record(j);
  };
  const experiments::LearningRun run =
      experiments::run_learning(model, spec, setup ? &*setup : nullptr, 0, watchers);
  const learning::LearningResult& r = run.result;
  nlohmann::json json = experiments::learn_json(spec, r);
  if (setup) json["hardware"] = run.hardware;

  if (!o.out.empty()) {
    write_file_atomic(dir / "learning.json", json.dump(2) + "\n");
    write_file_atomic(dir / "trace.csv", trace_csv(morph, spec.learning->learner, r));
    steps->commit();
  }
  replay.write();
  plot.learning(r, spec.learning->search.threshold_deg, body::failing_legs(spec.faults));
  plot.write();
  // Learning that did not reach a combination that holds exits 3 (docs/cli.md), after every
  // output is written.
  const auto end = [&r] {
    if (r.outcome == learning::Outcome::not_converged ||
        r.outcome == learning::Outcome::budget_reached) {
      throw GoalNotReached(std::string(learning::to_string(r.outcome)));
    }
  };
  if (o.json) {
    std::cout << json.dump(2) << "\n";
    end();
    return;
  }
  print_learning_end(std::cout, spec, r);
  if (setup) std::cout << hw::hardware_summary(run.hardware) << "\n";
  if (!o.out.empty()) {
    std::cout << "wrote " << o.out << "/{learning.json,trace.csv," << steps_file << "}\n";
  }
  if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
  if (!o.plot.empty()) std::cout << "wrote " << o.plot << "\n";
  if (plot.model_map()) std::cout << "wrote " << model_map_path(o.plot) << "\n";
  end();
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
  add_hardware_flags(*cmd, opts->run);
  cmd->add_flag("--json", opts->json, "print one JSON object instead of the table");
  cmd->add_option("--out", opts->out,
                  "directory for learning.json, trace.csv and steps.csv (the per-step record; "
                  "hardware.csv on a real robot)");
  add_replay_flag(*cmd, opts->replay);
  add_plot_flag(*cmd, opts->plot);
  cmd->callback([opts] { run_learn(*opts); });
}

}  // namespace multicpg::apps
