// What `multicpg reproduce` is asked for (report/reproduce.h), as every stage sees it
// (report/stages/stage.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/sim_options.h"

namespace multicpg::report {

struct ReproduceOptions {
  std::filesystem::path out;
  bool quick = false;  // fewer runs and faster videos: minutes, not tens of minutes
  int jobs = 0;        // parallel learning runs and stages; 0 = every core
  std::uint64_t seed = 1;
  // The simulation of every stage: its body model and parameters (--model and the Body flags);
  // paper-sim, the paper's simulator, by default.
  sim::SimOptions sim;
  bool progress = true;
  // Stages to run (stage ids, see reproduce_stages()); empty = all; the stages they need run
  // too. index.html shows those done.
  std::vector<std::string> only;
};

}  // namespace multicpg::report
