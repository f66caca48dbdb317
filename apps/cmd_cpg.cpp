// multicpg cpg: outputs of a master CPG and one client, in or out of sync (paper Fig. 6).
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/options.h"
#include "apps/text_plot.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/cpg_pair.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

// Tail of the run inspected for an exact periodic orbit and shown as a chart.
constexpr std::size_t kSummaryTail = 60;

struct CpgOptions {
  int period = 5;
  std::optional<int> client_period;
  std::string sync = "on";
  bool uncontrolled = false;
  long steps = 3000;  // p = 4, the slowest to lock from reset, is within 1e-6 by then
  std::string csv;
};

std::string describe_orbit(int period) {
  return period == 0 ? std::string("no periodic orbit (chaotic or not yet settled)")
                     : "period-" + std::to_string(period) + " orbit";
}

void run_cpg(const CpgOptions& o) {
  const int client_period = o.client_period.value_or(o.period);
  if (o.sync != "on" && o.sync != "off") {
    throw BadInput("--sync must be 'on' or 'off', got '" + o.sync + "'");
  }
  std::optional<AtomicFile> csv;
  if (!o.csv.empty()) csv.emplace(o.csv);

  experiments::CpgPairOptions run;
  run.master_period = o.period;
  run.client_period = client_period;
  run.synchronised = o.sync == "on";
  run.chaotic = o.uncontrolled;
  run.steps = o.steps;
  const std::vector<experiments::CpgPairSample> samples =
      experiments::run_cpg_pair(neural::CpgParams{}, run);

  std::vector<double> master_x1;
  std::vector<double> client_x1;
  for (const auto& s : samples) {
    master_x1.push_back(s.master_x1);
    client_x1.push_back(s.client_x1);
  }
  const std::size_t tail = std::min(kSummaryTail, samples.size());
  const int master_orbit = experiments::orbit_period(master_x1, neural::kMaxPeriod, tail);
  const int client_orbit = experiments::orbit_period(client_x1, neural::kMaxPeriod, tail);
  bool identical_x1 = true;
  double x2_gap = 0.0;
  for (std::size_t i = samples.size() - tail; i < samples.size(); ++i) {
    identical_x1 = identical_x1 && samples[i].master_x1 == samples[i].client_x1;
    x2_gap = std::max(x2_gap, std::abs(samples[i].master_x2 - samples[i].client_x2));
  }

  std::cout << "master: period " << o.period << (o.uncontrolled ? " (uncontrolled)" : "")
            << ", client: period " << client_period << ", sync " << o.sync << ", " << o.steps
            << " steps\n"
            << "master x1: " << describe_orbit(master_orbit) << "\n"
            << "client x1: " << describe_orbit(client_orbit) << "\n"
            << "over the last " << tail << " steps: client x1 "
            << (identical_x1 ? "identical to" : "differs from") << " the master's; x2 differs by "
            << std::setprecision(2) << std::scientific << x2_gap << std::defaultfloat << "\n";
  if (run.synchronised && identical_x1) {
    // Eq. 5 couples x1 only; the client's shunted c leaves x2 off by the master's own control.
    std::cout << "(a synchronised client's x2 differs only by the master's own control input)\n";
  }
  std::cout << "\n";
  const std::vector<double> master_tail(master_x1.end() - tail, master_x1.end());
  const std::vector<double> client_tail(client_x1.end() - tail, client_x1.end());
  std::cout << strip_chart("master x1 (last " + std::to_string(tail) + " steps)", master_tail)
            << strip_chart("client x1", client_tail);

  if (csv) {
    std::ostream& f = csv->stream();
    f << "step,master_x1,master_x2,client_x1,client_x2\n";
    f.precision(17);
    for (std::size_t t = 0; t < samples.size(); ++t) {
      const auto& s = samples[t];
      f << t << "," << s.master_x1 << "," << s.master_x2 << "," << s.client_x1 << "," << s.client_x2
        << "\n";
    }
    csv->commit();
  }
}

}  // namespace

void register_cpg(CLI::App& app) {
  auto opts = std::make_shared<CpgOptions>();
  CLI::App* cmd =
      app.add_subcommand("cpg", "outputs of a master CPG and one client (paper Fig. 6)");
  const Limits<int> cpg_periods{neural::kMinPeriod, neural::kMaxPeriod};
  cmd->add_option("--period", opts->period, "master period")
      ->check(in(cpg_periods))
      ->capture_default_str();
  cmd->add_option("--client-period", opts->client_period, "client period (default: master's)")
      ->check(in(cpg_periods));
  cmd->add_option("--sync", opts->sync, "on: client synchronised to the master (alpha = 1)")
      ->capture_default_str();
  cmd->add_flag("--uncontrolled", opts->uncontrolled, "no chaos control: both CPGs chaotic");
  cmd->add_option("--steps", opts->steps, "steps to run")
      ->check(in(body::kRunStepsLimits))
      ->capture_default_str();
  cmd->add_option("--csv", opts->csv, "write step,master_x1,master_x2,client_x1,client_x2");
  cmd->callback([opts] { run_cpg(*opts); });
}

}  // namespace multicpg::apps
