// multicpg calibrate: search the body parameters for the body that fails like the real AMOSII
// (paper §5 Table 1; docs/fidelity.md "Calibration"), every candidate saved as it finishes
// (resumable), and draw which parameter moves which number.
#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/table.h"
#include "experiments/calibration.h"
#include "experiments/paper.h"
#include "experiments/processes.h"
#include "experiments/runner.h"
#include "report/figures.h"

namespace multicpg::apps {
namespace {

struct CalibrateOptions {
  std::string robot = "hexapod";
  std::string target = "table1";
  std::string out;
  std::optional<int> jobs;
  int budget = experiments::kDefaultCalibrationBudget;
  std::uint64_t seed = 1;
  std::vector<long> warmups = experiments::kDefaultCalibrationWarmups;
  std::vector<std::string> search;  // KEY or KEY=LO..HI[:log]
  sim::SimOptions sim;
  BodyFlags body;
};

// "slip", "slip=0.001..0.05" or "slip=0.001..0.05:log". A key of the default set keeps its
// interval and scale when none is given; any other its documented range, linear.
experiments::SearchedParam parse_search(const std::string& text) {
  const std::size_t eq = text.find('=');
  experiments::SearchedParam p;
  p.key = text.substr(0, eq);
  const robot::NumberParam* param = nullptr;
  try {
    param = &robot::number_param(p.key);
  } catch (const BadInput& e) {
    throw BadInput(std::string("--search: ") + e.what());
  }
  if (eq == std::string::npos) {
    for (const experiments::SearchedParam& d : experiments::default_searched_params()) {
      if (d.key == p.key) return d;
    }
    p.lo = param->limits.lo;
    p.hi = param->limits.hi;
    return p;
  }
  std::string range = text.substr(eq + 1);
  const std::string log_suffix = ":log";
  if (range.size() > log_suffix.size() &&
      range.compare(range.size() - log_suffix.size(), log_suffix.size(), log_suffix) == 0) {
    p.log_scale = true;
    range.resize(range.size() - log_suffix.size());
  }
  const std::size_t dots = range.find("..");
  if (dots == std::string::npos || !CLI::detail::lexical_cast(range.substr(0, dots), p.lo) ||
      !CLI::detail::lexical_cast(range.substr(dots + 2), p.hi)) {
    throw BadInput("--search: takes KEY, KEY=LO..HI or KEY=LO..HI:log, got '" + text + "'");
  }
  return p;
}

// The flag of a calibration key ("budget" -> "--budget", "params[1].hi" -> "--search").
std::string calibration_flag(const std::string& key) {
  if (key.rfind("params", 0) == 0) return "--search";
  if (key.rfind("warmups", 0) == 0) return "--warmups";
  if (key.rfind("sim.", 0) == 0) return sim_flag(key.substr(4));
  return "--" + key;
}

void print_summary(const experiments::Calibration& cal, const std::string& out,
                   const report::FigureFiles& figure) {
  const experiments::Candidate& best = cal.candidates[cal.best];
  const experiments::CandidateNumbers& n = best.numbers;
  const std::size_t feasible =
      std::count_if(cal.candidates.begin(), cal.candidates.end(),
                    [](const experiments::Candidate& c) { return c.numbers.feasible(); });
  std::cout << cal.candidates.size() << " candidates (" << cal.ran << " walked now, " << cal.loaded
            << " loaded), " << feasible << " feasible\n";
  std::cout << "best " << best.id << (n.feasible() ? "" : " (misses a constraint)") << ":";
  for (const experiments::SearchedParam& p : cal.spec.params) {
    std::cout << " " << p.key << "="
              << fmt::format("{:.4g}", robot::number_param(p.key).get(best.body));
  }
  std::cout << "\n";
  if (!n.failure.empty()) {
    std::cout << "  no candidate walked: " << n.failure << "\n";
    return;
  }
  for (std::size_t i = 0; i < n.fit.size(); ++i) {
    const auto& paper = experiments::paper::kTunnel[i];
    std::cout << fmt::format(
        "  {:<9} all 4: {:+6.1f}° (real robot {:+.0f}°); paper's periods: "
        "{:+6.1f}°, passed {} of {}; mirror {}: {:+6.1f}°\n",
        n.fit[i].name, n.fit[i].mean_deg(), experiments::paper::signed_before_deg(paper),
        n.paper_periods[i].mean_deg(), n.paper_periods[i].passed(),
        n.paper_periods[i].starts.size(), n.mirrors[i].name, n.mirrors[i].mean_deg());
  }
  std::cout << fmt::format(
      "  score {:.2f}° RMS; intact: max |yaw| {:.2f}° per window, {:.2f} cm/s\n", n.score_deg,
      n.intact_max_yaw_deg(), 100.0 * n.intact_mean_speed_m_s());
  std::cout << "wrote " << out << "/{candidates.csv,candidates.json,summary.json} and "
            << figure.png.string() << "\n";
}

void run(const CalibrateOptions& o) {
  experiments::CalibrationSpec spec;
  spec.target = experiments::parse_calibration_target(o.target);
  spec.robot.kind = robot::parse_robot(o.robot);
  if (spec.robot.kind != robot::RobotKind::hexapod) {
    throw BadInput("--robot: Table 1 is the hexapod's; got " + o.robot);
  }
  spec.robot.sim = sim_options(o.sim, o.body, spec.robot.kind);
  if (o.search.empty()) {
    spec.params = experiments::default_searched_params();
  } else {
    for (const std::string& s : o.search) spec.params.push_back(parse_search(s));
  }
  spec.budget = o.budget;
  spec.seed = o.seed;
  spec.warmups = o.warmups;
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    // "params[1].hi" names the searched parameter as the user wrote it: "--search slip: hi ..."
    const std::string& key = e.key();
    if (key.rfind("params[", 0) == 0) {
      const std::size_t i = std::stoul(key.substr(7));
      const std::size_t dot = key.find('.');
      const std::string field = dot == std::string::npos ? "" : key.substr(dot + 1) + " ";
      throw BadInput("--search " + spec.params.at(i).key + ": " + field + e.what());
    }
    throw BadInput(calibration_flag(key) + ": " + key + " " + e.what());
  }
  if (experiments::is_primary_process()) ensure_writable_dir(o.out);
  const experiments::Calibration cal = experiments::run_calibration(
      spec, o.out, o.jobs.value_or(experiments::default_jobs()), /*progress=*/true);
  if (!experiments::is_primary_process()) return;
  const experiments::Sensitivity s = experiments::sensitivity(experiments::candidates_table(cal));
  report::CalibrationMap map{s.params, s.numbers, s.rho, "Which body parameter moves which number",
                             fmt::format("rank correlation over the {} design candidates of a "
                                         "calibration against Table 1",
                                         s.candidates)};
  print_summary(cal, o.out, report::plot_calibration(map, o.out));
}

}  // namespace

void register_calibrate(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  o->body.model = std::string(robot::to_string(robot::BodyModel::real));
  CLI::App* cmd = app.add_subcommand(
      "calibrate",
      "search the body parameters for the body that fails like the real robot (paper §5 "
      "Table 1; resumable; docs/fidelity.md)");
  cmd->add_option("--robot", o->robot, "the robot (Table 1 is the hexapod's)")
      ->check(one_of(robot::kRobotKindNames.names(), "robot"))
      ->capture_default_str();
  cmd->add_option("--target", o->target,
                  "what to fit: table1 (paper §5 Table 1, before learning: 42°, 21°, 23° right)")
      ->check(one_of({std::string(experiments::to_string(experiments::CalibrationTarget::table1))},
                     "calibration target"))
      ->capture_default_str();
  cmd->add_option("--out", o->out,
                  "directory for the candidates, CSV, JSON, summary and figure (resumes)")
      ->required();
  cmd->add_option("--jobs", o->jobs, "parallel candidates (default: every core)")
      ->check(in(experiments::kJobsLimits));
  cmd->add_option("--budget", o->budget,
                  "candidates walked: a space-filling design of 60 %, then a compass search")
      ->check(in(experiments::kCalibrationBudgetLimits))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "seed of the space-filling design")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_option("--warmups", o->warmups,
                  "controller warm-ups of the starts every candidate is scored over (their mean)")
      ->delimiter(',')
      ->check(in(experiments::kCalibrationWarmupLimits))
      ->capture_default_str();
  cmd->add_option("--search", o->search,
                  "a body parameter to search, KEY or KEY=LO..HI[:log], repeatable (default: "
                  "disabled_posture.tc, .ctr, .fti, slip, foot_friction, joint_compliance, "
                  "servo_torque)");
  // The body's unsearched values: --model (real: the measured masses and body lift) and the
  // Body flags over it.
  add_sim_flags(*cmd, o->sim, o->body);
  cmd->callback([o] { run(*o); });
}

}  // namespace multicpg::apps
