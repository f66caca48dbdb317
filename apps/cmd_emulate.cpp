// multicpg emulate: a fake robot on pseudo-terminals that speaks a hardware file's protocol and
// moves the simulated robot with what it receives (docs/hardware.md "Rehearse on the emulator").
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/limits.h"
#include "emulator/emulator.h"
#include "hw/hardware_file.h"

namespace multicpg::apps {
namespace {

struct EmulateOptions {
  RunFlags run;  // the robot and its simulation
  std::string hardware;
  std::string protocol;
  std::vector<std::string> injections;
  std::uint64_t seed = 1;
  bool wire_time = false;
  std::string log;
  std::string rehearsal;
  long runs = 0;  // 0: until interrupted
};

void run_emulate(const EmulateOptions& o) {
  const experiments::RunSpec spec = run_spec(o.run, /*learn=*/false);
  const hw::HardwareFile file =
      hw::load_hardware_file(o.hardware, experiments::morphology(spec.robot));
  if (!o.protocol.empty() && hw::parse_protocol(o.protocol) != file.protocol) {
    throw BadInput("--protocol " + o.protocol + ": the hardware file '" + o.hardware + "' speaks " +
                   std::string(hw::to_string(file.protocol)));
  }
  emulator::EmulatorSpec emulator;
  for (const std::string& text : o.injections) {
    try {
      emulator.injections.push_back(emulator::parse_injection(text, file));
    } catch (const BadInput& e) {
      throw BadInput(std::string("--inject ") + e.what());
    }
  }
  emulator.seed = o.seed;
  emulator.wire_time = o.wire_time;
  emulator.log = o.log;
  if (!o.rehearsal.empty()) require_writable_file(o.rehearsal);
  const sim::SimModel model = experiments::make_model(spec.robot);
  emulator::Emulator emu(model, file, emulator);
  if (!o.rehearsal.empty()) {
    write_file_atomic(o.rehearsal,
                      hw::with_ports(file.path, emu.bus_path(), emu.yaw_path(), ::getpid()));
  }
  std::cout << "emulating " << file.name << " (" << hw::to_string(file.protocol) << ") on the "
            << experiments::morphology(spec.robot).name << "\nbus " << emu.bus_path() << "\n";
  if (!emu.yaw_path().empty()) std::cout << "yaw " << emu.yaw_path() << "\n";
  if (!o.rehearsal.empty()) std::cout << "rehearsal file " << o.rehearsal << "\n";
  std::cout << (o.runs == 1   ? "serving one run\n"
                : o.runs == 0 ? "serving runs until interrupted (Ctrl-C)\n"
                              : "serving " + std::to_string(o.runs) + " runs\n")
            << std::flush;
  // One run after another on the same ports, each from the robot's start pose
  // (docs/hardware.md "Rehearse on the emulator").
  for (long run = 1; o.runs == 0 || run <= o.runs; ++run) {
    if (run > 1 && !emu.next_run()) break;
    const emulator::EmulatorSummary s = emu.run();
    std::cout << "run " << run << ": served " << s.steps << " control steps and " << s.answers
              << " answers; refused " << s.malformed << " malformed frames"
              << (s.posture ? "; the safe posture was commanded" : "")
              << (s.torque_off ? "; the torque was turned off" : "")
              << (s.hung_up ? "; the injected hang-up closed the ports" : "") << "\n"
              << std::flush;
    if (s.hung_up) break;
  }
}

}  // namespace

void register_emulate(CLI::App& app) {
  auto o = std::make_shared<EmulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "emulate",
      "a fake robot on a pseudo-terminal: speaks the hardware file's protocol and moves the "
      "simulated robot with what it receives (docs/hardware.md)");
  cmd->add_option("--hardware", o->hardware, "the hardware file to emulate")->required();
  const std::vector<std::string> protocols = hw::protocol_names();
  cmd->add_option("--protocol", o->protocol,
                  fmt::format("{}: must be the file's (a check, not a choice)",
                              fmt::join(protocols, " or ")))
      ->check(one_of(protocols, "protocol"));
  add_robot_flag(*cmd, o->run);
  cmd->add_option("--inject", o->injections,
                  "a fault from command frame STEP on, repeatable: drop=P@STEP, corrupt=P@STEP "
                  "(answer bytes lost or changed with probability P), latency=MS@STEP, "
                  "silent=ID@STEP (a servo; the board: any ID), drift=DEG_PER_S@STEP, "
                  "silent-yaw@STEP, hangup@STEP (the emulator ends as if killed), "
                  "hangup-yaw@STEP (the yaw line's port closes)");
  cmd->add_option("--seed", o->seed, "the draws of drop and corrupt")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_option("--runs", o->runs,
                  "serve this many runs, one after another, then end (default: until "
                  "interrupted)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--wire-time", o->wire_time,
                "each frame and answer also takes its bytes' time on the wire at the file's baud");
  cmd->add_option("--log", o->log, "write what happened as JSON lines with monotonic times");
  cmd->add_option("--rehearsal", o->rehearsal,
                  "write the hardware file with the emulator's ports here, for --hardware");
  add_sim_flags(*cmd, o->run.sim, o->run.body);
  cmd->callback([o] { run_emulate(*o); });
}

}  // namespace multicpg::apps
