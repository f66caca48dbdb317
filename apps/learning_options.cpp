#include "apps/learning_options.h"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "apps/flag_checks.h"
#include "common/errors.h"
#include "learning/choice_options.h"
#include "learning/default_learner.h"
#include "learning/learners.h"
#include "learning/number_options.h"

namespace multicpg::apps {

namespace {

const learning::NameOption& name_option(std::string_view flag) {
  for (const learning::NameOption& option : learning::kLearningNames) {
    if (option.flag == flag) return option;
  }
  throw std::logic_error("no learning option --" + std::string(flag));
}

}  // namespace

std::vector<std::string> mode_names() {
  return name_option("mode").names();
}

std::vector<std::string> steering_names() {
  return name_option("steering").names();
}

std::vector<std::string> learner_name_list() {
  std::vector<std::string> names;
  for (const learning::LearnerInfo& l : learning::learner_list()) names.emplace_back(l.name);
  return names;
}

namespace {

// One numeric learning option's flag, as learning/number_options.h declares it.
void add_number_flag(CLI::App& cmd, LearningFlags& f, const learning::LearningNumber& option) {
  std::visit(
      [&](const auto& n) {
        using T = typename std::decay_t<decltype(n)>::Value;
        auto& value = n.field(f.options);
        CLI::Option* flag = cmd.add_option("--" + std::string(n.flag), value, std::string(n.help))
                                ->check(in(n.limits));
        // A default worked out by the run (settle's) has none to show.
        if constexpr (!std::is_same_v<std::decay_t<decltype(value)>, std::optional<T>>) {
          flag->capture_default_str();
        }
        if (n.robust_only) flag->each([&f](const std::string&) { f.robust_only = true; });
      },
      option);
}

// "--steering, --hold-windows, ... and --no-period-learning": the flags of robust mode alone.
std::string robust_flags() {
  std::vector<std::string> flags;
  for (const learning::NameOption& option : learning::kLearningNames) {
    if (option.robust_only) flags.push_back("--" + std::string(option.flag));
  }
  for (const learning::LearningNumber& option : learning::kLearningNumbers) {
    std::visit(
        [&](const auto& n) {
          if (n.robust_only) flags.push_back("--" + std::string(n.flag));
        },
        option);
  }
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    if (option.robust_only) flags.push_back("--no-" + std::string(option.flag));
  }
  std::string out;
  for (std::size_t i = 0; i < flags.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == flags.size() ? " and " : ", ") + flags[i];
  }
  return out;
}

// One learning option set by a name, as learning/choice_options.h declares it.
void add_name_flag(CLI::App& cmd, LearningFlags& f, const learning::NameOption& option) {
  cmd.add_option_function<std::string>(
         "--" + std::string(option.flag),
         [&f, &option](const std::string& text) {
           option.set(f.options, text);
           if (option.robust_only) f.robust_only = true;
         },
         std::string(option.help))
      ->check(one_of(option.names(), std::string(option.flag)))
      ->default_str(std::string(option.get(f.options)));
}

// One switch, as --no-FLAG.
void add_switch_flag(CLI::App& cmd, LearningFlags& f, const learning::SwitchOption& option) {
  cmd.add_flag_callback(
      "--no-" + std::string(option.flag),
      [&f, &option] {
        option.field(f.options) = false;
        if (option.robust_only) f.robust_only = true;
      },
      std::string(option.help));
}

}  // namespace

void add_learning_flags(CLI::App& cmd, LearningFlags& f, bool with_beta) {
  learning::CompensationOptions& o = f.options;
  o.seed = 1;
  for (const learning::NameOption& option : learning::kLearningNames) {
    add_name_flag(cmd, f, option);
  }
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    add_switch_flag(cmd, f, option);
  }
  cmd.add_option("--learner", o.learner.name,
                 "which learner searches: " + learning::learner_names() +
                     " (default: the prior in robust mode where the robot's dataset is, else the "
                     "annealing; docs/learning.md \"Which learner a run uses\")")
      ->check(one_of(learner_name_list(), "learner"))
      ->each([&f](const std::string&) { f.learner_named = true; });
  cmd.add_option("--learner-option", f.learner_options,
                 "KEY=VALUE, one of the learner's options (repeatable; VALUE is read as JSON "
                 "when it is JSON, else as text), e.g. acquisition=ucb");
  if (with_beta) {
    cmd.add_option("--beta", f.beta,
                   "the annealing's factor: 0 random search, 10 greedy (its learner option beta)")
        ->check(in(learning::kBetaLimits))
        ->default_str(fmt::format("{}", learning::kDefaultBeta));
  }
  for (const learning::LearningNumber& option : learning::kLearningNumbers) {
    add_number_flag(cmd, f, option);
  }
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

learning::CompensationOptions learning_options(const LearningFlags& f,
                                               const experiments::RobotSpec& robot,
                                               const body::FaultTimeline& faults) {
  learning::CompensationOptions o = f.options;
  if (!f.learner_named) {
    o.learner.name = learning::default_learner(
                         {o, robot.kind, robot.file != nullptr, f.beta.has_value(), faults})
                         .name;
  }
  for (const std::string& item : f.learner_options) {
    auto [key, value] = learner_option(item, "--learner-option");
    if (o.learner.options.contains(key)) {
      throw BadInput("--learner-option: " + key + " is given twice");
    }
    o.learner.options[key] = std::move(value);
  }
  if (f.beta) {
    if (o.learner.name != learning::kPaperLearner) {
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
      throw BadInput(robust_flags() + " are robust-mode options");
    }
    o.steering = learning::Steering::off;  // recorded as it runs: paper mode never steers
  }
  return o;
}

}  // namespace multicpg::apps
