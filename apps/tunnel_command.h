// `multicpg tunnel` without its printing (paper §5, Table 1): one home for the CLI and the Python
// API (issue 11), so both check the same flags and walk the same run.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "apps/learning_options.h"
#include "apps/sim_flags.h"
#include "experiments/tunnel.h"
#include "learning/compensation.h"
#include "sim/stepper.h"

namespace multicpg::apps {

struct TunnelRequest {
  std::string disable;
  std::optional<std::string> periods;  // --periods as given; none = every leg 4
  bool learn = false;                  // --learn: learn in the open field first
  LearningFlags learning;
  long max_steps = experiments::kTunnelMaxSteps;
  std::string video;  // .mp4 to film the tunnel walk; empty = none
  sim::SimOptions sim;
  BodyFlags body;
};

struct TunnelOutcome {
  std::vector<std::size_t> disabled;
  std::vector<int> periods;  // walked: given, or learned
  experiments::TunnelRun run;
  std::optional<learning::CompensationOptions> options;  // with --learn
  std::optional<learning::LearningResult> learned;       // with --learn
  double tunnel_length_m = 0.0;
  double tunnel_width_m = 0.0;
};

// Checks the request (BadInput, one line), then walks the hexapod through the tunnel, after
// learning if asked (`learning_observer`, may be null, sees the learning run), filming it if
// asked.
TunnelOutcome run_tunnel_command(const TunnelRequest& request,
                                 sim::Observer* learning_observer = nullptr);

// passed, touched_wall, steps, forward_m, lateral_m, deviation_deg, periods (leg name -> period)
// and, after learning, the learning result and its options: `tunnel --json`.
nlohmann::json tunnel_json(const robot::Morphology& morph, const TunnelOutcome& outcome);

}  // namespace multicpg::apps
