#include "report/benchmark_figure.h"

#include <string>
#include <system_error>
#include <vector>

#include "common/table.h"
#include "robot/morphology.h"

namespace multicpg::report {

std::string no_benchmark_figure(const experiments::LearnerBenchmark& b) {
  if (experiments::holding_scenarios(b) > 0) return {};
  return "none of the " +
         counted(static_cast<long>(experiments::benchmark_scenarios(b)), "scenario") +
         " has a combination that holds, so no run can be held (benchmark.md lists each one)";
}

std::optional<FigureFiles> draw_learner_benchmark(const experiments::LearnerBenchmark& b,
                                                  const std::filesystem::path& out_dir,
                                                  std::string_view stem) {
  if (!no_benchmark_figure(b).empty()) {
    const std::string name(stem.empty() ? figure_by_name("learner-benchmark").stem : stem);
    for (const char* ext : {".png", ".svg", ".csv"}) {
      std::error_code ec;
      std::filesystem::remove(out_dir / (name + ext), ec);
    }
    return std::nullopt;
  }
  const nlohmann::json summary = experiments::benchmark_summary(b);
  const auto optional_number = [](const nlohmann::json& v) {
    return v.is_null() ? std::nullopt : std::optional<double>(v.get<double>());
  };
  std::vector<LearnerScore> scores;
  for (const nlohmann::json& l : summary.at("learners")) {
    scores.push_back({experiments::benchmark_label(l), l.at("share_held"), l.at("share_low"),
                      l.at("share_high"), optional_number(l.at("q1_trials")),
                      optional_number(l.at("median_trials")), optional_number(l.at("q3_trials"))});
  }
  return plot_learner_benchmark(scores,
                                {std::string(robot::to_string(b.dataset.robot)), b.spec.budget,
                                 static_cast<int>(experiments::holding_scenarios(b)), b.spec.seeds},
                                out_dir, stem);
}

}  // namespace multicpg::report
