#include "apps/flag_checks.h"

#include <algorithm>
#include <utility>

#include "common/user_text.h"
#include "experiments/experiment_limits.h"
#include "robot/morphology.h"
#include "sim/robot_file.h"

namespace multicpg::apps {

CLI::Validator one_of(std::vector<std::string> names, std::string what) {
  return CLI::Validator(
      [names = std::move(names), what = std::move(what)](std::string& text) -> std::string {
        if (std::find(names.begin(), names.end(), text) != names.end()) return {};
        return unknown_name(what, text, names);
      },
      "");
}

CLI::Validator robot_name() {
  const CLI::Validator builtin = one_of(robot::kRobotKindNames.names(), "robot");
  return CLI::Validator(
      [builtin](std::string& text) -> std::string {
        if (sim::is_robot_file(text)) return {};
        std::string checked = text;
        const std::string error = builtin(checked);
        return error.empty() ? error : error + "; or a robot file, FILE.toml";
      },
      "");
}

void add_max_runs_flag(CLI::App& cmd, std::int64_t& max_runs) {
  cmd.add_option("--max-runs", max_runs,
                 "refuse an experiment of more runs (grid points x scenarios x runs, or a "
                 "landscape's combinations): each holds about 9 kB of options while it runs")
      ->check(in(experiments::kMaxRunsLimits))
      ->capture_default_str();
}

void require_for_options_from(CLI::App& cmd, std::size_t first, CLI::Option* needed) {
  const std::vector<CLI::Option*> options = cmd.get_options();
  for (std::size_t i = first; i < options.size(); ++i) options[i]->needs(needed);
}

void refuse_empty_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size() > 0) option->check(kNotEmpty);
  }
  for (CLI::App* sub : app.get_subcommands({})) refuse_empty_values(*sub);
}

}  // namespace multicpg::apps
