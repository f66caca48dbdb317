// The figures (figures.h): their registry and one plot function per figure.
#include "report/figures.h"

#include <algorithm>
#include <cmath>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/table.h"
#include "common/user_text.h"
#include "report/figure_drawing.h"

namespace multicpg::report {
namespace fs = std::filesystem;

using namespace drawing;

namespace {

constexpr std::array<FigureInfo, 12> kFigures{{
    {"gait", "fig02-gaits", "gait.gp", 1200, 900,
     "Fig. 2: gait diagrams for p = 1, 4, 5, 6, 8, 9 (blue = stance, white = swing)"},
    {"cpg-sync", "fig06-cpg-sync", "cpg_sync.gp", 1200, 700,
     "Fig. 6: master and client CPG outputs, synchronised and free"},
    {"learning-trace", "fig08-learning-trace", "learning_trace.gp", 1000, 550,
     "Fig. 8: deviation per trial of one learning run"},
    {"motor", "fig09-motor", "motor_outputs.gp", 1200, 1000,
     "Fig. 9: the 18 motor outputs after learning"},
    {"contacts", "fig10-contacts", "foot_contacts.gp", 1200, 800,
     "Fig. 10: foot contact signals of the legs"},
    {"learning-hexapod", "fig11-hexapod", "learning_summary.gp", 1200, 800,
     "Fig. 11: learning results per disabled-leg scenario, hexapod"},
    {"learning-quadruped", "fig13-quadruped", "learning_summary.gp", 900, 800,
     "Fig. 13: learning results per disabled leg, quadruped"},
    {"beta", "fig14-beta", "beta_study.gp", 1000, 600,
     "Fig. 14: trials to converge for each annealing factor beta"},
    {"trunk-path", "trunk-path-r1", "trunk_path.gp", 1000, 700,
     "Trunk path seen from above, R1 disabled, before and after learning"},
    {"landscape", "landscape-map", "landscape.gp", 1200, 700,
     "Landscape: worst deviation of every combination of working-leg periods"},
    {"calibration", "calibration-sensitivity", "calibration.gp", 1100, 650,
     "Calibration: which body parameter moves which Table 1 number (rank correlation)"},
    {"learner-benchmark", "benchmark-figure", "learner_benchmark.gp", 1000, 750,
     "Learners replayed on landscapes: share held within the budget and trials to hold"},
}};

void require_step(double step_seconds, std::string_view figure) {
  require(step_seconds > 0.0, figure, "step duration must be positive");
}

// Gait names of paper §2.1 (docs/controller.md "Gaits").
std::string gait_name(int period) {
  switch (period) {
    case 1:
      return "stop";
    case 4:
      return "tripod";
    case 5:
      return "tetrapod";
    case 6:
      return "transition";
    case 8:
      return "fast wave";
    case 9:
      return "slow wave";
    default:
      return "";
  }
}

}  // namespace

std::span<const FigureInfo> known_figures() {
  return kFigures;
}

const FigureInfo& figure_by_name(std::string_view name) {
  for (const FigureInfo& f : kFigures) {
    if (f.name == name) return f;
  }
  std::vector<std::string> known;
  for (const FigureInfo& f : kFigures) known.emplace_back(f.name);
  throw BadInput(unknown_name("figure", name, known));
}

FigureFiles plot_gait_diagrams(const std::vector<GaitPanel>& panels,
                               const std::vector<std::string>& legs, double step_seconds,
                               const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("gait");
  require(!panels.empty(), info.name, "no gait panels");
  require_step(step_seconds, info.name);
  ensure_writable_dir(out_dir);
  // Stance runs as intervals [start, end) in steps.
  Csv csv({"period", "leg", "row", "stance_start_step", "stance_end_step"});
  Params params;
  std::size_t steps = 0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const GaitPanel& panel = panels[i];
    require_rows(panel.swing, legs, info.name);
    steps = std::max(steps, panel.swing.size());
    for (std::size_t leg = 0; leg < legs.size(); ++leg) {
      for (const auto& [start, end] : runs_of(panel.swing, leg, false)) {
        csv.row({std::to_string(panel.period), legs[leg], std::to_string(leg),
                 std::to_string(start), std::to_string(end)});
      }
    }
    const std::string gait = gait_name(panel.period);
    params.num("period" + std::to_string(i + 1), panel.period)
        .text("title" + std::to_string(i + 1),
              "p = " + std::to_string(panel.period) + (gait.empty() ? "" : ": " + gait));
  }
  params.num("panels", static_cast<double>(panels.size()))
      .num("steps", static_cast<double>(steps))
      .num("step_seconds", step_seconds)
      .text("legs", join(legs));
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_cpg_sync(const std::vector<CpgPairPoint>& synchronised,
                          const std::vector<CpgPairPoint>& independent, int master_period,
                          int client_period, const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("cpg-sync");
  require(!synchronised.empty() && synchronised.size() == independent.size(), info.name,
          "need two equally long non-empty traces");
  ensure_writable_dir(out_dir);
  Csv csv({"step", "sync_master_x1", "sync_master_x2", "sync_client_x1", "sync_client_x2",
           "free_master_x1", "free_master_x2", "free_client_x1", "free_client_x2"});
  for (std::size_t t = 0; t < synchronised.size(); ++t) {
    const CpgPairPoint& s = synchronised[t];
    const CpgPairPoint& f = independent[t];
    csv.row({std::to_string(t), shortest(s.master_x1), shortest(s.master_x2), shortest(s.client_x1),
             shortest(s.client_x2), shortest(f.master_x1), shortest(f.master_x2),
             shortest(f.client_x1), shortest(f.client_x2)});
  }
  Params params;
  params.num("master_period", master_period).num("client_period", client_period);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_learning_trace(const std::vector<TrialPoint>& trials,
                                const std::vector<std::string>& legs, double threshold_deg,
                                const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("learning-trace");
  require(!trials.empty(), info.name, "no trials");
  require(threshold_deg > 0.0, info.name, "threshold must be positive");
  ensure_writable_dir(out_dir);
  std::vector<std::string> header{"trial", "deviation_deg", "accepted", "reference_deg", "change"};
  header.insert(header.end(), legs.begin(), legs.end());
  Csv csv(header);
  // reference_deg: E_ref; change: the legs whose period differs from the combination accepted so
  // far (docs/learning.md "Candidates").
  const std::vector<double> references = reference_deviations(trials);
  std::vector<int> accepted = trials.front().periods;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const TrialPoint& trial = trials[i];
    require(trial.periods.size() == legs.size(), info.name,
            "trial " + std::to_string(trial.trial) + " has " +
                std::to_string(trial.periods.size()) + " periods, expected " +
                std::to_string(legs.size()));
    std::string change;
    for (std::size_t leg = 0; leg < legs.size(); ++leg) {
      if (trial.periods[leg] == accepted[leg]) continue;
      if (!change.empty()) change += ' ';
      change += legs[leg] + "=" + std::to_string(trial.periods[leg]);
    }
    if (trial.accepted) accepted = trial.periods;
    std::vector<std::string> row{std::to_string(trial.trial), shortest(trial.deviation_deg),
                                 trial.accepted ? "1" : "0", shortest(references[i]), change};
    for (int p : trial.periods) row.push_back(std::to_string(p));
    csv.row(row);
  }
  Params params;
  params.num("threshold", threshold_deg);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_motor_outputs(const MotorTrace& motor, const std::vector<std::string>& legs,
                               const std::vector<std::string>& notes, double step_seconds,
                               const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("motor");
  require_rows(motor, legs, info.name);
  require(notes.empty() || notes.size() == legs.size(), info.name, "need one note per leg or none");
  require_step(step_seconds, info.name);
  ensure_writable_dir(out_dir);
  std::vector<std::string> header{"step", "time_s"};
  for (const auto& leg : legs) {
    for (const char* joint : {"TC", "CTr", "FTi"}) header.push_back(leg + "_" + joint);
  }
  Csv csv(header);
  for (std::size_t t = 0; t < motor.size(); ++t) {
    std::vector<std::string> row{std::to_string(t),
                                 shortest(static_cast<double>(t) * step_seconds)};
    for (const auto& joints : motor[t]) {
      for (double m : joints) row.push_back(shortest(m));
    }
    csv.row(row);
  }
  Params params;
  params.text("legs", join(legs)).num("step_seconds", step_seconds);
  for (std::size_t leg = 0; leg < legs.size(); ++leg) {
    const std::string note = notes.empty() ? "" : notes[leg];
    params.text("title" + std::to_string(leg + 1),
                "Leg " + legs[leg] + (note.empty() ? "" : ": " + note));
  }
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_foot_contacts(const std::vector<std::vector<bool>>& contact,
                               const std::vector<std::string>& legs, double step_seconds,
                               const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("contacts");
  require_rows(contact, legs, info.name);
  require_step(step_seconds, info.name);
  ensure_writable_dir(out_dir);
  std::vector<std::string> header{"step", "time_s"};
  header.insert(header.end(), legs.begin(), legs.end());
  Csv csv(header);
  for (std::size_t t = 0; t < contact.size(); ++t) {
    std::vector<std::string> row{std::to_string(t),
                                 shortest(static_cast<double>(t) * step_seconds)};
    for (bool c : contact[t]) row.push_back(c ? "1" : "0");
    csv.row(row);
  }
  Params params;
  params.text("legs", join(legs)).num("step_seconds", step_seconds);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_learning_summary(const std::vector<ScenarioSummary>& scenarios,
                                  std::string_view robot, double threshold_deg,
                                  const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("learning-" + std::string(robot));
  require(!scenarios.empty(), info.name, "no scenarios");
  require(threshold_deg > 0.0, info.name, "threshold must be positive");
  ensure_writable_dir(out_dir);
  Csv csv({"scenario", "mean_trials", "sd_trials", "mean_deviation_deg", "sd_deviation_deg",
           "share_converged", "label"});
  for (const ScenarioSummary& s : scenarios) {
    require(s.share_converged >= 0.0 && s.share_converged <= 1.0, info.name,
            "share converged of " + s.scenario + " is outside 0..1");
    const std::string label =
        s.no_deviation ? "n/d" : std::to_string(std::lround(100.0 * s.share_converged)) + "%";
    csv.row({s.scenario, shortest(s.mean_trials), shortest(s.sd_trials),
             shortest(s.mean_deviation_deg), shortest(s.sd_deviation_deg),
             shortest(s.share_converged), label});
  }
  Params params;
  params.text("robot", robot).num("threshold", threshold_deg);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_beta_study(const std::vector<BetaSummary>& betas, std::string_view disabled_legs,
                            const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("beta");
  require(!betas.empty(), info.name, "no beta values");
  ensure_writable_dir(out_dir);
  Csv csv({"beta", "mean_trials", "sd_trials", "share_converged"});
  for (const BetaSummary& b : betas) {
    require(b.beta >= 0.0, info.name, "beta must not be negative");
    csv.row({shortest(b.beta), shortest(b.mean_trials), shortest(b.sd_trials),
             shortest(b.share_converged)});
  }
  Params params;
  params.text("disabled_legs", disabled_legs);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_learner_benchmark(const std::vector<LearnerScore>& learners,
                                   const LearnerBenchmarkSetting& setting, const fs::path& out_dir,
                                   std::string_view stem) {
  const FigureInfo& info = figure_by_name("learner-benchmark");
  require(!learners.empty(), info.name, "no learners");
  require(setting.budget > 0, info.name, "the budget must be positive");
  ensure_writable_dir(out_dir);
  // The trials axis: twice the budget, or the largest median when it is larger, so that no bar is
  // cut; a whisker past it ends at it, and each label gives the numbers themselves.
  double cut = 2.0 * setting.budget;
  for (const LearnerScore& l : learners) {
    if (l.median_trials) cut = std::max(cut, *l.median_trials);
  }
  const auto text = [](const std::optional<double>& v) {
    return v ? fixed(*v, 0) : std::string("never");
  };
  // Every row has a label at a finite height: gnuplot 5.4 crashes on a label plot with no point.
  Csv csv({"learner", "share_held", "share_low", "share_high", "share_label", "bar_trials",
           "whisker_low", "whisker_high", "trials_label", "trials_label_y"});
  for (const LearnerScore& l : learners) {
    require(l.share_low <= l.share_held && l.share_held <= l.share_high, info.name,
            l.name + ": the share lies outside its interval");
    const double high = std::min(l.q3_trials.value_or(cut), cut);
    csv.row({l.name, shortest(l.share_held), shortest(l.share_low), shortest(l.share_high),
             std::to_string(std::lround(100.0 * l.share_held)) + "%",
             l.median_trials ? shortest(*l.median_trials) : "NaN",
             shortest(std::min(l.q1_trials.value_or(cut), cut)), shortest(high),
             text(l.median_trials) + " (" + text(l.q1_trials) + "–" + text(l.q3_trials) + ")",
             shortest(l.median_trials ? high : 0.0)});
  }
  Params params;
  params.text("robot", setting.robot)
      .num("budget", setting.budget)
      .text("replayed", counted(setting.scenarios, "scenario") + " where a combination holds x " +
                            counted(setting.seeds, "seed"))
      .num("cut", cut);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_trunk_paths(const TrunkPaths& paths, const fs::path& out_dir,
                             std::string_view stem) {
  const FigureInfo& info = figure_by_name("trunk-path");
  require(!paths.before.empty() || !paths.after.empty(), info.name, "no path points");
  ensure_writable_dir(out_dir);
  // One block per polyline, blocks separated by a blank line so gnuplot breaks the line there.
  Csv csv({"series", "x_m", "y_m"});
  const auto block = [&csv](const std::string& series, const std::vector<Point2>& points) {
    for (const Point2& p : points) csv.row({series, shortest(p.x), shortest(p.y)});
    csv.gap();
  };
  block("before", paths.before);
  block("after", paths.after);
  for (const auto& wall : paths.walls) block("wall", wall);
  Params params;
  params.text("before_label", paths.before_label).text("after_label", paths.after_label);
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_landscape(const std::vector<LandscapePoint>& points, std::string_view title,
                           double threshold_deg, const fs::path& out_dir, std::string_view stem) {
  const FigureInfo& info = figure_by_name("landscape");
  require(!points.empty(), info.name, "no combinations");
  require(threshold_deg > 0.0, info.name, "threshold must be positive");
  std::size_t windows = 0;
  for (const LandscapePoint& p : points) windows = std::max(windows, p.window_worst_deg.size());
  require(windows > 0, info.name, "no windows");
  ensure_writable_dir(out_dir);
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a].worst_deg < points[b].worst_deg;
  });
  std::vector<std::string> header{"rank", "worst_deg", "holds", "first_window_passes",
                                  "best", "learned",   "label"};
  for (std::size_t w = 1; w <= windows; ++w) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "w" + std::to_string(w).
    std::string column = "w";
    column += std::to_string(w);
    column += "_worst_deg";
    header.push_back(std::move(column));
  }
  Csv csv(header);
  std::size_t holding = 0;
  std::size_t first = 0;
  std::size_t learned = 0;
  std::size_t learned_holding = 0;
  for (std::size_t r = 0; r < order.size(); ++r) {
    const LandscapePoint& p = points[order[r]];
    require(!p.window_worst_deg.empty(), info.name, p.label + " has no window");
    holding += p.holds ? 1 : 0;
    first += p.first_window_passes ? 1 : 0;
    learned += static_cast<std::size_t>(p.learned);
    learned_holding += p.holds ? static_cast<std::size_t>(p.learned) : 0;
    std::vector<std::string> row{std::to_string(r + 1),
                                 shortest(p.worst_deg),
                                 p.holds ? "1" : "0",
                                 p.first_window_passes ? "1" : "0",
                                 p.best ? "1" : "0",
                                 std::to_string(p.learned),
                                 p.label};
    for (double d : p.window_worst_deg) row.push_back(shortest(d));
    // A window not walked (after the first over the threshold): gnuplot skips NaN.
    row.resize(header.size(), "NaN");
    csv.row(row);
  }
  const auto percent = [&](std::size_t n) {
    return std::to_string(
               std::lround(100.0 * static_cast<double>(n) / static_cast<double>(points.size()))) +
           "%";
  };
  std::string subtitle = std::to_string(points.size()) +
                         " combinations: " + std::to_string(holding) + " (" + percent(holding) +
                         ") hold in every window, " + percent(first) +
                         " pass the first window (|yaw| only)";
  if (learned > 0) {
    subtitle += "; learned: " + std::to_string(learned_holding) + " of " + std::to_string(learned) +
                " hold";
  }
  Params params;
  params.text("title", std::string(title))
      .text("subtitle", subtitle)
      .num("threshold", threshold_deg)
      .num("windows", static_cast<double>(windows))
      .num("count", static_cast<double>(points.size()))
      .num("learned", static_cast<double>(learned));
  return draw(info, out_dir, stem, csv, params);
}

FigureFiles plot_calibration(const CalibrationMap& map, const fs::path& out_dir,
                             std::string_view stem) {
  const FigureInfo& info = figure_by_name("calibration");
  require(!map.params.empty() && !map.numbers.empty(), info.name, "nothing to draw");
  require(map.rho.size() == map.params.size(), info.name, "one row of rho per parameter");
  ensure_writable_dir(out_dir);
  Csv csv({"x", "y", "rho", "parameter", "number"});
  for (std::size_t p = 0; p < map.params.size(); ++p) {
    require(map.rho[p].size() == map.numbers.size(), info.name,
            map.params[p] + " has " + std::to_string(map.rho[p].size()) + " values, expected " +
                std::to_string(map.numbers.size()));
    for (std::size_t n = 0; n < map.numbers.size(); ++n) {
      csv.row({std::to_string(n), std::to_string(p), shortest(map.rho[p][n]), map.params[p],
               map.numbers[n]});
    }
  }
  // gnuplot tic lists: "label" position, ...
  const auto tics = [](const std::vector<std::string>& labels) {
    std::string out;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (i > 0) out += ", ";
      out += '"';
      out += labels[i];
      out += "\" ";
      out += std::to_string(i);
    }
    return out;
  };
  Params params;
  params.text("title", map.title)
      .text("subtitle", map.subtitle)
      .text("xtics_list", tics(map.numbers))
      .text("ytics_list", tics(map.params))
      .num("nx", static_cast<double>(map.numbers.size()))
      .num("ny", static_cast<double>(map.params.size()));
  return draw(info, out_dir, stem, csv, params);
}

}  // namespace multicpg::report
