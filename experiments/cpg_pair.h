// A master CPG and one client (paper Fig. 6): synchronised by Eq. 5 or independent.
#pragma once

#include <vector>

#include "neural/cpg.h"

namespace multicpg::experiments {

struct CpgPairSample {
  double master_x1, master_x2, client_x1, client_x2;
};

struct CpgPairOptions {
  int master_period = 5;
  int client_period = 5;
  bool synchronised = true;
  bool chaotic = false;  // both CPGs uncontrolled
  long steps = 200;
};

std::vector<CpgPairSample> run_cpg_pair(const neural::CpgParams& params,
                                        const CpgPairOptions& options);

// A controlled orbit is unstable and held by a tiny control input, so it converges only
// geometrically (to about 1e-14, never bit for bit); orbits closer than this count as periodic.
inline constexpr double kOrbitTolerance = 1e-6;

// Smallest period (<= max_period) with which the last `tail` samples of `values` repeat within
// kOrbitTolerance; 0 when none does.
int orbit_period(const std::vector<double>& values, int max_period, std::size_t tail);

}  // namespace multicpg::experiments
