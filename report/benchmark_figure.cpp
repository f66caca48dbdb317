#include "report/benchmark_figure.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::report {

FigureFiles draw_learner_benchmark(const experiments::LearnerBenchmark& b,
                                   const std::filesystem::path& out_dir, std::string_view stem) {
  const nlohmann::json summary = experiments::benchmark_summary(b);
  const auto optional_number = [](const nlohmann::json& v) {
    return v.is_null() ? std::nullopt : std::optional<double>(v.get<double>());
  };
  std::vector<LearnerScore> scores;
  for (const nlohmann::json& l : summary.at("learners")) {
    scores.push_back({l.at("learner").at("name").get<std::string>(), l.at("share_held"),
                      l.at("share_low"), l.at("share_high"), optional_number(l.at("q1_trials")),
                      optional_number(l.at("median_trials")), optional_number(l.at("q3_trials"))});
  }
  std::set<std::string> holding;
  for (const experiments::BenchmarkCell& c : b.cells) {
    if (c.holding > 0) holding.insert(c.scenario);
  }
  return plot_learner_benchmark(scores,
                                {std::string(robot::to_string(b.dataset.robot)), b.spec.budget,
                                 static_cast<int>(holding.size()), b.spec.seeds},
                                out_dir, stem);
}

}  // namespace multicpg::report
