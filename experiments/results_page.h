// docs/results.md: our experiment tables beside what the paper states. Generated from
// the experiments' summaries, never typed by hand; differences are said plainly.
#pragma once

#include <optional>
#include <string>

#include "experiments/learning_experiments.h"

namespace multicpg::experiments {

struct ResultsInputs {
  std::optional<ExperimentTable> hexapod;
  std::optional<ExperimentTable> quadruped;
  std::optional<ExperimentTable> beta;
  std::string command;  // the command line that made the page, quoted at its top
};

std::string results_markdown(const ResultsInputs& inputs);

}  // namespace multicpg::experiments
