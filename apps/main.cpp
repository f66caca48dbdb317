// multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).
// Exit codes: 0 success, 2 bad input, 1 runtime failure, 130 / 143 stopped by SIGINT / SIGTERM
// (under mpirun: the job's, printed once).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <string>
#include <string_view>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "common/provenance.h"
#include "experiments/processes.h"
#include "sim/mujoco_guard.h"

namespace {

using namespace multicpg;

// Flushes standard output: a result that did not reach it (a full disk, a closed pipe) is a
// failure, not a success. Returns the exit code to use.
int finish_stdout(int code) {
  std::cout.flush();
  const bool ok = static_cast<bool>(std::cout) && std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (ok) return code;
  std::cerr << "multicpg: cannot write standard output\n";
  return code == 0 ? 1 : code;
}

// The commands whose work run_tasks shares among the processes of an MPI job. Every other one
// would only run again in each process (and `reproduce` runs experiments side by side, which
// the processes could not follow in step), so under mpirun with -np > 1 they are refused.
constexpr std::string_view kSharedCommands[] = {"experiment table", "experiment beta", "landscape",
                                                "run", "calibrate"};

// BadInput unless the command `app` parsed may run in several processes.
void check_processes(const CLI::App& app) {
  if (experiments::process_count() == 1) return;
  std::string command;
  for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
    sub = sub->get_subcommands().front();
    command += (command.empty() ? "" : " ") + sub->get_name();
  }
  if (std::find(std::begin(kSharedCommands), std::end(kSharedCommands), command) ==
      std::end(kSharedCommands)) {
    throw BadInput("'" + command +
                   "' runs in one process; under mpirun with -np > 1 only experiment table, "
                   "experiment beta, landscape and run share their runs");
  }
}

// Runs the command; a failure comes back as its exit code and error line (printed by
// ProcessGroup::finish, once for the whole job).
experiments::Ending run(int argc, char** argv) {
  CLI::App app{"multicpg: multiple chaotic CPGs with learning for legged locomotion"};
  app.require_subcommand(1);
  apps::register_gait(app);
  apps::register_cpg(app);
  apps::register_walk(app);
  apps::register_model(app);
  apps::register_learn(app);
  apps::register_experiment(app);
  apps::register_tunnel(app);
  apps::register_render(app);
  apps::register_view(app);
  apps::register_reproduce(app);
  apps::register_figure(app);
  apps::register_landscape(app);
  apps::register_learner_benchmark(app);
  apps::register_calibrate(app);
  apps::register_run(app);
  apps::register_emulate(app);
  apps::register_replay(app);
  apps::refuse_empty_values(app);
  app.parse_complete_callback([&app] { check_processes(app); });  // before the command runs
  const auto failed = [](int code, const char* what) {
    return experiments::Ending{code, std::string("multicpg: ") + what};
  };
  const auto stopped = [&failed](const Interrupted& e) { return failed(e.exit_code(), e.what()); };
  try {
    if (argc > 1 && argv[1][0] != '-') {
      try {
        app.get_subcommand(argv[1]);
      } catch (const CLI::OptionNotFound&) {
        throw BadInput(std::string("unknown command '") + argv[1] + "' (see multicpg --help)");
      }
    }
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    if (!experiments::is_primary_process()) return {};
    return {app.exit(e), ""};  // --help
  } catch (const CLI::ParseError& e) {
    return failed(2, e.what());
  } catch (const OptionError& e) {
    return failed(2, (e.key() + " " + e.what()).c_str());
  } catch (const BadInput& e) {
    return failed(2, e.what());
  } catch (const experiments::FailedElsewhere& e) {
    return {e.code(), ""};  // the failing process reports it
  } catch (const Interrupted& e) {
    return stopped(e);
  } catch (const std::exception& e) {
    // A failure a signal caused (a child process killed by the same Ctrl-C) is the signal's.
    if (interrupt_signal() != 0) return stopped(Interrupted(interrupt_signal()));
    return failed(1, e.what());
  }
  // Stopped after the work was done: the files are whole, but the user asked to stop.
  if (interrupt_signal() != 0) return stopped(Interrupted(interrupt_signal()));
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  multicpg::install_interrupt_handlers();
  multicpg::sim::install_mujoco_handlers();
  multicpg::set_command_line(argc, argv);
  // Under mpirun, one of the job's processes (experiments/processes.h).
  multicpg::experiments::ProcessGroup processes(argc, argv);
  return finish_stdout(processes.finish(run(argc, argv)));
}
