#include "experiments/tables.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/enum_names.h"
#include "common/errors.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "learning/compensation.h"
#include "robot/leg_sets.h"

namespace multicpg::experiments {
namespace {

constexpr auto kExperimentKindNames = enum_names<ExperimentKind>({{ExperimentKind::table, "table"},
                                                                  {ExperimentKind::beta, "beta"},
                                                                  {ExperimentKind::grid, "grid"}});

// Fixed decimals: degrees to 0.01, trials to 0.1, shares to 0.01.
constexpr int kDegreeDecimals = 2;
constexpr int kTrialDecimals = 1;
constexpr int kShareDecimals = 2;

std::string pm(const MeanSd& m, int decimals) {
  return mean_pm_sd(m.mean, m.sd, decimals);
}

// The learning result of `task`; a record that is not one is a damaged experiment.
learning::LearningResult read_result(const robot::Morphology& morph, const Task& task,
                                     const nlohmann::json& result) {
  try {
    return learning::result_from_json(result, morph);
  } catch (const BadInput& e) {
    throw RuntimeFailure("run " + task.key + ": " + e.what());
  }
}

std::string best_cell(const GroupSummary& row) {
  return row.best_periods.empty() ? "-"
                                  : row.best_periods + " (" + std::to_string(row.best_count) + ")";
}

}  // namespace

MeanSd mean_sd(const std::vector<double>& values) {
  MeanSd out;
  if (values.empty()) return out;
  double sum = 0.0;
  for (double v : values) sum += v;
  out.mean = sum / static_cast<double>(values.size());
  if (values.size() < 2) return out;
  double squares = 0.0;
  for (double v : values) squares += (v - out.mean) * (v - out.mean);
  out.sd = std::sqrt(squares / static_cast<double>(values.size() - 1));
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : (values[mid - 1] + values[mid]) / 2.0;
}

nlohmann::json to_json(const GroupSummary& r) {
  auto pair = [](const MeanSd& m) { return nlohmann::json{{"mean", m.mean}, {"sd", m.sd}}; };
  return {{"group", r.group},
          {"runs", r.runs},
          {"converged", r.converged},
          {"no_deviation", r.no_deviation},
          {"initial_deviation_deg", pair(r.initial_deviation_deg)},
          {"final_deviation_deg", pair(r.final_deviation_deg)},
          {"trials", pair(r.trials)},
          {"median_trials", r.median_trials},
          {"within_paper_trials", r.within_paper_trials},
          {"best_periods", r.best_periods},
          {"best_count", r.best_count}};
}

GroupSummary group_summary_from_json(const nlohmann::json& j) {
  auto pair = [](const nlohmann::json& m) {
    return MeanSd{m.at("mean").get<double>(), m.at("sd").get<double>()};
  };
  GroupSummary r;
  r.group = j.at("group").get<std::string>();
  r.runs = j.at("runs").get<int>();
  r.converged = j.at("converged").get<int>();
  r.no_deviation = j.at("no_deviation").get<int>();
  r.initial_deviation_deg = pair(j.at("initial_deviation_deg"));
  r.final_deviation_deg = pair(j.at("final_deviation_deg"));
  r.trials = pair(j.at("trials"));
  r.median_trials = j.at("median_trials").get<double>();
  r.within_paper_trials = j.at("within_paper_trials").get<int>();
  r.best_periods = j.at("best_periods").get<std::string>();
  r.best_count = j.at("best_count").get<int>();
  return r;
}

double GroupSummary::share_converged() const {
  return runs > 0 ? static_cast<double>(converged) / runs : 0.0;
}

std::vector<GroupSummary> summarize(const robot::Morphology& morph, const std::vector<Task>& tasks,
                                    const std::vector<nlohmann::json>& results) {
  if (results.size() != tasks.size()) {
    throw RuntimeFailure("expected " + std::to_string(tasks.size()) + " results, got " +
                         std::to_string(results.size()));
  }
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::size_t>> members;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    auto [it, fresh] = members.try_emplace(tasks[i].group);
    if (fresh) order.push_back(tasks[i].group);
    it->second.push_back(i);
  }
  std::vector<GroupSummary> rows;
  for (const std::string& group : order) {
    GroupSummary row;
    row.group = group;
    std::vector<double> initial;
    std::vector<double> deviations;
    std::vector<double> trials;
    std::map<std::string, int> finals;  // ordered, so the first maximum is alphabetically first
    for (std::size_t i : members[group]) {
      const learning::LearningResult r = read_result(morph, tasks[i], results[i]);
      ++row.runs;
      initial.push_back(r.initial_deviation_deg);
      deviations.push_back(r.final_deviation_deg);
      trials.push_back(r.trials);
      if (r.outcome == learning::Outcome::no_deviation) ++row.no_deviation;
      if (r.converged()) {
        ++row.converged;
        if (r.trials <= paper::kMostTrials) ++row.within_paper_trials;
        const robot::LegSet disabled = robot::leg_set_from_json(morph, results[i].at("disabled"));
        ++finals[robot::period_map_text(morph, r.periods, disabled)];
      }
    }
    row.initial_deviation_deg = mean_sd(initial);
    row.final_deviation_deg = mean_sd(deviations);
    row.trials = mean_sd(trials);
    row.median_trials = median(trials);
    for (const auto& [periods, count] : finals) {
      if (count > row.best_count) {
        row.best_periods = periods;
        row.best_count = count;
      }
    }
    rows.push_back(row);
  }
  return rows;
}

Table scenario_data(const std::vector<GroupSummary>& rows, const std::string& group_title) {
  Table t{{{group_title}}, {}};
  for (const char* title :
       {"runs", "converged", "no_deviation", "share_converged", "final_deviation_mean_deg",
        "final_deviation_sd_deg", "trials_mean", "trials_sd", "best_periods", "best_count"}) {
    t.columns.push_back({title});
  }
  for (const GroupSummary& r : rows) {
    t.add_row({r.group, std::to_string(r.runs), std::to_string(r.converged),
               std::to_string(r.no_deviation), fixed(r.share_converged(), kShareDecimals),
               fixed(r.final_deviation_deg.mean, kDegreeDecimals),
               fixed(r.final_deviation_deg.sd, kDegreeDecimals),
               fixed(r.trials.mean, kTrialDecimals), fixed(r.trials.sd, kTrialDecimals),
               r.best_periods, std::to_string(r.best_count)});
  }
  return t;
}

Table scenario_table(const std::vector<GroupSummary>& rows, const std::string& group_title) {
  Table t{{{group_title, Align::left},
           {"Runs"},
           {"Converged (share)"},
           {"No deviation"},
           {"Final deviation (deg), mean ± SD"},
           {"Trials, mean ± SD"},
           {"Most frequent combination (runs)", Align::left}},
          {}};
  for (const GroupSummary& r : rows) {
    t.add_row({r.group, std::to_string(r.runs), fixed(r.share_converged(), kShareDecimals),
               std::to_string(r.no_deviation), pm(r.final_deviation_deg, kDegreeDecimals),
               pm(r.trials, kTrialDecimals), best_cell(r)});
  }
  return t;
}

Table beta_data(const std::vector<GroupSummary>& rows) {
  Table t;
  for (const char* title : {"beta", "runs", "converged", "share_converged", "trials_mean",
                            "trials_sd", "final_deviation_mean_deg", "final_deviation_sd_deg"}) {
    t.columns.push_back({title});
  }
  for (const GroupSummary& r : rows) {
    t.add_row({r.group, std::to_string(r.runs), std::to_string(r.converged),
               fixed(r.share_converged(), kShareDecimals), fixed(r.trials.mean, kTrialDecimals),
               fixed(r.trials.sd, kTrialDecimals),
               fixed(r.final_deviation_deg.mean, kDegreeDecimals),
               fixed(r.final_deviation_deg.sd, kDegreeDecimals)});
  }
  return t;
}

Table beta_table(const std::vector<GroupSummary>& rows) {
  Table t{{{"beta"},
           {"Runs"},
           {"Converged (share)"},
           {"Trials, mean ± SD"},
           {"Final deviation (deg), mean ± SD"}},
          {}};
  for (const GroupSummary& r : rows) {
    t.add_row({r.group, std::to_string(r.runs), fixed(r.share_converged(), kShareDecimals),
               pm(r.trials, kTrialDecimals), pm(r.final_deviation_deg, kDegreeDecimals)});
  }
  return t;
}

std::string_view to_string(ExperimentKind kind) {
  return kExperimentKindNames.name(kind);
}

ExperimentKind parse_experiment_kind(std::string_view text) {
  if (const std::optional<ExperimentKind> kind = kExperimentKindNames.find(text)) return *kind;
  throw BadInput("unknown experiment '" + std::string(text) + "' (" +
                 kExperimentKindNames.list(" or ") + ")");
}

}  // namespace multicpg::experiments
