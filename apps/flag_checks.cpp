#include "apps/flag_checks.h"

#include "experiments/experiment_limits.h"

namespace multicpg::apps {

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
