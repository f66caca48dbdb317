// multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).
// Exit codes: 0 success, 2 bad input, 1 runtime failure, 130 / 143 stopped by SIGINT / SIGTERM
// (under mpirun: the job's, printed once).
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <new>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "common/provenance.h"
#include "common/user_text.h"
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

// " (did you mean PREFIX NAME?)" when a name of `known` is close to `typed`, else "".
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& known,
                         const std::string& prefix = "") {
  const std::optional<std::string> near = closest_name(typed, known);
  return near ? " (did you mean " + prefix + *near + "?)" : "";
}

// The commands of `app` (an option group is an unnamed CLI::App: not a command).
std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (!sub->get_name().empty()) names.push_back(sub->get_name());
  }
  return names;
}

// The flags of `app`, those of its option groups included.
void add_flag_names(const CLI::App& app, std::vector<std::string>& names) {
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name().empty()) add_flag_names(*sub, names);
  }
}

// Throws BadInput for a word of the command line that should name a command ("multicpg wlak",
// "multicpg experiment tabel") and names none, with the command meant if it is near.
void check_command_words(const CLI::App& app, int argc, char** argv) {
  const CLI::App* command = &app;
  std::string path;  // "experiment " for the commands of `experiment`
  for (int i = 1; i < argc && argv[i][0] != '-'; ++i) {
    const std::string word = argv[i];
    const std::vector<std::string> known = command_names(*command);
    if (known.empty()) return;
    if (std::find(known.begin(), known.end(), word) == known.end()) {
      const std::string meant = did_you_mean(word, known, path);
      throw BadInput("unknown command '" + path + word + "'" +
                     (meant.empty() ? " (see multicpg " + path + "--help)" : meant));
    }
    command = command->get_subcommand(word);
    path += word + " ";
  }
}

// The command the command line chose ("walk", "experiment table") and its CLI::App.
std::pair<std::string, const CLI::App*> parsed_command(const CLI::App& app) {
  std::string name;
  const CLI::App* command = &app;
  while (!command->get_subcommands().empty()) {
    command = command->get_subcommands().front();
    name += (name.empty() ? "" : " ") + command->get_name();
  }
  return {name, command};
}

// One line for arguments the command does not take: the first unknown flag with the flag meant
// if one is near ("unknown flag '--period' of walk (did you mean --periods?)"), else the first
// unexpected argument.
std::string unexpected_arguments(const CLI::App& app, int argc, char** argv) {
  const auto [name, command] = parsed_command(app);
  const std::vector<std::string> extras = app.remaining(true);
  const std::set<std::string> unexpected(extras.begin(), extras.end());
  const std::string help = " (see multicpg " + (name.empty() ? "" : name + " ") + "--help)";
  const std::string of = name.empty() ? "" : " of " + name;
  std::optional<std::string> first;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (unexpected.count(arg) == 0) continue;
    if (arg.size() > 1 && arg[0] == '-') {
      const std::string flag = arg.substr(0, arg.find('='));
      std::vector<std::string> flags;
      add_flag_names(*command, flags);
      const std::string meant = did_you_mean(flag, flags);
      return "unknown flag '" + flag + "'" + of + (meant.empty() ? help : meant);
    }
    if (!first) first = arg;
  }
  return "unexpected argument '" + first.value_or(extras.empty() ? "" : extras.front()) + "'" +
         (name.empty() ? "" : " to " + name) + help;
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
  app.set_version_flag(
      "--version", [] { return build_info_text(mj_versionString()); },
      "print the version, git commit, MuJoCo version and compiler, and exit");
  app.parse_complete_callback([&app] { check_processes(app); });  // before the command runs
  const auto failed = [](int code, const std::string& what) {
    return experiments::Ending{code, "multicpg: " + printable(what)};
  };
  const auto stopped = [&failed](const Interrupted& e) { return failed(e.exit_code(), e.what()); };
  try {
    check_command_words(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    if (!experiments::is_primary_process()) return {};
    return {app.exit(e), ""};  // --help, --version
  } catch (const CLI::ExtrasError&) {
    return failed(2, unexpected_arguments(app, argc, argv));
  } catch (const CLI::ParseError& e) {
    return failed(2, e.what());
  } catch (const OptionError& e) {
    return failed(2, e.key() + " " + e.what());
  } catch (const BadInput& e) {
    return failed(2, e.what());
  } catch (const GoalNotReached&) {
    // Every output is written and has said what happened: no further line.
    if (interrupt_signal() != 0) return stopped(Interrupted(interrupt_signal()));
    return {GoalNotReached::kExitCode, ""};
  } catch (const experiments::FailedElsewhere& e) {
    return {e.code(), ""};  // the failing process reports it
  } catch (const Interrupted& e) {
    return stopped(e);
  } catch (const std::bad_alloc&) {
    // An address-space limit (ulimit -v) or a full machine: say so, not std::bad_alloc.
    if (interrupt_signal() != 0) return stopped(Interrupted(interrupt_signal()));
    return failed(1, "out of memory: ask for fewer --jobs or a smaller run");
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
