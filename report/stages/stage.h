// The stages of `multicpg reproduce`: one table of {id, figures, run}, one file per
// stage, each a thin layer over the experiments' functions that turns their results into a
// report Section (figures, tables, videos and what the paper says beside what we measured).
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/learning_experiments.h"
#include "report/figures.h"
#include "report/html.h"
#include "report/reproduce_options.h"

namespace multicpg::report {

// Runs per experiment and film speeds: the paper's (docs/learning.md "The paper's experiments") or,
// with --quick, a few.
struct Sizes {
  int hexapod_runs, quadruped_runs, beta_runs;
  int beta_max_trials;  // trial cap of the β study's runs (paper: 200)
  // The β values of the study; empty = the paper's (Fig. 14, experiments::kBetaStudyValues).
  std::span<const double> beta_values;
  int film_speed;         // controller steps per video frame of the learning film
  int tunnel_film_speed;  // and of the tunnel films (slower: the walls are the point)
  long walk_film_steps;   // steps of the walking videos, filmed in real time
  int landscape_windows;  // windows each combination of the landscape is measured over
  // Periods each working leg takes in the landscape; empty = the annealing's whole period set.
  std::span<const int> landscape_periods;
  // Periods-alone learning in the tunnel (tunnel --learn --steering off): trials per episode
  // and episodes at most.
  int periods_alone_max_trials;
  int periods_alone_max_episodes;
  // Seeds per scenario and learner of the learner benchmark.
  int benchmark_seeds;
  // Table 1 side by side walks every named body model (paper-sim and real) and this run's own
  // if it is neither; false: this run's body alone.
  bool tunnel_every_body;
};

// What a stage gets: the options, the sizes and the report folder.
struct StageContext {
  ReproduceOptions options;
  Sizes sizes;
  std::function<void(const std::string&)> progress;

  // out/<name>, created.
  std::filesystem::path dir(const std::string& name) const;
  // A path relative to index.html.
  std::string rel(const std::filesystem::path& file) const;
  std::string image(const FigureFiles& files) const { return rel(files.png); }
  // The experiment saved in out/experiments/<name> (resumable, runner.h).
  experiments::ExperimentSpec experiment(robot::RobotKind kind, const std::string& name,
                                         int runs) const;
};

struct Stage {
  std::string_view id;
  // The figures of figures.h's registry the stage draws (under their registry file names).
  std::vector<std::string_view> figures;
  Section (*run)(const StageContext&);
  // Stages whose saved results this one reads (it starts after them).
  std::vector<std::string_view> needs = {};
  // Started before the stages without it (in this table's order, once its needs are done): the
  // long stages and the stages they need, so that short stages fill the end.
  bool early = false;
};

// Every stage, in the report's order.
const std::vector<Stage>& reproduce_stages();
// Throws BadInput naming the known stages for an unknown id.
const Stage& stage_by_id(std::string_view id);

Section gaits_stage(const StageContext& ctx);
Section cpg_sync_stage(const StageContext& ctx);
Section walking_stage(const StageContext& ctx);
Section learning_r1_stage(const StageContext& ctx);
Section hexapod_table_stage(const StageContext& ctx);
Section quadruped_table_stage(const StageContext& ctx);
Section beta_stage(const StageContext& ctx);

// Fig. 14's claim, "β = 0 needs the most trials", judged on the median trials of each β, runs
// that ended without converging counted as cut at the trial cap (censored: they needed more).
// A median that falls on a cut run is only a lower bound; two such medians cannot be ordered,
// which makes the verdict `partly`. `text` says each β's median and how many runs were cut.
struct BetaMostTrials {
  Reproduced reproduced = Reproduced::no;
  std::string text;
};
BetaMostTrials beta_zero_most_trials(const std::vector<experiments::GroupSummary>& rows,
                                     int max_trials);
Section tunnel_stage(const StageContext& ctx);
Section landscape_stage(const StageContext& ctx);
Section calibration_stage(const StageContext& ctx);
Section learner_benchmark_stage(const StageContext& ctx);

// Leg names in morphology order (the figures' legend).
std::vector<std::string> leg_names(const robot::Morphology& morph);

}  // namespace multicpg::report
