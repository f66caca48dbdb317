// multicpg model: print the MJCF of a robot, as the simulation compiles it (SPEC §7).
#include <iostream>

#include "apps/commands.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"

namespace multicpg::apps {
namespace {

struct ModelOptions {
  std::string robot = "hexapod";
  bool tunnel = false;
  sim::SimOptions sim;
  std::string out;
};

void run_model(const ModelOptions& o) {
  const robot::RobotKind kind = robot::parse_robot(o.robot);
  sim::SimOptions options = sim_options(o.sim);
  options.scene.tunnel = o.tunnel;
  const std::string xml = sim::model_xml(kind, options);
  if (o.out.empty()) {
    std::cout << xml;
  } else {
    write_file_atomic(o.out, xml);
  }
}

}  // namespace

void register_model(CLI::App& app) {
  auto opts = std::make_shared<ModelOptions>();
  CLI::App* cmd = app.add_subcommand("model", "print a robot's MuJoCo model (MJCF)");
  cmd->add_option("--robot", opts->robot, "hexapod, quadruped or octopod")->capture_default_str();
  cmd->add_flag("--tunnel", opts->tunnel, "add the 3.0 m x 1.2 m corridor of paper §5");
  add_sim_flags(*cmd, opts->sim, /*with_servo=*/false);
  cmd->add_option("--out", opts->out, "write the MJCF to this file instead of printing it");
  cmd->callback([opts] { run_model(*opts); });
}

}  // namespace multicpg::apps
