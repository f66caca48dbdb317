// multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).
// Exit codes: 0 success, 2 bad input, 1 runtime failure.
#include <iostream>

#include "apps/commands.h"
#include "common/errors.h"

int main(int argc, char** argv) {
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    std::cerr << "multicpg: " << e.what() << "\n";
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
