#include "experiments/cpg_pair.h"

#include <cmath>

#include "common/interrupt.h"

namespace multicpg::experiments {

std::vector<CpgPairSample> run_cpg_pair(const neural::CpgParams& params,
                                        const CpgPairOptions& options) {
  neural::CpgState master;
  neural::CpgState client;
  neural::cpg_reset(params, master, options.master_period);
  neural::cpg_reset(params, client, options.client_period);
  master.chaotic = client.chaotic = options.chaotic;
  const double alpha = options.synchronised ? 1.0 : 0.0;
  std::vector<CpgPairSample> out;
  out.reserve(options.steps);
  for (long t = 0; t < options.steps; ++t) {
    check_interrupted();
    neural::cpg_step(params, master);
    neural::cpg_step(params, client, neural::SyncInput{alpha, master.x1});
    out.push_back({master.x1, master.x2, client.x1, client.x2});
  }
  return out;
}

int orbit_period(const std::vector<double>& values, int max_period, std::size_t tail) {
  if (values.size() < tail + static_cast<std::size_t>(max_period)) return 0;
  const std::size_t begin = values.size() - tail;
  for (int p = 1; p <= max_period; ++p) {
    bool periodic = true;
    for (std::size_t i = begin; i < values.size() && periodic; ++i) {
      periodic = std::abs(values[i] - values[i - p]) < kOrbitTolerance;
    }
    if (periodic) return p;
  }
  return 0;
}

}  // namespace multicpg::experiments
