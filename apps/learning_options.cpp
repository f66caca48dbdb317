#include "apps/learning_options.h"

#include <fmt/format.h>

#include <string>

#include "apps/flag_checks.h"
#include "common/errors.h"
#include "learning/learners.h"

namespace multicpg::apps {

std::vector<std::string> mode_names() {
  return {std::string(learning::to_string(learning::Mode::robust)),
          std::string(learning::to_string(learning::Mode::paper))};
}

std::vector<std::string> steering_names() {
  return {std::string(learning::to_string(learning::Steering::reflex)),
          std::string(learning::to_string(learning::Steering::off))};
}

std::vector<std::string> learner_name_list() {
  std::vector<std::string> names;
  for (const learning::LearnerInfo& l : learning::learner_list()) names.emplace_back(l.name);
  return names;
}

void add_learning_flags(CLI::App& cmd, LearningFlags& f, bool with_beta) {
  learning::CompensationOptions& o = f.options;
  o.seed = 1;
  const auto robust_only = [&f](const std::string&) { f.robust_only = true; };
  cmd.add_option_function<std::string>(
         "--mode", [&o](const std::string& text) { o.mode = learning::parse_mode(text); },
         "robust (yaw and path angle, several windows to accept, monitoring, steering) "
         "or paper (paper §3 exactly: one window, yaw only)")
      ->check(one_of(mode_names(), "mode"))
      ->default_str(std::string(learning::to_string(o.mode)));
  cmd.add_option("--learner", o.learner.name,
                 "which learner searches: " + learning::learner_names() +
                     " (docs/learning.md \"Learners\")")
      ->check(one_of(learner_name_list(), "learner"))
      ->capture_default_str();
  cmd.add_option("--learner-option", f.learner_options,
                 "KEY=VALUE, one of the learner's options (repeatable; VALUE is read as JSON "
                 "when it is JSON, else as text), e.g. acquisition=ucb");
  cmd.add_option_function<std::string>(
         "--steering",
         [&f](const std::string& text) {
           f.options.steering = learning::parse_steering(text);
           f.robust_only = true;
         },
         "robust mode: reflex (orientation reflex on the VRN steering inputs) or off")
      ->check(one_of(steering_names(), "steering"))
      ->default_str(std::string(learning::to_string(o.steering)));
  cmd.add_option("--hold-windows", o.hold_windows,
                 "robust mode: consecutive windows a combination must hold")
      ->check(in(learning::kHoldWindowsLimits))
      ->capture_default_str()
      ->each(robust_only);
  cmd.add_option("--monitor-windows", o.monitor_windows,
                 "robust mode: clean windows after the last fault or episode before the run ends")
      ->check(in(learning::kMonitorWindowsLimits))
      ->capture_default_str()
      ->each(robust_only);
  cmd.add_flag_callback(
      "--no-period-learning",
      [&f] {
        f.options.learn_periods = false;
        f.robust_only = true;
      },
      "robust mode: keep the periods, compensate by steering alone");
  if (with_beta) {
    cmd.add_option("--beta", f.beta,
                   "the annealing's factor: 0 random search, 10 greedy (its learner option beta)")
        ->check(in(learning::kBetaLimits))
        ->default_str(fmt::format("{}", learning::kDefaultBeta));
  }
  cmd.add_option("--threshold", o.search.threshold_deg,
                 "deviation (deg) below which learning stops")
      ->check(in(learning::kThresholdLimits))
      ->capture_default_str();
  cmd.add_option("--window", o.window_steps, "steps per measured window")
      ->check(in(learning::kWindowStepsLimits))
      ->capture_default_str();
  cmd.add_option("--settle", o.settle_steps,
                 "unmeasured steps after each period change (default: slowest CPG lock + "
                 "longest delay, 337 for the hexapod; robust mode: 863)")
      ->check(in(learning::kSettleStepsLimits));
  cmd.add_option("--max-trials", o.search.max_trials,
                 "trials an episode may take before it ends 'not converged'")
      ->check(in(learning::kMaxTrialsLimits))
      ->capture_default_str();
  cmd.add_option("--max-episodes", o.max_episodes,
                 "robust mode: episodes (detection, then learning) before the run ends 'episode "
                 "cap reached'")
      ->check(in(learning::kMaxEpisodesLimits))
      ->capture_default_str()
      ->each(robust_only);
  cmd.add_option("--step-budget", o.step_budget,
                 "controller steps the run may spend in trials, over all its episodes, before it "
                 "ends 'budget reached' (docs/learning.md \"Step budget\")")
      ->check(in(learning::kStepBudgetLimits))
      ->capture_default_str();
  cmd.add_option("--seed", o.seed, "seed of the run's random generator")
      ->check(seed_value())
      ->capture_default_str();
}

std::pair<std::string, nlohmann::json> learner_option(const std::string& item,
                                                      const std::string& flag) {
  const std::size_t eq = item.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw BadInput(flag + ": expected KEY=VALUE, got '" + item + "'");
  }
  const std::string value = item.substr(eq + 1);
  const nlohmann::json parsed = nlohmann::json::parse(value, nullptr, /*allow_exceptions=*/false);
  return {item.substr(0, eq), parsed.is_discarded() ? nlohmann::json(value) : parsed};
}

learning::CompensationOptions learning_options(const LearningFlags& f) {
  learning::CompensationOptions o = f.options;
  for (const std::string& item : f.learner_options) {
    auto [key, value] = learner_option(item, "--learner-option");
    if (o.learner.options.contains(key)) {
      throw BadInput("--learner-option: " + key + " is given twice");
    }
    o.learner.options[key] = std::move(value);
  }
  if (f.beta) {
    if (o.learner.name != learning::kDefaultLearner) {
      throw BadInput("--beta: the annealing's option; --learner " + o.learner.name +
                     " has no beta");
    }
    if (o.learner.options.contains("beta")) {
      throw BadInput("--beta: given twice (also as --learner-option beta=...)");
    }
    o.learner.options["beta"] = *f.beta;
  }
  if (o.mode == learning::Mode::paper) {
    if (f.robust_only) {
      throw BadInput(
          "--steering, --hold-windows, --monitor-windows, --max-episodes and --no-period-learning "
          "are "
          "robust-mode options");
    }
    o.steering = learning::Steering::off;  // recorded as it runs: paper mode never steers
  }
  return o;
}

}  // namespace multicpg::apps
