// The landscape: every combination of the working legs' periods of the quadruped with
// L2 disabled, walked and measured, with where the quadruped table's learning runs ended. The
// ground truth against which learning is scored; the paper has no such figure.
#include "experiments/landscape.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/errors.h"
#include "common/table.h"
#include "experiments/runner.h"
#include "experiments/sweep.h"
#include "report/landscape_figure.h"
#include "report/stages/stage.h"
#include "robot/leg_sets.h"

namespace multicpg::report {
namespace {

// The scenario of the brute-force check (docs/learning.md): the quadruped's hardest (few
// combinations hold).
constexpr const char* kScenario = "L2";

// The periods every converged run of `scenario` in the experiment `dir` ended with.
std::vector<learning::Periods> learned_periods(const std::filesystem::path& dir,
                                               const std::string& scenario,
                                               const robot::Morphology& morph) {
  std::vector<learning::Periods> learned;
  for (const experiments::Task& task : experiments::tasks_of(experiments::read_sweep(dir).sweep)) {
    if (task.group != scenario) continue;
    const std::filesystem::path file = dir / "runs" / (task.key + ".json");
    const std::optional<nlohmann::json> run = experiments::read_sealed(file);
    if (!run) throw RuntimeFailure("'" + file.string() + "' is missing");
    const nlohmann::json& result = run->at("result");
    if (result.at("converged").get<bool>()) {
      learned.push_back(robot::period_map_from_json(morph, result.at("periods")));
    }
  }
  return learned;
}

}  // namespace

Section landscape_stage(const StageContext& ctx) {
  experiments::LandscapeSpec spec;
  spec.robot.kind = robot::RobotKind::quadruped;
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  spec.disabled = robot::parse_leg_set(morph, kScenario);
  spec.windows = ctx.sizes.landscape_windows;
  spec.robot.sim = ctx.options.sim;
  if (!ctx.sizes.landscape_periods.empty()) {
    spec.period_set.assign(ctx.sizes.landscape_periods.begin(), ctx.sizes.landscape_periods.end());
  }
  const std::vector<learning::Periods> converged =
      learned_periods(ctx.options.out / "experiments" / "quadruped", kScenario, morph);
  std::vector<learning::Periods> learned;
  for (const learning::Periods& p : converged) {
    if (experiments::in_landscape(spec, p)) learned.push_back(p);
  }
  const std::string folder = "experiments/landscape-quadruped-" + std::string(kScenario);
  const experiments::Landscape landscape = experiments::run_landscape(
      spec, ctx.dir(folder), ctx.options.jobs > 0 ? ctx.options.jobs : experiments::default_jobs(),
      ctx.options.progress, learned, "landscape");
  const FigureFiles figure = draw_landscape(landscape, learned, ctx.dir("figures"));

  const nlohmann::json summary = experiments::landscape_summary(landscape, learned);
  Table top{{{"rank"},
             {"periods", Align::left},
             {"worst deviation (deg)"},
             {"holds every window", Align::left},
             {"passes the paper's first window", Align::left}},
            {}};
  const std::vector<std::size_t> ranked = experiments::ranked_combinations(landscape);
  for (std::size_t r = 0; r < ranked.size() && r < experiments::kLandscapeTop; ++r) {
    const experiments::CombinationMeasure& m = landscape.combinations[ranked[r]];
    top.add_row({std::to_string(r + 1), robot::period_map_text(morph, m.periods, spec.disabled),
                 fixed(m.worst_deg, 2), m.holds ? "yes" : "no",
                 m.first_window_passes ? "yes" : "no"});
  }
  int learned_holding = 0;
  for (const nlohmann::json& l : summary.at("learned")) learned_holding += l.at("holds") ? 1 : 0;
  const std::optional<std::size_t> best = experiments::best_combination(landscape);
  const std::string threshold = fixed(spec.threshold_deg, 0) + "°";
  return {"landscape",
          "The landscape: quadruped, " + std::string(kScenario) + " disabled",
          "Not in the paper, which judges a combination by one 400-step window of yaw. Every "
          "combination of the working legs' periods, walked from a running robot, settled and "
          "measured over " +
              counted(spec.windows, "window") +
              " (yaw change and path angle): the truth against which learning is scored.",
          std::to_string(landscape.combinations.size()) + " combinations (each working leg at " +
              fmt::format("{}", fmt::join(spec.period_set, ", ")) + "; " +
              counted(spec.windows, "window") + " each): " +
              std::to_string(summary.at("holding").get<int>()) + " hold every window under " +
              threshold + ", " + std::to_string(summary.at("first_window_passing").get<int>()) +
              " pass the paper's first window. Best: " +
              (best ? robot::period_map_text(morph, landscape.combinations[*best].periods,
                                             spec.disabled) +
                          " (" + fixed(landscape.combinations[*best].worst_deg, 2) + "°)"
                    : std::string("none holds")) +
              ". The quadruped table's learning (paper mode) converged " +
              counted(static_cast<long>(converged.size()), "time") + " for " + kScenario + "; " +
              std::to_string(learned.size()) + " of its combinations lie in this map, " +
              std::to_string(learned_holding) + " of them hold every window.",
          {ctx.image(figure)},
          {},
          {folder + "/landscape.csv", folder + "/summary.json"},
          {top}};
}

}  // namespace multicpg::report
