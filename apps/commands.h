// Subcommands of the multicpg CLI. Each register_* adds one subcommand whose callback does the
// work; errors are thrown as BadInput (exit 2) or RuntimeFailure (exit 1) and reported by main.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "experiments/landscape.h"

namespace multicpg::apps {

void register_gait(CLI::App& app);
void register_cpg(CLI::App& app);
void register_view(CLI::App& app);
void register_walk(CLI::App& app);
void register_model(CLI::App& app);
void register_learn(CLI::App& app);
void register_experiment(CLI::App& app);
void register_render(CLI::App& app);
void register_tunnel(CLI::App& app);
void register_reproduce(CLI::App& app);
void register_figure(CLI::App& app);
void register_landscape(CLI::App& app);
void register_learner_benchmark(CLI::App& app);
void register_calibrate(CLI::App& app);
void register_run(CLI::App& app);  // run, rerun, merge
void register_emulate(CLI::App& app);
void register_replay(CLI::App& app);

// Walks the landscapes in OUT (resumable), draws their maps and prints what holds: `landscape`
// and `run` of a kind = "landscape" file. One landscape fills OUT; several (a dataset) each fill
// OUT/<scenario>, and their dataset goes to OUT/landscapes.{csv.gz,json}.
void run_landscapes_and_report(const std::vector<experiments::LandscapeSpec>& specs,
                               const std::string& out, int jobs,
                               const std::vector<learning::Periods>& learned = {});

}  // namespace multicpg::apps
