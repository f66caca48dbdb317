#include "learning/learner.h"

#include <algorithm>
#include <limits>

namespace multicpg::learning {

std::vector<std::size_t> LearnerSetup::working() const {
  const std::vector<std::size_t>& failed = told.failed();
  std::vector<std::size_t> out;
  for (std::size_t leg = 0; leg < start.size(); ++leg) {
    if (std::find(failed.begin(), failed.end(), leg) == failed.end()) out.push_back(leg);
  }
  return out;
}

double detail_number(const TrialRecord& trial, const std::string& key) {
  const auto it = trial.details.find(key);
  if (it == trial.details.end()) return std::numeric_limits<double>::quiet_NaN();
  if (it->is_boolean()) return it->get<bool>() ? 1.0 : 0.0;
  if (it->is_number()) return it->get<double>();
  return std::numeric_limits<double>::quiet_NaN();
}

EpisodeEnd run_episode(Learner& learner, const EpisodeHooks& hooks) {
  EpisodeEnd end;
  while (learner.stop() == StopReason::running) {
    const std::optional<Periods> candidate = learner.propose();
    if (!candidate) break;
    const Measurement m = hooks.measure(end.trials + 1, *candidate);
    TrialRecord record = learner.observe(m);
    ++end.trials;
    const bool interrupted = hooks.decided && hooks.decided(record);
    end.trace.push_back(std::move(record));
    if (interrupted) break;
  }
  end.reason = learner.stop();
  end.answer = learner.answer();
  return end;
}

}  // namespace multicpg::learning
