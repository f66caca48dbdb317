// multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).
// Exit codes: 0 success, 2 bad input, 1 runtime failure.
#include <cstdio>
#include <iostream>
#include <string>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "common/errors.h"
#include "common/provenance.h"
#include "sim/sim.h"

namespace {

// Flushes standard output: a result that did not reach it (a full disk, a closed pipe) is a
// failure, not a success. Returns the exit code to use.
int finish_stdout(int code) {
  std::cout.flush();
  const bool ok = static_cast<bool>(std::cout) && std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (ok) return code;
  std::cerr << "multicpg: cannot write standard output\n";
  return code == 0 ? 1 : code;
}

int run(int argc, char** argv) {
  using namespace multicpg;
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
  apps::register_run(app);
  apps::refuse_empty_values(app);
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
    return app.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    std::cerr << "multicpg: " << e.what() << "\n";
    return 2;
  } catch (const OptionError& e) {
    std::cerr << "multicpg: " << e.key() << " " << e.what() << "\n";
    return 2;
  } catch (const BadInput& e) {
    std::cerr << "multicpg: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "multicpg: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  multicpg::sim::install_mujoco_handlers();
  multicpg::set_command_line(argc, argv);
  return finish_stdout(run(argc, argv));
}
