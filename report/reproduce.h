// `multicpg reproduce`: every experiment of docs/learning.md "The paper's experiments" — figures,
// tables, videos and the tunnel — into one folder with an index.html that sets each beside what the
// paper reports. The stages themselves are in report/stages/ (one table, stage.h); this is the
// driver.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "sim/sim.h"

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

// The stage that draws a figure of figures.h's registry (e.g. "motor" -> "learning-r1"); throws
// BadInput naming the known figures for an unknown name, and for one no stage draws (landscape).
std::string stage_of_figure(std::string_view figure);

// Runs every stage not yet done in `out`, up to `jobs` stages at once (each finished stage is
// saved at once, so a run started again with the same options continues where it stopped) and
// writes out/index.html. Throws BadInput for an unwritable folder, an unknown stage or a folder
// made with other options.
void reproduce(const ReproduceOptions& options);

}  // namespace multicpg::report
