#include "learning/default_learner.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <variant>

#include "common/errors.h"
#include "learning/landscape_cache.h"
#include "learning/landscapes.h"

namespace multicpg::learning {

namespace {

constexpr std::string_view kPriorLearner = "prior";

// Whether the repository's dataset of `robot` walked the way `options` walks exists and has the
// run's period set: what the prior needs of a run besides the scenario (check_learner).
bool repository_dataset_fits(robot::RobotKind robot, const CompensationOptions& options) {
  std::filesystem::path path;
  try {
    path = repository_dataset(robot, options.steering == Steering::reflex);
  } catch (const BadInput&) {
    return false;  // none anywhere it looks: the annealing, which the run's header names
  }
  return read_landscape_dataset_once(path)->period_set == options.search.period_set;
}

}  // namespace

bool leg_losses_only(const body::FaultTimeline& faults) {
  return std::all_of(faults.begin(), faults.end(), [](const body::Fault& f) {
    return std::holds_alternative<body::LegFault>(f.kind);
  });
}

LearnerChoice default_learner(const DefaultLearnerQuery& query) {
  const CompensationOptions& o = query.options;
  LearnerChoice choice;
  if (o.mode == Mode::robust && o.learn_periods && o.tell_fault && !query.beta_given &&
      !query.robot_file && leg_losses_only(query.faults) &&
      repository_dataset_fits(query.robot, o)) {
    choice.name = std::string(kPriorLearner);
  }
  return resolve_learner(choice);
}

}  // namespace multicpg::learning
