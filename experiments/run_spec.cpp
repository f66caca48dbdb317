#include "experiments/run_spec.h"

#include <algorithm>

#include "common/errors.h"
#include "common/limits.h"
#include "robot/leg_sets.h"
#include "sim/walk.h"

namespace multicpg::experiments {

body::StartSpec learning_start(learning::Mode mode) {
  body::StartSpec start;
  if (mode == learning::Mode::paper) start.warmup = 0;
  return start;
}

void validate(const RunSpec& spec) {
  const robot::Morphology& morph = morphology(spec.robot);
  validate(spec.robot);
  const std::vector<int>& periods = spec.start.periods;
  if (!periods.empty() && periods.size() != morph.size()) {
    throw OptionError("start.periods", "the " + morph.name + " takes " +
                                           std::to_string(morph.size()) + " periods, got " +
                                           std::to_string(periods.size()));
  }
  for (int p : periods) {
    if (!robot::is_gait_period(p)) throw OptionError("start.periods", robot::no_gait_message(p));
  }
  require_in("start.warmup", spec.start.warmup, body::kStepLimits);
  try {
    body::validate(morph, spec.faults);
  } catch (const OptionError&) {
    throw;
  } catch (const BadInput& e) {
    throw OptionError("faults", e.what());
  }
  require_in("record.check_windows", spec.record.check_windows, kCheckWindowsLimits);
  if (!spec.learning) return;
  within("learning", [&] {
    learning::validate(*spec.learning);
    learning::validate_faults(*spec.learning, spec.faults);
  });
  // Before any walk, the detection's too (a real robot walks it).
  (void)learner_data(spec);
  if (spec.faults.empty()) {
    throw OptionError("faults", "a learning run needs a leg that fails: there is nothing to learn");
  }
  if (std::adjacent_find(periods.begin(), periods.end(), std::not_equal_to<>()) != periods.end()) {
    throw OptionError("start.periods",
                      "a learning run starts with every leg at one period, its clients "
                      "synchronised (paper §2.3)");
  }
}

learning::LearnerData learner_data(const RunSpec& spec) {
  if (!spec.learning) return {};
  learning::LearnerData data;
  within("learning", [&] {
    within("learner", [&] {
      // Told what every episode's learner is told (learning/compensation.cpp).
      data = learning::check_learner(
          spec.learning->learner, spec.robot.kind,
          spec.learning->tell_fault ? learning::ToldFault::legs(body::failing_legs(spec.faults))
                                    : learning::ToldFault::nothing(),
          learning::criterion(*spec.learning), spec.learning->search.period_set);
    });
  });
  return data;
}

}  // namespace multicpg::experiments
