#include "experiments/run_spec.h"

#include <algorithm>

#include "common/errors.h"
#include "common/limits.h"
#include "robot/body_models.h"
#include "robot/leg_sets.h"
#include "sim/robot_file.h"
#include "sim/walk.h"

namespace multicpg::experiments {

sim::StartSpec learning_start(learning::Mode mode) {
  sim::StartSpec start;
  if (mode == learning::Mode::paper) start.warmup = 0;
  return start;
}

const robot::Morphology& morphology(const RunSpec& spec) {
  return robot::morphology(spec.robot);
}

sim::SimModel make_run_model(const RunSpec& spec) {
  return make_run_model(spec, spec.sim);
}

sim::SimModel make_run_model(const RunSpec& spec, const sim::SimOptions& options) {
  return spec.robot_file ? sim::make_sim_model(spec.robot_file->file, options)
                         : sim::make_sim_model(spec.robot, options);
}

namespace {

// A robot file's body is its MJCF: of the body
// parameters only those of the controller apply (the disabled legs' posture and the body lift,
// robot/body_params.h).
void validate_file_robot(const sim::SimOptions& options) {
  if (options.model != robot::kDefaultBodyModel) {
    throw OptionError("sim.model", "a robot file's body is its model (docs/robots.md)");
  }
  const robot::BodyParams defaults = robot::body_params(robot::kDefaultBodyModel);
  for (const robot::NumberParam& p : robot::number_params()) {
    const bool controller = p.key == "lift_body" || p.key.starts_with("disabled_posture");
    if (!controller && p.get(options.body) != p.get(defaults)) {
      throw OptionError("sim.body." + std::string(p.key),
                        "a robot file's body is its model (docs/robots.md)");
    }
  }
}

}  // namespace

void validate(const RunSpec& spec) {
  const robot::Morphology& morph = morphology(spec);
  within("sim", [&] { sim::validate(spec.sim, spec.robot); });
  if (spec.robot_file) validate_file_robot(spec.sim);
  const std::vector<int>& periods = spec.start.periods;
  if (!periods.empty() && periods.size() != morph.size()) {
    throw OptionError("start.periods", "the " + morph.name + " takes " +
                                           std::to_string(morph.size()) + " periods, got " +
                                           std::to_string(periods.size()));
  }
  for (int p : periods) {
    if (!robot::is_gait_period(p)) throw OptionError("start.periods", robot::no_gait_message(p));
  }
  require_in("start.warmup", spec.start.warmup, sim::kStepLimits);
  try {
    sim::validate(morph, spec.faults);
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
    within("learner", [&] {
      learning::check_learner(spec.learning->learner, spec.robot, sim::failing_legs(spec.faults));
    });
  });
  if (spec.faults.empty()) {
    throw OptionError("faults", "a learning run needs a leg that fails: there is nothing to learn");
  }
  if (std::adjacent_find(periods.begin(), periods.end(), std::not_equal_to<>()) != periods.end()) {
    throw OptionError("start.periods",
                      "a learning run starts with every leg at one period, its clients "
                      "synchronised (paper §2.3)");
  }
}

}  // namespace multicpg::experiments
