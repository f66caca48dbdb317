// The learner benchmark's figure: report/figures.h's plot_learner_benchmark fed from
// experiments/learner_benchmark.h.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "experiments/learner_benchmark.h"
#include "report/figures.h"

namespace multicpg::report {

// Why `b` has no figure, or empty when it has one. The figure pools the scenarios where a
// combination holds; a selection with none has no share held to draw (benchmark.md has each
// scenario's runs).
std::string no_benchmark_figure(const experiments::LearnerBenchmark& b);

// Draws <out_dir>/<stem or benchmark-figure>.{png,svg,csv}: each learner's share held within
// the budget and its trials to a held combination, pooled over the scenarios where one holds.
// Without a figure (no_benchmark_figure) it draws none, removes those files if an earlier run
// left them (they would show another selection) and returns nothing.
std::optional<FigureFiles> draw_learner_benchmark(const experiments::LearnerBenchmark& b,
                                                  const std::filesystem::path& out_dir,
                                                  std::string_view stem = {});

}  // namespace multicpg::report
