#include "report/reproduce.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/cpg_pair.h"
#include "experiments/gait.h"
#include "experiments/learning_experiments.h"
#include "experiments/learning_run.h"
#include "experiments/results_page.h"
#include "experiments/scenarios.h"
#include "experiments/tunnel.h"
#include "report/figures.h"
#include "report/film.h"
#include "report/html.h"

namespace multicpg::report {
namespace {

namespace fs = std::filesystem;
using robot::RobotKind;

// Runs per experiment: the paper's (SPEC §8) or, with --quick, a few.
struct Sizes {
  int hexapod_runs, quadruped_runs, beta_runs;
  int film_speed;         // controller steps per video frame of the learning film
  int tunnel_film_speed;  // and of the tunnel films (slower: the walls are the point)
  long walk_film_steps;   // steps of the walking videos, filmed in real time
};
constexpr Sizes kFull{
    experiments::kScenarioRuns, experiments::kScenarioRuns, experiments::kBetaRuns, 4, 2, 400};
constexpr Sizes kQuick{1, 2, 3, 8, 4, 160};
// The tunnel films look down the corridor from behind the robot, far enough to see both walls.
const CameraSpec kTunnelCamera{"trunk", 2.5, 0.0, -45.0, {}};

// Steps walked with the learned periods after learning, for Figs. 9 and 10 and the path.
constexpr long kAfterLearningSteps = 400;
// Steps shown in Figs. 9 and 10: a little over one cycle of the slowest learned period (p = 9).
constexpr long kMotorFigureSteps = 180;
// Walk of each period for the speed table, and of the paths before and after learning.
constexpr long kSpeedWalkSteps = 1200;
const std::vector<int> kGaitFigurePeriods{1, 4, 5, 6, 8, 9};
// Fig. 6: master p = 5, client p = 6 (paper §2.3).
constexpr int kFig6Master = 5;
constexpr int kFig6Client = 6;
constexpr long kFig6Steps = 3000;
constexpr long kFig6Shown = 60;  // the last steps, once both orbits have locked
// Tunnel scenarios and the combinations the paper learned for them (paper §5, reference §5.4).
struct TunnelScenario {
  std::string name;
  std::string paper_periods;                 // "R2=4 L1=6 ..."
  double paper_before_deg, paper_after_deg;  // Table 1
};
const std::vector<TunnelScenario> kTunnelScenarios{{"R1", "R2=5 R3=4 L1=5 L2=6 L3=5", 42.0, 7.97},
                                                   {"R1+R3", "R2=4 L1=6 L2=4 L3=9", 21.0, 0.95},
                                                   {"R1+R3+L2", "R2=4 L1=4 L3=9", 23.0, 2.67}};

std::string num(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::vector<std::string> leg_names(const robot::Morphology& morph) {
  std::vector<std::string> out;
  for (const robot::Leg& leg : morph.legs) out.push_back(leg.name);
  return out;
}

// "R2=4 L1=6" on top of all-4 periods.
std::vector<int> parse_periods_text(const robot::Morphology& morph, const std::string& text) {
  std::vector<int> periods(morph.size(), learning::kStartPeriod);
  std::istringstream in(text);
  std::string item;
  while (in >> item) {
    const std::size_t eq = item.find('=');
    periods[robot::leg_index(morph, item.substr(0, eq))] = std::stoi(item.substr(eq + 1));
  }
  return periods;
}

std::string rel(const fs::path& file, const fs::path& root) {
  return fs::relative(file, root).generic_string();
}

class Reproduction {
 public:
  explicit Reproduction(const ReproduceOptions& o)
      : o_(o), sizes_(o.quick ? kQuick : kFull), start_(std::chrono::steady_clock::now()) {}

  void run() {
    ensure_writable_dir(o_.out);
    check_arguments();
    const std::map<std::string, std::function<Section()>> make{
        {"gaits", [&] { return gaits(); }},
        {"cpg-sync", [&] { return cpg_sync(); }},
        {"walking", [&] { return walking(); }},
        {"learning-r1", [&] { return learning_r1(); }},
        {"hexapod-table", [&] { return scenario_table(RobotKind::hexapod); }},
        {"quadruped-table", [&] { return scenario_table(RobotKind::quadruped); }},
        {"beta", [&] { return beta(); }},
        {"tunnel", [&] { return tunnel(); }},
    };
    std::vector<std::string> stages;
    for (const std::string& id : reproduce_stages()) {
      if (o_.only.empty() || std::find(o_.only.begin(), o_.only.end(), id) != o_.only.end()) {
        stages.push_back(id);
      }
    }
    std::vector<Section> sections;
    for (std::size_t i = 0; i < stages.size(); ++i) {
      const std::string& id = stages[i];
      const fs::path saved = o_.out / "sections" / (id + ".json");
      progress("[" + std::to_string(i + 1) + "/" + std::to_string(stages.size()) + "] " + id);
      if (fs::exists(saved)) {
        std::ifstream in(saved);
        sections.push_back(section_from_json(nlohmann::json::parse(in)));
        progress("  already done");
        continue;
      }
      sections.push_back(make.at(id)());
      ensure_writable_dir(saved.parent_path());
      write_file_atomic(saved, to_json(sections.back()).dump(2) + "\n");
    }
    write_results_page();
    write_file_atomic(o_.out / "index.html",
                      index_html("multicpg: the paper reproduced", intro(), sections));
    progress("wrote " + (o_.out / "index.html").string());
  }

 private:
  std::string intro() const {
    return std::string(
               "Ren et al., \"Multiple chaotic central pattern generators with learning "
               "for legged locomotion and malfunction compensation\", Information "
               "Sciences 2015, reproduced with multicpg in MuJoCo") +
           (o_.quick ? " (quick run: few learning runs per experiment, faster videos)" : "") +
           ". Each section says what the paper reports and what we measured; every figure has "
           "its SVG and the CSV behind it. Tables of the experiments: results.md.";
  }

  void progress(const std::string& line) const {
    if (!o_.progress) return;
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::cerr << "reproduce " << num(s, 0) << " s: " << line << "\n";
  }

  // A folder made with other options is not resumed (the sections would not match).
  void check_arguments() const {
    const nlohmann::json args{{"quick", o_.quick}, {"seed", o_.seed}};
    const fs::path file = o_.out / "reproduce.json";
    if (fs::exists(file)) {
      std::ifstream in(file);
      nlohmann::json old;
      try {
        old = nlohmann::json::parse(in);
      } catch (const nlohmann::json::exception&) {
        throw BadInput("'" + file.string() + "' is not a reproduce record");
      }
      if (old != args) {
        throw BadInput("'" + o_.out.string() + "' holds a reproduction made with other options (" +
                       old.dump() + "); use another --out");
      }
      return;
    }
    write_file_atomic(file, args.dump() + "\n");
  }

  const sim::SimModel& model(RobotKind kind, bool tunnel = false) {
    const int key = static_cast<int>(kind) * 2 + (tunnel ? 1 : 0);
    auto it = models_.find(key);
    if (it == models_.end()) {
      sim::SimOptions options;
      options.scene.tunnel = tunnel;
      it = models_.emplace(key, std::make_unique<sim::SimModel>(sim::make_sim_model(kind, options)))
               .first;
    }
    return *it->second;
  }

  fs::path dir(const std::string& name) const {
    const fs::path d = o_.out / name;
    ensure_writable_dir(d);
    return d;
  }

  std::string image(const FigureFiles& f) const { return rel(f.png, o_.out); }

  Section gaits() {
    const neural::ControllerModel controller = neural::make_controller_model(RobotKind::hexapod);
    std::vector<GaitPanel> panels;
    std::string fractions;
    constexpr long kShownCycles = 2;
    constexpr long kSlowestCycle = 9 * (2 * 9 + 1);  // p = 9: 171 steps (reference §2.4)
    for (int p : kGaitFigurePeriods) {
      neural::ControllerState state = neural::make_controller_state(controller, p);
      const long steps = kShownCycles * kSlowestCycle;
      const experiments::GaitRecord g =
          experiments::record_gait(controller, state, experiments::kDefaultGaitWarmup, steps);
      panels.push_back({p, g.swing});
      fractions += (fractions.empty() ? "" : ", ") + std::string("p") + std::to_string(p) + " " +
                   num(experiments::swing_fractions(g).front(), 3);
    }
    const FigureFiles f = plot_gait_diagrams(panels, leg_names(controller.morphology),
                                             sim::kDefaultControlDt, dir("figures"), "fig02-gaits");
    return {"gaits",
            "Gaits for each period (Fig. 2)",
            "Periods 9, 8, 6, 5, 4 give the slow wave, fast wave, transition, tetrapod and tripod "
            "gaits; p = 1 stops with all legs on the ground. One step ≈ 0.037 s.",
            "Swing fraction of every leg = 1/p (" + fractions +
                "); p = 4 is an exact tripod (R1, R3, L2 against R2, L1, L3); p = 1 holds every "
                "joint constant (τ = 18, τ_L = 90, the authors' code).",
            {image(f)},
            {},
            {},
            {}};
  }

  Section cpg_sync() {
    auto pair = [&](bool synchronised) {
      experiments::CpgPairOptions o;
      o.master_period = kFig6Master;
      o.client_period = kFig6Client;
      o.synchronised = synchronised;
      o.steps = kFig6Steps;
      const auto samples = experiments::run_cpg_pair(neural::CpgParams{}, o);
      std::vector<CpgPairPoint> out;
      for (auto it = samples.end() - kFig6Shown; it != samples.end(); ++it) {
        out.push_back({it->master_x1, it->master_x2, it->client_x1, it->client_x2});
      }
      return out;
    };
    const auto synced = pair(true);
    const auto free = pair(false);
    std::vector<double> client;
    for (const auto& p : free) client.push_back(p.client_x1);
    bool identical = true;
    for (const auto& p : synced) identical = identical && p.client_x1 == p.master_x1;
    const FigureFiles f =
        plot_cpg_sync(synced, free, kFig6Master, kFig6Client, dir("figures"), "fig06-cpg-sync");
    return {"cpg-sync",
            "Master and client CPG in and out of synchrony (Fig. 6)",
            "Master period 5, client period 6: synchronised, the client's output is the "
            "master's; desynchronised, each oscillates with its own period.",
            std::string("Synchronised (α = 1): client x1 ") +
                (identical ? "identical to the master's bit for bit" : "NOT identical") +
                ". Desynchronised: the client settles to a period-" +
                std::to_string(experiments::orbit_period(client, neural::kMaxPeriod, 30)) +
                " orbit, the master to period 5.",
            {image(f)},
            {},
            {},
            {}};
  }

  Section walking() {
    const sim::SimModel& hexapod = model(RobotKind::hexapod);
    Table speeds{{"period", "gait", "distance (m)", "speed (cm/s)",
                  "largest |deviation| per 400 "
                  "steps (deg)"},
                 {}};
    const std::map<int, std::string> names{{1, "stop"},       {4, "tripod"},    {5, "tetrapod"},
                                           {6, "transition"}, {8, "fast wave"}, {9, "slow wave"}};
    for (int p : kGaitFigurePeriods) {
      sim::WalkSpec spec;
      spec.periods.assign(hexapod.legs.size(), p);
      spec.controller_warmup = sim::kControllerWarmup;
      spec.steps = kSpeedWalkSteps;
      spec.record = false;
      const sim::WalkResult r = sim::walk(hexapod, spec);
      double worst = 0.0;
      for (double d : r.window_deviations_deg) worst = std::max(worst, std::abs(d));
      speeds.rows.push_back({std::to_string(p), names.at(p), num(r.distance_m, 3),
                             num(100.0 * r.speed_m_s, 2), num(worst, 2)});
    }
    const fs::path videos = dir("videos");
    std::vector<std::string> films;
    for (bool broken : {false, true}) {
      const fs::path out = videos / (broken ? "walk-r1-disabled.mp4" : "walk-tripod.mp4");
      Film film(hexapod, {out, kDefaultFrameWidth, kDefaultFrameHeight, 1, {}});
      sim::WalkSpec spec;
      spec.steps = sizes_.walk_film_steps;
      spec.controller_warmup = sim::kControllerWarmup;
      spec.record = false;
      if (broken) spec.disabled = {0};
      spec.on_step = [&](const sim::SimState& s) { film.capture(s); };
      sim::walk(hexapod, spec);
      film.finish();
      films.push_back(rel(out, o_.out));
    }
    return {"walking",
            "Walking with all legs, and with R1 disabled",
            "With all legs working the robot walks straight; with p = 4, 5, 6, 8, 9 it walks "
            "with the tripod ... slow wave gait, slower as p grows. With R1 disabled and all "
            "periods 4 it turns right (≈38° per 400 steps in the paper's simulator, 42° on the "
            "real robot).",
            "Speeds of each gait over " + std::to_string(kSpeedWalkSteps) +
                " steps, the controller warmed up for " + std::to_string(sim::kControllerWarmup) +
                " steps first so the robot starts in its gait (table). Videos: the tripod, and "
                "R1 disabled from the start (R1 drawn red), real time.",
            {},
            films,
            {},
            {speeds}};
  }

  Section learning_r1() {
    const sim::SimModel& hexapod = model(RobotKind::hexapod);
    const robot::Morphology& morph = hexapod.controller.morphology;
    learning::CompensationOptions options;
    options.disabled = {robot::leg_index(morph, "R1")};
    // R1 fails as the first measured window starts, after the robot walked healthy while its
    // CPGs settled: that window's deviation is the paper's "after 400 time steps" (§4.1).
    options.fail_step = learning::default_settle_steps(hexapod.controller);
    options.seed = o_.seed;
    const fs::path video = dir("videos") / "learning-r1.mp4";
    Film film(hexapod, {video, kDefaultFrameWidth, kDefaultFrameHeight, sizes_.film_speed, {}});
    const experiments::LearningRun run = experiments::run_learning(
        hexapod, options, /*record=*/true, kAfterLearningSteps, film_learning(film));
    film.finish();
    const learning::LearningResult& r = run.result;

    // Fig. 8: the trace, trial 0 = the window that detected the deviation.
    std::vector<TrialPoint> points{
        {0, r.initial_deviation_deg, true, std::vector<int>(morph.size(), 4)}};
    Table trace{{"trial"}, {}};
    for (const robot::Leg& leg : morph.legs) trace.header.push_back(leg.name);
    trace.header.insert(trace.header.end(), {"deviation (deg)", "decision"});
    auto trace_row = [&](int trial_no, const std::vector<int>& periods, double e,
                         const std::string& decision) {
      std::vector<std::string> row{std::to_string(trial_no)};
      for (std::size_t i = 0; i < periods.size(); ++i) {
        const bool off = std::find(options.disabled.begin(), options.disabled.end(), i) !=
                         options.disabled.end();
        row.push_back(std::to_string(periods[i]) + (off ? " (disabled)" : ""));
      }
      row.push_back(num(e, 2));
      row.push_back(decision);
      trace.rows.push_back(row);
    };
    trace_row(0, points.front().periods, r.initial_deviation_deg, "deviation detected");
    for (const learning::TrialRecord& t : r.trace) {
      points.push_back({t.trial, t.deviation_deg, t.accepted, t.periods});
      trace_row(t.trial, t.periods, t.deviation_deg, t.accepted ? "kept" : "rejected");
    }
    const fs::path figures = dir("figures");
    const FigureFiles fig8 = plot_learning_trace(
        points, leg_names(morph), options.annealing.threshold_deg, figures, "fig08-learning-trace");

    // Figs. 9 and 10: the last steps, walking with the learned periods.
    const sim::WalkRecord& rec = run.record;
    const std::size_t legs = morph.size();
    const std::size_t end = rec.rows();
    const std::size_t begin = end - static_cast<std::size_t>(kMotorFigureSteps);
    MotorTrace motor;
    std::vector<std::vector<bool>> contact;
    for (std::size_t row = begin; row < end; ++row) {
      std::vector<std::array<double, 3>> m(legs);
      std::vector<bool> c(legs);
      for (std::size_t leg = 0; leg < legs; ++leg) {
        for (std::size_t j = 0; j < 3; ++j) m[leg][j] = rec.command[(row * legs + leg) * 3 + j];
        c[leg] = rec.contact[row * legs + leg] != 0;
      }
      motor.push_back(m);
      contact.push_back(c);
    }
    std::vector<std::string> notes;
    int r1_touches = 0;
    for (std::size_t leg = 0; leg < legs; ++leg) {
      notes.push_back(leg == 0 ? "disabled" : "p" + std::to_string(r.periods[leg]));
    }
    for (const auto& c : contact) r1_touches += c[0] ? 1 : 0;
    const FigureFiles fig9 = plot_motor_outputs(motor, leg_names(morph), notes, hexapod.control_dt,
                                                figures, "fig09-motor");
    const FigureFiles fig10 = plot_foot_contacts(contact, leg_names(morph), hexapod.control_dt,
                                                 figures, "fig10-contacts");

    // The trunk's path from above, R1 disabled: all periods 4 versus the learned ones.
    TrunkPaths paths;
    for (bool learned : {false, true}) {
      sim::WalkSpec spec;
      spec.periods = learned ? r.periods : std::vector<int>(legs, 4);
      spec.disabled = options.disabled;
      spec.steps = kSpeedWalkSteps;
      spec.controller_warmup = sim::kControllerWarmup;
      spec.record = false;
      const sim::WalkResult w = sim::walk(hexapod, spec);
      auto& path = learned ? paths.after : paths.before;
      for (std::size_t i = 0; i < w.record.rows(); ++i)
        path.push_back({w.record.x[i], w.record.y[i]});
    }
    paths.before_label = "all periods 4";
    paths.after_label =
        "learned: " + experiments::working_periods_text(morph, r.periods, options.disabled);
    const FigureFiles path_fig = plot_trunk_paths(paths, figures, "trunk-path-r1");

    write_file_atomic(figures / "learning-r1.json",
                      learning::to_json(r, morph, options.disabled).dump(2) + "\n");
    return {"learning-r1",
            "Learning with R1 disabled (Figs. 8, 9, 10; the trunk's path)",
            "R1 disabled, all periods 4: 37.86° after the first 400 steps. Trial 1 L1 = 5: "
            "21.46°, kept; trial 2 R3 = 9: 64.12°, rejected (P = 5.45e-10); after 7 trials "
            "0.25° with R2 = 5, R3 = 4, L1 = 5, L2 = 6, L3 = 5 (Fig. 8). Fig. 9: the 18 motor "
            "outputs, R1 constant, hind FTi inverted. Fig. 10: the disabled R1 still touches "
            "the ground intermittently.",
            "Seed " + std::to_string(o_.seed) + ": " + num(r.initial_deviation_deg, 2) +
                "° detected, then " + r.status + " after " + std::to_string(r.trials) +
                " trials at " + num(r.final_deviation_deg, 2) + "° with " +
                experiments::working_periods_text(morph, r.periods, options.disabled) +
                ". R1's foot touched the "
                "ground in " +
                std::to_string(r1_touches) + " of the " + std::to_string(kMotorFigureSteps) +
                " steps of Fig. 10. The video shows the "
                "whole run at " +
                std::to_string(sizes_.film_speed) + "× speed.",
            {image(fig8), image(fig9), image(fig10), image(path_fig)},
            {rel(video, o_.out)},
            {rel(figures / "learning-r1.json", o_.out)},
            {trace}};
  }

  experiments::ExperimentSpec experiment_spec(RobotKind kind, const std::string& name, int runs) {
    experiments::ExperimentSpec spec;
    spec.kind = kind;
    spec.runs = runs;
    spec.seed = o_.seed;
    spec.jobs = o_.jobs;
    spec.out = dir("experiments/" + name);
    spec.progress = o_.progress;
    return spec;
  }

  Section scenario_table(RobotKind kind) {
    const bool hexapod = kind == RobotKind::hexapod;
    const std::string name(robot::to_string(kind));
    const experiments::ExperimentTable t = experiments::run_scenario_table(
        experiment_spec(kind, name, hexapod ? sizes_.hexapod_runs : sizes_.quadruped_runs));
    (hexapod ? hexapod_ : quadruped_) = t;
    std::vector<ScenarioSummary> bars;
    int converged = 0, runs = 0, within = 0;
    for (const experiments::GroupSummary& g : t.rows) {
      bars.push_back({g.group, g.trials.mean, g.trials.sd, g.final_deviation_deg.mean,
                      g.final_deviation_deg.sd, g.share_converged(), g.no_deviation == g.runs});
      converged += g.converged;
      runs += g.runs;
      within += g.within_paper_trials;
    }
    const FigureFiles f = plot_learning_summary(bars, name, kPaperThresholdDeg, dir("figures"),
                                                hexapod ? "fig11-hexapod" : "fig13-quadruped");
    Table table{{"disabled", "runs", "converged", "final deviation (deg)", "trials",
                 "most frequent combination"},
                {}};
    for (const experiments::GroupSummary& g : t.rows) {
      table.rows.push_back(
          {g.group, std::to_string(g.runs), std::to_string(g.converged),
           num(g.final_deviation_deg.mean, 2) + " ± " + num(g.final_deviation_deg.sd, 2),
           num(g.trials.mean, 1) + " ± " + num(g.trials.sd, 1),
           g.best_periods.empty() ? "-" : g.best_periods});
    }
    const std::string base = "experiments/" + name + "/";
    return {name + "-table",
            hexapod ? "Hexapod: learning per scenario (Fig. 11)"
                    : "Quadruped: learning per scenario (Fig. 13)",
            hexapod ? "24 scenarios of 1-3 disabled legs (its Fig. 11 shows 21; the numbers are "
                      "not in the text), 10 runs each: learning for most scenarios ends within "
                      "20 trials, below 8°."
                    : "R1, R2, L1, L2 disabled, 10 runs each: the controller finds feasible "
                      "combinations (no numbers in the text).",
            std::to_string(runs) + " runs: " + std::to_string(converged) + " converged below 8°, " +
                std::to_string(within) +
                " of them within 20 trials (mean ± SD over runs in the table).",
            {image(f)},
            {},
            {base + "table.csv", base + "table.md", base + "summary.json"},
            {table}};
  }

  Section beta() {
    const experiments::ExperimentTable t =
        experiments::run_beta_study(experiment_spec(RobotKind::hexapod, "beta", sizes_.beta_runs),
                                    experiments::kBetaStudyValues);
    beta_ = t;
    std::vector<BetaSummary> bars;
    Table table{{"β", "runs", "converged", "trials", "final deviation (deg)"}, {}};
    std::string most;
    double most_trials = -1.0;
    for (const experiments::GroupSummary& g : t.rows) {
      bars.push_back({std::stod(g.group), g.trials.mean, g.trials.sd, g.share_converged()});
      table.rows.push_back(
          {g.group, std::to_string(g.runs), std::to_string(g.converged),
           num(g.trials.mean, 1) + " ± " + num(g.trials.sd, 1),
           num(g.final_deviation_deg.mean, 2) + " ± " + num(g.final_deviation_deg.sd, 2)});
      if (g.trials.mean > most_trials) {
        most_trials = g.trials.mean;
        most = g.group;
      }
    }
    const FigureFiles f = plot_beta_study(bars, "R1+R2", dir("figures"), "fig14-beta");
    return {"beta",
            "Influence of β (Fig. 14)",
            "R1 and R2 disabled, 50 runs per β: β = 0 (random search) needs the most trials; "
            "the search shortens as β grows; a large β (greedy) can get stuck above 8°.",
            std::to_string(t.rows.empty() ? 0 : t.rows.front().runs) +
                " runs per β; the most trials on average at β = " + most + " (" +
                num(most_trials, 1) + ").",
            {image(f)},
            {},
            {"experiments/beta/table.csv", "experiments/beta/table.md"},
            {table}};
  }

  Section tunnel() {
    const sim::SimModel& open = model(RobotKind::hexapod);
    const sim::SimModel& corridor = model(RobotKind::hexapod, /*tunnel=*/true);
    const robot::Morphology& morph = open.controller.morphology;
    const fs::path videos = dir("videos");
    const fs::path figures = dir("figures");
    Table table{{"disabled", "periods", "source", "deviation (deg)", "forward (m)", "lateral (m)",
                 "result", "paper (deg)"},
                {}};
    std::vector<std::string> films;
    std::vector<std::string> images;
    for (const TunnelScenario& sc : kTunnelScenarios) {
      const std::vector<std::size_t> disabled = robot::parse_leg_list(morph, [&] {
        std::string s = sc.name;
        std::replace(s.begin(), s.end(), '+', ',');
        return s;
      }());
      learning::CompensationOptions options;
      options.disabled = disabled;
      options.seed = o_.seed;
      const experiments::LearningRun learned = experiments::run_learning(open, options, false);
      struct Variant {
        std::string source;
        std::vector<int> periods;
        double paper_deg;
      };
      const std::vector<Variant> variants{
          {"all 4", std::vector<int>(morph.size(), 4), sc.paper_before_deg},
          {"our learning", learned.result.periods, sc.paper_after_deg},
          {"the paper's learning", parse_periods_text(morph, sc.paper_periods),
           sc.paper_after_deg}};
      TrunkPaths paths;
      for (const Variant& v : variants) {
        const bool filmed = v.source != "the paper's learning";
        std::string stem = "tunnel-" + sc.name + (v.source == "all 4" ? "-before" : "-after");
        std::replace(stem.begin(), stem.end(), '+', '-');
        std::optional<Film> film;
        if (filmed) {
          film.emplace(corridor,
                       FilmSpec{videos / (stem + ".mp4"), kDefaultFrameWidth, kDefaultFrameHeight,
                                sizes_.tunnel_film_speed, kTunnelCamera});
        }
        const experiments::TunnelRun t =
            experiments::run_tunnel(corridor, {disabled, v.periods, experiments::kTunnelMaxSteps},
                                    [&](const sim::SimState& s) {
                                      if (film)
                                        film->capture(s, sc.name + " disabled, " + v.source);
                                    });
        if (film) {
          film->finish();
          films.push_back(rel(videos / (stem + ".mp4"), o_.out));
        }
        table.rows.push_back(
            {sc.name, experiments::working_periods_text(morph, v.periods, disabled), v.source,
             num(t.deviation_deg, 2), num(t.forward_m, 2), num(t.lateral_m, 2),
             t.passed ? "passed" : (t.touched_wall ? "hit a wall" : "too slow"),
             "≈" + num(v.paper_deg, 2)});
        if (v.source == "the paper's learning") continue;
        auto& path = v.source == "all 4" ? paths.before : paths.after;
        for (std::size_t i = 0; i < t.record.rows(); ++i) {
          path.push_back({t.record.x[i], t.record.y[i]});
        }
      }
      const double half = open.scene.tunnel_width / 2.0;
      const double length = open.scene.tunnel_length;
      paths.walls = {{{0.0, half}, {length, half}}, {{0.0, -half}, {length, -half}}};
      paths.before_label = "all periods 4";
      paths.after_label = "learned";
      std::string stem = "tunnel-path-" + sc.name;
      std::replace(stem.begin(), stem.end(), '+', '-');
      images.push_back(image(plot_trunk_paths(paths, figures, stem)));
    }
    return {"tunnel",
            "The tunnel (Table 1)",
            "Tunnel 3.0 m × 1.2 m. Disabled R1, R1+R3, R1+R3+L2 with all periods 4: the robot "
            "deviated right and hit the wall (≈42°, 21°, 23°); with the learned periods it "
            "passed (≈7.97°, 0.95°, 2.67°).",
            "Deviation = atan(lateral / forward) of the trunk from the entrance to the end, or "
            "to where it touched a wall. Rows \"our learning\" use a learning run (seed " +
                std::to_string(o_.seed) +
                ") on open ground; rows \"the paper's learning\" replay the paper's combinations "
                "on our robot.",
            images,
            films,
            {},
            {table}};
  }

  void write_results_page() {
    experiments::ResultsInputs in;
    in.hexapod = hexapod_ ? hexapod_ : read_if_present("hexapod");
    in.quadruped = quadruped_ ? quadruped_ : read_if_present("quadruped");
    in.beta = beta_ ? beta_ : read_if_present("beta");
    if (!in.hexapod && !in.quadruped && !in.beta) return;
    in.command = "multicpg reproduce --out " + o_.out.string() + (o_.quick ? " --quick" : "");
    write_file_atomic(o_.out / "results.md", experiments::results_markdown(in));
  }

  std::optional<experiments::ExperimentTable> read_if_present(const std::string& name) const {
    const fs::path d = o_.out / "experiments" / name;
    if (!fs::exists(d / "summary.json")) return std::nullopt;
    return experiments::read_experiment(d);
  }

  ReproduceOptions o_;
  Sizes sizes_;
  std::chrono::steady_clock::time_point start_;
  std::map<int, std::unique_ptr<sim::SimModel>> models_;
  std::optional<experiments::ExperimentTable> hexapod_, quadruped_, beta_;
};

}  // namespace

const std::vector<std::string>& reproduce_stages() {
  static const std::vector<std::string> stages{"gaits",       "cpg-sync",      "walking",
                                               "learning-r1", "hexapod-table", "quadruped-table",
                                               "beta",        "tunnel"};
  return stages;
}

std::string stage_of_figure(std::string_view figure) {
  const std::string_view name = figure_by_name(figure).name;  // BadInput for unknown names
  static const std::map<std::string_view, std::string> stage{
      {"gait", "gaits"},
      {"cpg-sync", "cpg-sync"},
      {"learning-trace", "learning-r1"},
      {"motor", "learning-r1"},
      {"contacts", "learning-r1"},
      {"trunk-path", "learning-r1"},
      {"learning-hexapod", "hexapod-table"},
      {"learning-quadruped", "quadruped-table"},
      {"beta", "beta"}};
  const auto it = stage.find(name);
  if (it == stage.end()) {
    throw BadInput("figure '" + std::string(name) + "' is drawn by its own command (multicpg " +
                   std::string(name) + "), not by reproduce");
  }
  return it->second;
}

void reproduce(const ReproduceOptions& options) {
  for (const std::string& id : options.only) {
    const auto& all = reproduce_stages();
    if (std::find(all.begin(), all.end(), id) == all.end()) {
      throw BadInput("unknown reproduce stage '" + id + "'");
    }
  }
  Reproduction(options).run();
}

}  // namespace multicpg::report
