#include "report/figures.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/table.h"
#include "report/subprocess.h"

namespace multicpg::report {
namespace fs = std::filesystem;

namespace {

constexpr const char* kGnuplot = "gnuplot";
// Installed layout: <prefix>/bin/multicpg and <prefix>/share/multicpg/gnuplot.
constexpr const char* kInstalledScripts = "../share/multicpg/gnuplot";
constexpr const char* kFont = "DejaVu Sans,11";

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

// --- CSV -------------------------------------------------------------------------------------

class Csv {
 public:
  explicit Csv(const std::vector<std::string>& header) { row(header); }
  void row(const std::vector<std::string>& fields) { text_ += csv_line(fields); }
  // A blank line: gnuplot starts a new line segment there (used between polylines).
  void gap() { text_ += '\n'; }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// --- gnuplot ---------------------------------------------------------------------------------

// gnuplot single-quoted string: a quote is written twice.
std::string gp_string(std::string_view text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

fs::path scripts_dir() {
  const fs::path source(MULTICPG_GNUPLOT_SOURCE_DIR);
  if (fs::is_directory(source)) return source;
  std::error_code ec;
  const fs::path installed =
      fs::read_symlink("/proc/self/exe", ec).parent_path() / kInstalledScripts;
  if (!ec && fs::is_directory(installed)) return installed.lexically_normal();
  throw RuntimeFailure("gnuplot scripts not found in " + source.string() +
                       " nor next to the program");
}

// Parameters handed to a script as gnuplot variables.
class Params {
 public:
  Params& text(const std::string& name, std::string_view value) {
    code_ += name + "=" + gp_string(value) + "; ";
    return *this;
  }
  Params& num(const std::string& name, double value) {
    code_ += name + "=" + shortest(value) + "; ";
    return *this;
  }
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

std::string temp_name(const fs::path& path) {
  return path.string() + ".tmp" + std::to_string(::getpid());
}

// Runs one script for one terminal into a temporary file, then moves it into place.
void run_gnuplot(const fs::path& script, const std::string& terminal, const Params& params,
                 const fs::path& out) {
  const std::string tmp = temp_name(out);
  const std::string preamble = terminal + "; set output " + gp_string(tmp) + "; " + params.code();
  const ProcessResult result = run_process({kGnuplot, "-e", preamble, script.string()});
  std::error_code ec;
  if (result.exit_code != 0 || !fs::exists(tmp) || fs::file_size(tmp, ec) == 0) {
    fs::remove(tmp, ec);
    throw RuntimeFailure("gnuplot " + script.filename().string() + " failed: " +
                         (result.exit_code == 0 ? "wrote no picture (" + tool_error(result) + ")"
                                                : tool_error(result)));
  }
  fs::rename(tmp, out, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw RuntimeFailure("cannot move '" + tmp + "' into place: " + why);
  }
}

FigureFiles draw(const FigureInfo& info, const fs::path& out_dir, std::string_view stem,
                 const Csv& csv, Params params) {
  const std::string name(stem.empty() ? info.stem : stem);
  FigureFiles files{out_dir / (name + ".png"), out_dir / (name + ".svg"),
                    out_dir / (name + ".csv")};
  write_file_atomic(files.csv, csv.text());
  const fs::path dir = scripts_dir();
  params.text("data", files.csv.string()).text("dir", (dir / "").string());
  const fs::path script = dir / info.script;
  const std::string size =
      " size " + std::to_string(info.width) + "," + std::to_string(info.height);
  const std::string look = " enhanced font " + gp_string(kFont) + " background rgb 'white'";
  run_gnuplot(script, "set terminal pngcairo" + size + look, params, files.png);
  run_gnuplot(script, "set terminal svg" + size + look, params, files.svg);
  return files;
}

// --- input checks ----------------------------------------------------------------------------

void require(bool ok, std::string_view figure, const std::string& what) {
  if (!ok) throw BadInput(std::string(figure) + ": " + what);
}

// Every row of `table` has one entry per leg.
template <class Row>
void require_rows(const std::vector<Row>& table, const std::vector<std::string>& legs,
                  std::string_view figure) {
  require(!legs.empty(), figure, "no legs");
  require(!table.empty(), figure, "no steps");
  for (std::size_t t = 0; t < table.size(); ++t) {
    require(table[t].size() == legs.size(), figure,
            "step " + std::to_string(t) + " has " + std::to_string(table[t].size()) +
                " legs, expected " + std::to_string(legs.size()));
  }
}

void require_step(double step_seconds, std::string_view figure) {
  require(step_seconds > 0.0, figure, "step duration must be positive");
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ' ';
    out += w;
  }
  return out;
}

// The runs [start, end) of steps where table[step][leg] == value: one box per run draws without
// seams.
std::vector<std::pair<std::size_t, std::size_t>> runs_of(
    const std::vector<std::vector<bool>>& table, std::size_t leg, bool value) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  std::size_t t = 0;
  while (t < table.size()) {
    if (table[t][leg] != value) {
      ++t;
      continue;
    }
    const std::size_t start = t;
    while (t < table.size() && table[t][leg] == value) ++t;
    runs.emplace_back(start, t);
  }
  return runs;
}

// E_ref of each trial: the deviation of the combination accepted so far (trial 0, the detection
// window, is accepted by definition; docs/learning.md "Candidates").
std::vector<double> reference_deviations(const std::vector<TrialPoint>& trials) {
  std::vector<double> out;
  double reference = trials.empty() ? 0.0 : trials.front().deviation_deg;
  for (const TrialPoint& trial : trials) {
    if (trial.accepted) reference = trial.deviation_deg;
    out.push_back(reference);
  }
  return out;
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
  std::string known;
  for (const FigureInfo& f : kFigures) {
    if (!known.empty()) known += ", ";
    known += f.name;
  }
  throw BadInput("unknown figure '" + std::string(name) + "' (known: " + known + ")");
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
  ensure_writable_dir(out_dir);
  // A quartile that does not exist (more than that share never held) is NaN: no bar drawn.
  const auto cell = [](const std::optional<double>& v) { return v ? shortest(*v) : "NaN"; };
  Csv csv({"learner", "share_held", "share_low", "share_high", "q1_trials", "median_trials",
           "q3_trials"});
  for (const LearnerScore& l : learners) {
    require(l.share_low <= l.share_held && l.share_held <= l.share_high, info.name,
            l.name + ": the share lies outside its interval");
    csv.row({l.name, shortest(l.share_held), shortest(l.share_low), shortest(l.share_high),
             cell(l.q1_trials), cell(l.median_trials), cell(l.q3_trials)});
  }
  Params params;
  params.text("robot", setting.robot)
      .num("budget", setting.budget)
      .num("scenarios", setting.scenarios)
      .num("seeds", setting.seeds);
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
  const std::size_t windows = points.front().window_worst_deg.size();
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
    require(p.window_worst_deg.size() == windows, info.name,
            p.label + " has " + std::to_string(p.window_worst_deg.size()) + " windows, expected " +
                std::to_string(windows));
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

namespace {

// The run picture's size: wide enough for the tunnel's 3 m beside its key; one panel taller
// with the learning trace.
constexpr int kPictureWidth = 1100;
constexpr int kPictureHeight = 850;
constexpr int kPictureTraceHeight = 400;
// Points of the trunk path drawn at most: a long run is thinned evenly (its last point kept),
// so gnuplot reads a small file whatever the run's length.
constexpr std::size_t kPicturePathPoints = 4000;

// A folder of its own under the system's temporary folder, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "multicpg-plot-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw RuntimeFailure("cannot make a temporary folder for the plot's data under " +
                           fs::temp_directory_path().string());
    }
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

void check_run_picture_path(const fs::path& png) {
  if (png.extension() != ".png") {
    throw BadInput("cannot plot to '" + png.string() + "': the file type must be .png");
  }
  require_writable_file(png);
}

void plot_run_picture(const RunPicture& picture, const fs::path& png) {
  constexpr std::string_view name = "run picture";
  check_run_picture_path(png);
  require(!picture.path.empty(), name, "no trunk path");
  require(picture.trials.empty() || picture.threshold_deg > 0.0, name,
          "threshold must be positive");
  require_rows(picture.contact, picture.legs, name);
  const TempDir data;

  Csv path({"series", "x_m", "y_m"});
  const std::size_t stride = (picture.path.size() + kPicturePathPoints - 1) / kPicturePathPoints;
  for (std::size_t i = 0; i < picture.path.size(); ++i) {
    if (i % stride != 0 && i + 1 != picture.path.size()) continue;
    path.row({"path", shortest(picture.path[i].x), shortest(picture.path[i].y)});
  }
  path.gap();
  const auto block = [&path](const std::string& series, const std::vector<Point2>& points) {
    for (const Point2& p : points) path.row({series, shortest(p.x), shortest(p.y)});
    path.gap();
  };
  for (const auto& wall : picture.walls) block("wall", wall);
  if (!picture.course.empty()) block("course", picture.course);
  write_file_atomic(data.path() / "path.csv", path.text());

  Csv trace({"trial", "deviation_deg", "accepted", "reference_deg"});
  const std::vector<double> references = reference_deviations(picture.trials);
  for (std::size_t i = 0; i < picture.trials.size(); ++i) {
    const TrialPoint& t = picture.trials[i];
    trace.row({std::to_string(t.trial), shortest(t.deviation_deg), t.accepted ? "1" : "0",
               shortest(references[i])});
  }
  write_file_atomic(data.path() / "trace.csv", trace.text());

  Csv gait({"leg", "row", "stance_start_step", "stance_end_step"});
  const long first = picture.first_contact_step;
  for (std::size_t leg = 0; leg < picture.legs.size(); ++leg) {
    for (const auto& [start, end] : runs_of(picture.contact, leg, true)) {
      gait.row({picture.legs[leg], std::to_string(leg),
                std::to_string(first + static_cast<long>(start)),
                std::to_string(first + static_cast<long>(end))});
    }
  }
  write_file_atomic(data.path() / "gait.csv", gait.text());

  const fs::path dir = scripts_dir();
  Params params;
  params.text("dir", (dir / "").string())
      .text("path", (data.path() / "path.csv").string())
      .text("trace", (data.path() / "trace.csv").string())
      .text("gait", (data.path() / "gait.csv").string())
      .text("title", picture.title)
      .num("has_walls", picture.walls.empty() ? 0 : 1)
      .num("has_course", picture.course.empty() ? 0 : 1)
      .num("has_trace", picture.trials.empty() ? 0 : 1)
      .num("threshold", picture.threshold_deg)
      .text("legs", join(picture.legs))
      .num("first_step", static_cast<double>(first))
      .num("last_step", static_cast<double>(first + static_cast<long>(picture.contact.size())));
  const int height = kPictureHeight + (picture.trials.empty() ? 0 : kPictureTraceHeight);
  run_gnuplot(dir / "run_picture.gp",
              "set terminal pngcairo size " + std::to_string(kPictureWidth) + "," +
                  std::to_string(height) + " enhanced font " + gp_string(kFont) +
                  " background rgb 'white'",
              params, png);
}

}  // namespace multicpg::report
