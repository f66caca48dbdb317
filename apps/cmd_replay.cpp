// multicpg replay: a saved run (an experiment's run file, or the JSON of learn or walk) made
// again and written as a 3D replay page, one self-contained HTML file (docs/replay.md).
#include <iostream>

#include "apps/commands.h"
#include "apps/sim_flags.h"
#include "common/errors.h"
#include "report/replay/page.h"
#include "report/replay/rerun.h"
#include "sim/json.h"

namespace multicpg::apps {
namespace {

struct ReplayOptions {
  std::string run;
  std::string out;
  sim::SimOptions sim;
  BodyFlags body;
};

void run_replay(const ReplayOptions& o) {
  report::check_replay_path(o.out);  // a bad path fails before the run is made again
  const sim::SimOptions options = with_body(o.sim, o.body);
  if (report::is_experiment_run(o.run) &&
      nlohmann::json(options) != nlohmann::json(with_body(sim::SimOptions{}, BodyFlags{}))) {
    throw BadInput("'" + o.run +
                   "' is an experiment's run, which records its simulation: give no simulation "
                   "flags");
  }
  const report::RerunReplay replay = report::rerun_saved(o.run, options);
  report::write_replay(replay.recording, replay.title, o.out);
  std::cout << "replayed " << o.run << " (" << replay.recording.rows() << " steps); wrote " << o.out
            << "\n";
}

}  // namespace

void register_replay(CLI::App& app) {
  auto o = std::make_shared<ReplayOptions>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "make a saved run again and write it as a 3D replay: one HTML page that opens offline in "
      "any browser (docs/replay.md)");
  cmd->add_option("RUN", o->run,
                  "an experiment's run file DIR/runs/ID.json, the JSON of learn --json or walk "
                  "--json, or a learn --out directory")
      ->required();
  cmd->add_option("--out", o->out, "the page, FILE.html")->required();
  // A learning or walk result does not record these (an experiment's run file does): give the
  // ones the run was made with.
  add_sim_flags(*cmd, o->sim, o->body);
  cmd->callback([o] { run_replay(*o); });
}

}  // namespace multicpg::apps
