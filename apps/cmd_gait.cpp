// multicpg gait: the gait the controller produces for one period (paper Fig. 2).
#include <iomanip>
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/options.h"
#include "apps/text_plot.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/gait.h"
#include "robot/leg_sets.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

struct GaitOptions {
  std::string robot = "hexapod";
  int period = 4;
  long steps = 180;  // covers one cycle of the slowest gait (p = 9: 171 steps)
  long warmup = experiments::kDefaultGaitWarmup;
  std::string disable;
  std::string csv;
};

void run_gait(const GaitOptions& o) {
  const robot::RobotKind kind = robot::parse_robot(o.robot);
  require_gait_period(o.period, "--period");
  if (o.warmup < 0) throw BadInput("--warmup must not be negative");

  const neural::ControllerModel model = neural::make_controller_model(kind);
  const std::vector<std::size_t> disabled =
      parse_leg_flag(model.morphology, o.disable, "--disable");
  std::optional<AtomicFile> csv;
  if (!o.csv.empty()) csv.emplace(o.csv);

  neural::ControllerState state = neural::make_controller_state(model, o.period);
  for (std::size_t leg : disabled) neural::set_disabled(state, leg, true);
  const experiments::GaitRecord record = experiments::record_gait(model, state, o.warmup, o.steps);

  std::vector<std::string> names;
  for (const robot::Leg& leg : model.morphology.legs) names.push_back(leg.name);
  std::cout << model.morphology.name << ", period " << o.period << ", steps " << o.warmup << ".."
            << o.warmup + o.steps - 1 << " ('#' stance, '.' swing)";
  if (!disabled.empty()) {
    std::cout << ", disabled " << robot::leg_set_name(model.morphology, disabled);
  }
  std::cout << "\n" << gait_diagram(names, record.swing, o.warmup);
  const std::vector<double> fractions = experiments::swing_fractions(record);
  std::cout << "swing fraction:";
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::cout << " " << names[i] << " " << std::fixed << std::setprecision(3) << fractions[i];
  }
  std::cout << "\n";

  if (csv) {
    std::ostream& f = csv->stream();
    f << "step";
    for (const std::string& n : names) f << "," << n;
    f << "\n";
    for (std::size_t t = 0; t < record.swing.size(); ++t) {
      f << o.warmup + static_cast<long>(t);
      for (bool s : record.swing[t]) f << "," << (s ? 1 : 0);
      f << "\n";
    }
    csv->commit();
  }
}

}  // namespace

void register_gait(CLI::App& app) {
  auto opts = std::make_shared<GaitOptions>();
  CLI::App* cmd = app.add_subcommand("gait", "print the gait diagram of one period (paper Fig. 2)");
  cmd->add_option("--robot", opts->robot, "hexapod, quadruped or octopod")
      ->check(one_of(robot::kRobotKindNames.names(), "robot"))
      ->capture_default_str();
  cmd->add_option("--period", opts->period, "CPG period: 1 (stop), 4, 5, 6, 8 or 9")
      ->capture_default_str();
  cmd->add_option("--steps", opts->steps, "steps to show")
      ->check(in(body::kRunStepsLimits))
      ->capture_default_str();
  cmd->add_option("--warmup", opts->warmup, "steps run first, so the CPG locks and delays fill")
      ->check(in(body::kStepLimits))
      ->capture_default_str();
  cmd->add_option("--disable", opts->disable, "legs holding the disabled posture, e.g. R1,L2");
  cmd->add_option("--csv", opts->csv, "write step,<leg>... with 1 = swing, 0 = stance");
  cmd->callback([opts] { run_gait(*opts); });
}

}  // namespace multicpg::apps
