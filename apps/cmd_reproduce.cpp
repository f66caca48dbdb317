// multicpg reproduce: every figure, table and video of the paper into one folder (issue 5).
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "common/errors.h"
#include "report/reproduce.h"

namespace multicpg::apps {

void register_reproduce(CLI::App& app) {
  struct Options {
    report::ReproduceOptions run;
    std::optional<int> jobs;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "reproduce", "run every experiment of the paper and write DIR/index.html (resumable)");
  cmd->add_option("--out", o->run.out, "folder for the report")->required();
  cmd->add_flag("--quick", o->run.quick, "few learning runs and faster videos: a few minutes");
  cmd->add_option("--jobs", o->jobs, "parallel learning runs (default: every core)");
  cmd->add_option("--seed", o->run.seed, "base seed of every learning run")->capture_default_str();
  cmd->callback([o] {
    if (o->jobs && *o->jobs < 1) {
      throw BadInput("--jobs must be at least 1, got " + std::to_string(*o->jobs));
    }
    o->run.jobs = o->jobs.value_or(0);
    report::reproduce(o->run);
    std::cout << "open " << (o->run.out / "index.html").string() << "\n";
  });
}

}  // namespace multicpg::apps
