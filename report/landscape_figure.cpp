#include "report/landscape_figure.h"

#include <algorithm>
#include <optional>

#include "experiments/scenarios.h"
#include "robot/leg_sets.h"

namespace multicpg::report {

FigureFiles draw_landscape(const experiments::Landscape& landscape,
                           const std::vector<learning::Periods>& learned,
                           const std::filesystem::path& out_dir) {
  const experiments::LandscapeSpec& spec = landscape.spec;
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  const std::optional<std::size_t> best = experiments::best_combination(landscape);
  const learning::Criterion criterion = learning::criterion(experiments::landscape_options(spec));
  std::vector<LandscapePoint> points;
  for (std::size_t i = 0; i < landscape.combinations.size(); ++i) {
    const experiments::CombinationMeasure& m = landscape.combinations[i];
    LandscapePoint p{robot::period_map_text(morph, m.periods, spec.disabled),
                     {},
                     m.worst_deg,
                     m.holds,
                     m.first_window_passes};
    for (const body::WindowMeasure& w : m.windows) p.window_worst_deg.push_back(criterion.error(w));
    p.best = best == i;
    p.learned = static_cast<int>(std::count(learned.begin(), learned.end(), m.periods));
    points.push_back(std::move(p));
  }
  const std::string title =
      morph.name + ", " +
      (spec.disabled.empty() ? std::string("no leg") : robot::leg_set_name(morph, spec.disabled)) +
      " disabled";
  return plot_landscape(points, title, spec.threshold_deg, out_dir);
}

}  // namespace multicpg::report
