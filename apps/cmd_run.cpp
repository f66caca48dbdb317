// multicpg run | rerun | merge: experiments as files. `run` resolves a TOML
// experiment file (experiments/experiment_file.h) and runs it, or one shard of it; `rerun`
// runs one recorded run again (or films it); `merge` joins the shards of a job array.
#include <iostream>
#include <optional>
#include <sstream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/provenance.h"
#include "common/table.h"
#include "experiments/experiment_file.h"
#include "experiments/processes.h"
#include "experiments/scenarios.h"
#include "report/film.h"

namespace multicpg::apps {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::string file;
  std::string out;
  std::optional<int> jobs;
  std::optional<int> runs;
  std::string shard = "0/1";
  bool check = false;
  std::int64_t max_runs = experiments::kDefaultMaxRuns;
};

void print_table(const experiments::ExperimentTable& t) {
  std::cout << (t.experiment == experiments::ExperimentKind::beta
                    ? to_markdown(experiments::beta_table(t.rows))
                : t.experiment == experiments::ExperimentKind::grid
                    ? to_markdown(experiments::scenario_table(t.rows, "Grid point"))
                    : to_markdown(experiments::scenario_table(t.rows)));
}

void run(const RunOptions& o) {
  const experiments::Shard shard = experiments::parse_shard(o.shard);
  const int jobs = o.jobs.value_or(experiments::default_jobs());
  const experiments::Sweep sweep =
      experiments::load_experiment_file(o.file, o.runs, {o.max_runs, "--max-runs"});
  if (o.out.empty() && !o.check) {
    throw BadInput("--out: name the directory for the runs (or use --check)");
  }
  if (!sweep.landscapes.empty()) {
    std::size_t count = 0;
    for (const experiments::LandscapeSpec& spec : sweep.landscapes) {
      count += experiments::landscape_combinations(spec).size();
    }
    if (shard.count > 1) throw BadInput("--shard: a landscape runs whole (no shards)");
    if (o.check) {
      if (experiments::is_primary_process()) {
        std::cout << o.file << ": "
                  << (sweep.landscapes.size() == 1
                          ? std::string("a landscape")
                          : std::to_string(sweep.landscapes.size()) + " landscapes")
                  << " of " << count << " combinations\n";
      }
      return;
    }
    run_landscapes_and_report(sweep.landscapes, o.out, jobs);
    return;
  }
  std::size_t in_shard = 0;
  for (std::size_t i = 0; i < sweep.runs.size(); ++i) {
    in_shard += static_cast<int>(i % static_cast<std::size_t>(shard.count)) == shard.index;
  }
  std::size_t points = 1;
  for (const experiments::GridAxis& a : sweep.grid) points *= a.values.size();
  const std::size_t scenarios = sweep.resolved.at("scenarios").size();
  std::ostringstream count;
  count << o.file << ": " << counted(static_cast<long>(sweep.runs.size()), "run") << " ("
        << counted(static_cast<long>(points), "grid point") << " x "
        << counted(static_cast<long>(scenarios), "scenario") << " x "
        << counted(sweep.resolved.at("runs").get<long>(), "run") << ")";
  if (shard.count > 1) count << ", " << in_shard << " in shard " << o.shard;
  if (o.check) {
    if (experiments::is_primary_process()) std::cout << count.str() << "\n";
    return;
  }
  experiments::SweepRunOptions options;
  options.out = o.out;
  options.jobs = jobs;
  options.shard = shard;
  const experiments::SweepOutcome outcome = experiments::run_sweep(sweep, options);
  if (!experiments::is_primary_process()) return;  // the primary prints (processes.h)
  std::cout << count.str() << "\n";
  if (outcome.table) {
    print_table(*outcome.table);
    std::cout << "\nwrote " << o.out
              << "/{table.csv,table.md,summary.json,runs.csv,trials.csv} and " << o.out
              << "/runs/\n";
  } else {
    std::cout << "wrote " << o.out << "/runs/ (shard " << o.shard
              << "); join the shards with `multicpg merge`\n";
  }
}

struct RerunOptions {
  std::string dir;
  std::string id;
  std::string out;
  std::string film;
};

void rerun(const RerunOptions& o) {
  // An unknown file type fails before any work; a picture would show only the last step.
  if (!o.film.empty() && report::film_format(o.film) != report::FilmFormat::video) {
    throw BadInput("--film: name a video, FILE.mp4");
  }
  const experiments::RecordedSweep recorded = experiments::read_sweep(o.dir);
  const experiments::PlannedRun* planned = experiments::find_run(recorded.sweep, o.id);
  if (planned == nullptr) {
    throw BadInput("'" + o.dir + "' has no run " + o.id +
                   " (RUN_ID: a file name in runs/ without .json)");
  }
  const experiments::RunSpec& spec = planned->spec;
  nlohmann::json result;
  if (!o.film.empty()) {
    const sim::SimModel model = experiments::make_model(spec.robot);
    report::FilmSpec film_spec;
    film_spec.out = o.film;
    report::Film film(model, film_spec);
    report::FilmObserver observer(film);
    result = experiments::run_sweep_task(spec, &observer);
    film.finish();
    std::cout << "wrote " << o.film << " (" << film.frames() << " frames)\n";
  } else {
    result = experiments::run_sweep_task(spec);
  }
  if (!o.out.empty()) {
    experiments::RunnerOptions runner;
    runner.out_dir = o.out;
    runner.jobs = 1;
    runner.progress = false;
    runner.arguments = recorded.sweep.resolved;
    runner.provenance = provenance(mj_versionString());
    if (recorded.shard.count > 1)
      runner.arguments["shard"] = experiments::to_string(recorded.shard);
    ensure_writable_dir(o.out);
    experiments::run_tasks(
        {planned->task}, [&](const experiments::Task&) { return result; }, runner);
    std::cout << "wrote " << (fs::path(o.out) / "runs" / (o.id + ".json")).string() << "\n";
  }
  const fs::path saved_path = fs::path(o.dir) / "runs" / (o.id + ".json");
  const std::optional<nlohmann::json> saved = experiments::read_sealed(saved_path);
  std::cout << o.id << ": " << result.at("status").get<std::string>() << " after "
            << result.at("trials") << " trials";
  if (!saved) {
    std::cout << " (" << saved_path.string() << " not saved yet)\n";
    return;
  }
  if (saved->at("result") != result) {
    throw RuntimeFailure("rerun of " + o.id + " differs from " + saved_path.string());
  }
  std::cout << ", identical to " << saved_path.string() << "\n";
}

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "run an experiment file (TOML: scenarios, a grid of options, runs; docs/experiments.md)");
  cmd->add_option("FILE", o->file, "the experiment file (examples/*.toml)")->required();
  cmd->add_option("--out", o->out, "directory for the runs, tables and CSVs (resumes)");
  cmd->add_option("--jobs", o->jobs, "parallel runs (default: every core)")
      ->check(in(experiments::kJobsLimits));
  cmd->add_option("--runs", o->runs, "runs per grid point and scenario (replaces the file's)")
      ->check(in(experiments::kRunsLimits));
  add_max_runs_flag(*cmd, o->max_runs);
  cmd->add_option("--shard", o->shard,
                  "i/N: run only the runs whose index % N == i (a job array; join with merge)")
      ->capture_default_str();
  cmd->add_flag("--check", o->check, "validate the file and print the run count, run nothing");
  cmd->callback([o] { run(*o); });

  auto r = std::make_shared<RerunOptions>();
  CLI::App* re = app.add_subcommand(
      "rerun", "run one run of an experiment directory again, from its recorded options");
  re->add_option("DIR", r->dir, "the experiment directory")->required();
  re->add_option("RUN_ID", r->id, "the run's file name in DIR/runs without .json")->required();
  re->add_option("--out", r->out, "write the run file into this directory as well");
  re->add_option("--film", r->film, "film the run into FILE.mp4");
  re->callback([r] { rerun(*r); });

  struct MergeOptions {
    std::string out;
    std::vector<std::string> dirs;
  };
  auto m = std::make_shared<MergeOptions>();
  CLI::App* me = app.add_subcommand(
      "merge", "join the shard directories of one experiment (run --shard) into OUT");
  me->add_option("OUT", m->out, "the directory for the whole experiment")->required();
  me->add_option("DIR", m->dirs, "the shard directories")->required();
  me->callback([m] {
    std::vector<fs::path> dirs(m->dirs.begin(), m->dirs.end());
    print_table(experiments::merge_sweeps(m->out, dirs, /*progress=*/false));
    std::cout << "\nwrote " << m->out
              << "/{table.csv,table.md,summary.json,runs.csv,trials.csv} and " << m->out
              << "/runs/\n";
  });
}

}  // namespace multicpg::apps
