// multicpg model: print the MJCF of a robot, as the simulation compiles it (docs/robots.md), or
// write it with its robot file (docs/robots.md "Your robot: robot files"); check a robot file; or
// list the named body models with every value and its source.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <vector>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "robot/body_json.h"
#include "robot/body_models.h"
#include "robot/leg_sets.h"
#include "robot/robot_file.h"
#include "sim/robot_file.h"

namespace multicpg::apps {
namespace {

struct ModelOptions {
  std::string robot = "hexapod";
  bool tunnel = false;
  bool list = false;
  sim::SimOptions sim;
  BodyFlags body;
  std::string out;
  std::string check;
};

// What `model --check` walks: the tripod (robot::kDefaultPeriod) for 300 controller steps, 11 s
// at the paper's 27 Hz (§4), in which the built-in robots settle and walk 0.6 m.
constexpr long kCheckSteps = 300;
// It stands when its trunk ends at least this share of its start height above the ground, and
// touches neither the ground nor anything else of the world.
constexpr double kStandingShare = 0.5;

// True when a body of the trunk (reached from the trunk without passing a leg's TC joint) touches
// the world (ground, walls) in `state`.
bool trunk_touches_world(const sim::SimModel& model, const sim::SimState& state) {
  const mjModel* m = model.mj.get();
  std::vector<bool> leg_part(static_cast<std::size_t>(m->nbody), false);
  for (const sim::LegSlots& leg : model.legs) {
    leg_part[static_cast<std::size_t>(m->jnt_bodyid[leg.joints[0].joint])] = true;
  }
  // Parents come before their children in MuJoCo's body order.
  for (int b = 1; b < m->nbody; ++b) {
    if (leg_part[static_cast<std::size_t>(m->body_parentid[b])]) {
      leg_part[static_cast<std::size_t>(b)] = true;
    }
  }
  const auto trunk = [&](int geom) {
    const int body = m->geom_bodyid[geom];
    return body != 0 && !leg_part[static_cast<std::size_t>(body)];
  };
  const auto world = [&](int geom) { return m->geom_bodyid[geom] == 0; };
  const mjData* d = state.data.get();
  for (int c = 0; c < d->ncon; ++c) {
    const int g1 = d->contact[c].geom1;
    const int g2 = d->contact[c].geom2;
    if ((world(g1) && trunk(g2)) || (world(g2) && trunk(g1))) return true;
  }
  return false;
}

// What the robot file says and whether its robot stands: exit 0 when it does, 1 when it falls or
// its physics fails.
void check_robot_file(const std::string& path) {
  const robot::RobotFile file = sim::load_robot_file(path);
  const sim::SimModel model = sim::make_sim_model(file);
  const mjModel* m = model.mj.get();
  double mass = 0.0;
  for (int b = 0; b < m->nbody; ++b) mass += m->body_mass[b];
  std::cout << file.name << ": " << file.legs.size() << " legs (the "
            << robot::to_string(file.layout) << "'s layout), model " << file.model.string() << "\n";
  std::cout << "  trunk " << file.trunk << ", yaw from " << file.yaw << ", master " << file.master
            << ", mass " << fmt::format("{:.3f}", mass) << " kg\n";
  for (std::size_t i = 0; i < file.legs.size(); ++i) {
    const robot::LegMap& leg = file.legs[i];
    // The leg weighs what hangs from its TC joint's body.
    const int tc_body = m->jnt_bodyid[model.legs[i].joints[0].joint];
    std::cout << "  " << leg.name << " (" << robot::to_string(leg.side) << ", position "
              << leg.position << "): " << fmt::format("{:.3f}", m->body_subtreemass[tc_body])
              << " kg, foot " << leg.foot;
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const robot::JointMap& joint = leg.joints[j];
      std::cout << fmt::format(", {} {}{} [{:.1f}, {:.1f}] deg",
                               robot::to_string(robot::kJoints[j]), joint.sign < 0 ? "-" : "",
                               joint.name, joint.window.lo * 180.0 / std::numbers::pi,
                               joint.window.hi * 180.0 / std::numbers::pi);
    }
    std::cout << "\n";
  }
  sim::SimState state = sim::make_sim_state(model, robot::kDefaultPeriod);
  const double start_z = sim::trunk_position(model, state).z;
  std::cout << fmt::format("  standing height {:.3f} m\n", start_z);
  for (long step = 0; step < kCheckSteps; ++step) sim::sim_step(model, state);
  const sim::Position end = sim::trunk_position(model, state);
  std::cout << fmt::format("  after {} steps: trunk at {:.3f} m, {:.3f} m forward\n", kCheckSteps,
                           end.z, end.x);
  if (!(end.z >= kStandingShare * start_z)) {
    throw RuntimeFailure(path + ": the robot does not stand: its trunk sank from " +
                         fmt::format("{:.3f} m to {:.3f} m", start_z, end.z));
  }
  if (trunk_touches_world(model, state)) {
    throw RuntimeFailure(path + ": the robot does not stand: its trunk lies on the ground");
  }
  std::cout << "  it stands\n";
}

// `--out DIR`: DIR/NAME.xml and the robot file DIR/NAME.toml that walks it.
void write_robot_files(const ModelOptions& o, robot::RobotKind kind, const std::string& xml) {
  if (o.tunnel) {
    throw BadInput(
        "--tunnel: --out DIR writes a robot file, whose model is the robot on flat ground; write "
        "the tunnel with --out FILE.xml");
  }
  const std::filesystem::path dir(o.out);
  ensure_writable_dir(dir);
  const std::string name(robot::to_string(kind));
  const std::filesystem::path model = name + ".xml";
  write_file_atomic(dir / model, xml);
  write_file_atomic(dir / (name + ".toml"),
                    robot::robot_file_toml(robot::builtin_robot_file(kind, model)));
}

void run_model(const ModelOptions& o) {
  if (o.list) {
    std::cout << robot::body_models_listing();
    return;
  }
  if (!o.check.empty()) {
    check_robot_file(o.check);
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
  if (std::filesystem::path(o.out).extension() != ".xml") {
    if (!robot::is_flat(options.scene.terrain)) {
      throw BadInput("--terrain " + robot::terrain_text(options.scene.terrain) +
                     ": a robot file's model walks on flat ground; write it with --out FILE.xml");
    }
    write_robot_files(o, kind, xml);
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
  cmd->add_option("--robot", opts->robot, "hexapod, quadruped or octopod")
      ->check(one_of(robot::kRobotKindNames.names(), "robot"))
      ->capture_default_str();
  cmd->add_flag("--tunnel", opts->tunnel, "add the 3.0 m x 1.2 m corridor of paper §5");
  cmd->add_flag("--list", opts->list,
                "list the body models (--model) with every parameter's value and source");
  add_sim_flags(*cmd, opts->sim, opts->body, /*with_servo=*/false);
  cmd->add_option("--out", opts->out,
                  "write the MJCF to FILE.xml instead of printing it, or to DIR/NAME.xml with its "
                  "robot file DIR/NAME.toml (docs/robots.md)");
  cmd->add_option("--check", opts->check,
                  "read the robot file FILE.toml, print what it says and walk it to see that it "
                  "stands");
  cmd->callback([opts] { run_model(*opts); });
}

}  // namespace multicpg::apps
