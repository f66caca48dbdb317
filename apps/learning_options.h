// Flags shared by `learn`, `experiment`, `tunnel --learn` and `render --learn`: the learning
// options of paper §3 and docs/learning.md, bound directly to learning::CompensationOptions.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiments/run_robot.h"
#include "learning/compensation.h"
#include "sim/stepper.h"

namespace multicpg::apps {

struct LearningFlags {
  learning::CompensationOptions options;  // every flag writes its field here
  bool robust_only = false;  // a robust-mode flag (--steering, --hold-windows, ...) was given
  std::vector<std::string> learner_options;  // --learner-option KEY=VALUE, repeatable
  std::optional<double> beta;  // --beta: the annealing's option beta (learning/learners.h)
  bool learner_named = false;  // --learner was given; else the run's default (default_learner)
};

// The names each choice of the learning options takes, for one_of (apps/flag_checks.h): the
// modes (robust, paper), the steering (reflex, off) and the learners (learning/learners.h).
std::vector<std::string> mode_names();
std::vector<std::string> steering_names();
std::vector<std::string> learner_name_list();

// Adds --mode --steering --no-period-learning (learning/choice_options.h) --learner
// --learner-option --beta, the numeric options (learning/number_options.h: --hold-windows
// --monitor-windows --threshold --window --settle --max-trials --max-episodes --step-budget) and
// --seed, each
// range shown in --help and checked at parse time (without --beta when `with_beta` is false: the
// beta study sets it per run).
void add_learning_flags(CLI::App& cmd, LearningFlags& flags, bool with_beta = true);

// One "KEY=VALUE" of `flag` (--learner-option): the key and the value, read as JSON when it is
// JSON (numbers, true, ...) and as text otherwise. Throws BadInput naming `flag` when there is no
// key or no '='.
std::pair<std::string, nlohmann::json> learner_option(const std::string& item,
                                                      const std::string& flag);

// The options the flags give for a run of `robot` under `faults` (checked with the run,
// experiments::validate; the learner's options as given, resolved by learning::resolve_learner;
// without --learner the run's default, learning::default_learner). Throws BadInput (one line)
// for robust-mode flags in paper mode or a --learner-option that is not KEY=VALUE.
learning::CompensationOptions learning_options(const LearningFlags& flags,
                                               const experiments::RobotSpec& robot,
                                               const body::FaultTimeline& faults);

}  // namespace multicpg::apps
