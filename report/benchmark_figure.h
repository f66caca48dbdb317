// The learner benchmark's figure: report/figures.h's plot_learner_benchmark fed from
// experiments/learner_benchmark.h.
#pragma once

#include <filesystem>
#include <string_view>

#include "experiments/learner_benchmark.h"
#include "report/figures.h"

namespace multicpg::report {

// Draws <out_dir>/<stem or benchmark-figure>.{png,svg,csv}: each learner's share held within
// the budget and its trials to a held combination, pooled over the scenarios where one holds.
FigureFiles draw_learner_benchmark(const experiments::LearnerBenchmark& b,
                                   const std::filesystem::path& out_dir,
                                   std::string_view stem = {});

}  // namespace multicpg::report
