// multicpg model: print the MJCF of a robot, as the simulation compiles it (SPEC §7), or the
// named body models with every value and its source.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "robot/body_json.h"
#include "robot/body_models.h"

namespace multicpg::apps {
namespace {

struct ModelOptions {
  std::string robot = "hexapod";
  bool tunnel = false;
  bool list = false;
  sim::SimOptions sim;
  BodyFlags body;
  std::string out;
};

// Every model, every value, its unit and its source (robot/body_models.h).
void print_models(std::ostream& out) {
  for (robot::BodyModel m : robot::kBodyModels) {
    out << robot::to_string(m) << (m == robot::kDefaultBodyModel ? " (default)" : "") << ": "
        << robot::describe(m) << "\n";
    const robot::BodyParams values = robot::body_params(m);
    for (std::string_view key : robot::parameter_keys()) {
      const std::string k(key);
      const std::string shown =
          robot::value_text(values, key) + " " + std::string(robot::value_unit(key));
      out << "  " << std::left << std::setw(20) << k << std::setw(22) << shown << "  "
          << robot::value_source(m, key) << "\n";
    }
    out << "\n";
  }
}

void run_model(const ModelOptions& o) {
  if (o.list) {
    print_models(std::cout);
    return;
  }
  const robot::RobotKind kind = robot::parse_robot(o.robot);
  sim::SimOptions options = sim_options(o.sim, o.body, kind);
  options.scene.tunnel = o.tunnel;
  const std::string xml = sim::model_xml(kind, options);
  const std::vector<robot::ModelFile> files = robot::scene_files(options.scene);
  if (o.out.empty()) {
    if (!files.empty()) {
      throw BadInput("--terrain " + robot::terrain_text(options.scene.terrain) +
                     ": its heightfield is a file beside the model; write both with --out FILE");
    }
    std::cout << xml;
    return;
  }
  // The files first: a model file that exists refers to files that exist.
  for (const robot::ModelFile& f : files) {
    write_file_atomic(std::filesystem::path(o.out).parent_path() / f.name, f.bytes);
  }
  write_file_atomic(o.out, xml);
}

}  // namespace

void register_model(CLI::App& app) {
  auto opts = std::make_shared<ModelOptions>();
  CLI::App* cmd = app.add_subcommand(
      "model", "print a robot's MuJoCo model (MJCF), or with --list the body models");
  cmd->add_option("--robot", opts->robot, "hexapod, quadruped or octopod")->capture_default_str();
  cmd->add_flag("--tunnel", opts->tunnel, "add the 3.0 m x 1.2 m corridor of paper §5");
  cmd->add_flag("--list", opts->list,
                "list the body models (--model) with every parameter's value and source");
  add_sim_flags(*cmd, opts->sim, opts->body, /*with_servo=*/false);
  cmd->add_option("--out", opts->out, "write the MJCF to this file instead of printing it");
  cmd->callback([opts] { run_model(*opts); });
}

}  // namespace multicpg::apps
