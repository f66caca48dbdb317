#include "python/run_args.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "common/errors.h"
#include "learning/annealing.h"
#include "learning/choice_options.h"
#include "learning/default_learner.h"
#include "learning/learners.h"
#include "learning/number_options.h"
#include "learning/steering.h"
#include "python/args.h"
#include "python/values.h"

namespace multicpg::python {
namespace {

// The Python argument that sets a RunSpec key, for messages.
std::string argument_of(const std::string& key) {
  if (key == "start.periods") return "periods";
  if (key == "start.warmup") return "warmup";
  if (key == "faults") return "disable/faults/recoveries";
  if (key == "hardware.file") return "hardware";
  if (key.rfind("sim.", 0) == 0) return sim_argument(key.substr(4));
  if (key == "learning.annealing.threshold_deg") return "threshold";
  if (key == "learning.window_steps") return "window";
  if (key == "learning.settle_steps") return "settle";
  if (key == "learning.learn_periods") return "period_learning";
  const std::string options = "learning.learner.options.";
  if (key.rfind(options, 0) == 0) return "learner_options['" + key.substr(options.size()) + "']";
  if (key.rfind("learning.learner", 0) == 0) return "learner";
  return key.substr(key.rfind('.') + 1);
}

// The keywords of the numeric learning options (learning/number_options.h) that are robust mode's
// alone (`robust`) or not, with their defaults.
Params number_params(bool robust) {
  learning::CompensationOptions defaults;
  Params out;
  for (const learning::LearningNumber& option : learning::kLearningNumbers) {
    std::visit(
        [&](const auto& n) {
          if (n.robust_only != robust) return;
          const auto& value = n.field(defaults);
          py::object fallback = py::none();
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::optional<long>>) {
            if (value) fallback = py::int_(*value);
          } else {
            fallback = py::cast(value);
          }
          out.push_back({learning::keyword(n.flag), fallback});
        },
        option);
  }
  return out;
}

// The keywords of the learning options set by a name or a switch (learning/choice_options.h)
// that are robust mode's alone (`robust`) or not, with their defaults.
Params name_params(bool robust) {
  const learning::CompensationOptions defaults;
  Params out;
  for (const learning::NameOption& option : learning::kLearningNames) {
    if (option.robust_only == robust) {
      out.push_back({learning::keyword(option.flag), py::str(std::string(option.get(defaults)))});
    }
  }
  return out;
}

Params switch_params(bool robust) {
  learning::CompensationOptions defaults;
  Params out;
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    if (option.robust_only == robust) {
      out.push_back({learning::keyword(option.flag), py::bool_(option.field(defaults))});
    }
  }
  return out;
}

// What resolve_learner's keys are in Python.
std::string learner_argument(const std::string& key) {
  const std::string options = "options.";
  if (key.rfind(options, 0) == 0) return "learner_options['" + key.substr(options.size()) + "']";
  return "learner";
}

}  // namespace

Params fault_params() {
  return {{"disable", py::none()},
          {"disable_at", py::int_(0)},
          {"faults", py::none()},
          {"recoveries", py::none()}};
}

body::FaultTimeline fault_timeline(const robot::Morphology& morph, const Keywords& k) {
  const long at = whole(k["disable_at"], "disable_at", body::kStepLimits);
  body::FaultTimeline timeline = body::fail_at(legs(morph, k["disable"], "disable"), at);
  for (body::Fault& f : faults(morph, k["faults"], "faults", false)) {
    timeline.push_back(std::move(f));
  }
  for (body::Fault& f : faults(morph, k["recoveries"], "recoveries", true)) {
    timeline.push_back(std::move(f));
  }
  body::sort_timeline(timeline);
  return timeline;
}

Params robust_params() {
  return join({name_params(true), number_params(true), switch_params(true)});
}

Params learning_params() {
  return join({name_params(false),
               {{"learner", py::none()}, {"learner_options", py::none()}},
               robust_params(),
               {{"beta", py::float_(learning::kDefaultBeta)}},
               number_params(false),
               switch_params(false),
               {{"seed", py::int_(1)}}});
}

learning::CompensationOptions learning_options(const Keywords& k,
                                               const experiments::RobotSpec* robot,
                                               const body::FaultTimeline& faults) {
  learning::CompensationOptions o;
  for (const learning::NameOption& option : learning::kLearningNames) {
    const std::string name = learning::keyword(option.flag);
    const std::string value = text(k[name], name);
    named(name, [&] { option.set(o, value); });
  }
  if (o.mode == learning::Mode::paper) {
    // Paper mode has none of these (the CLI refuses their flags the same way).
    std::string given;
    for (const std::string& name : k.given_of(robust_params())) {
      given += (given.empty() ? "" : ", ") + name;
    }
    if (!given.empty()) {
      std::string robust;
      for (const Param& p : robust_params()) robust += (robust.empty() ? "" : ", ") + p.name;
      value_error("mode", "'paper' takes none of the robust-mode arguments " + robust +
                              " (given: " + given + ")");
    }
  }
  if (o.mode == learning::Mode::paper) o.steering = learning::Steering::off;  // as it runs
  for (const learning::LearningNumber& option : learning::kLearningNumbers) {
    std::visit(
        [&](const auto& n) {
          using T = typename std::decay_t<decltype(n)>::Value;
          using Stored = std::decay_t<decltype(n.field(o))>;
          const std::string name = learning::keyword(n.flag);
          // None: the default the run works out (settle's); other options take no None.
          if constexpr (std::is_same_v<Stored, std::optional<T>>) {
            if (k[name].is_none()) return;
          }
          if constexpr (std::is_floating_point_v<T>) {
            n.field(o) = real(k[name], name, n.limits);
          } else {
            n.field(o) = whole(k[name], name, n.limits);
          }
        },
        option);
  }
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    const std::string name = learning::keyword(option.flag);
    option.field(o) = flag(k[name], name);
  }
  if (!k["learner"].is_none()) o.learner.name = text(k["learner"], "learner");
  const py::object options = k["learner_options"];
  if (!options.is_none()) {
    if (!PyDict_Check(options.ptr())) {
      type_error("learner_options", "a dict of the learner's options", options);
    }
    o.learner.options = to_json(options, "learner_options");
  }
  // beta is the annealing's option (learning/learners.h), given as its own keyword as on the CLI.
  const double beta = real(k["beta"], "beta", learning::kBetaLimits);
  if (k["learner"].is_none() && robot) {
    o.learner.name =
        learning::default_learner({o, robot->kind, robot->file != nullptr, k.given("beta"), faults})
            .name;
  }
  if (k.given("beta")) {
    if (o.learner.name != learning::kPaperLearner) {
      value_error("beta",
                  "is the annealing's option; the learner '" + o.learner.name + "' has none");
    }
    if (o.learner.options.contains("beta")) {
      value_error("beta", "is given twice (also in learner_options)");
    }
    o.learner.options["beta"] = beta;
  }
  try {
    o.learner = learning::resolve_learner(o.learner);
  } catch (const OptionError& e) {
    value_error(learner_argument(e.key()), e.what());
  }
  o.seed = seed(k["seed"], "seed");
  return o;
}

void add_number_options(py::dict& out, const learning::CompensationOptions& o) {
  learning::CompensationOptions options = o;
  for (const learning::LearningNumber& option : learning::kLearningNumbers) {
    std::visit(
        [&](const auto& n) {
          const auto& value = n.field(options);
          const std::string name = learning::keyword(n.flag);
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::optional<long>>) {
            out[name.c_str()] = value ? py::object(py::int_(*value)) : py::none();
          } else {
            out[name.c_str()] = value;
          }
        },
        option);
  }
}

Params progress_params() {
  return {{"progress", py::bool_(true)}};
}

Params hardware_params() {
  return {{"hardware", py::none()}, {"lock_step", py::bool_(false)}};
}

std::optional<experiments::HardwareSetup> hardware_setup(const Keywords& k,
                                                         experiments::RunSpec& spec) {
  const bool lock_step = flag(k["lock_step"], "lock_step");
  if (k["hardware"].is_none()) {
    if (lock_step) value_error("lock_step", "needs hardware: it paces a real robot's run");
    return std::nullopt;
  }
  spec.hardware = experiments::HardwareSpec{path(k["hardware"], "hardware"), lock_step};
  try {
    return experiments::hardware_setup(spec);
  } catch (const OptionError& e) {
    value_error(argument_of(e.key()), e.what());
  } catch (const BadInput& e) {
    value_error("hardware", e.what());
  }
}

experiments::RunSpec run_spec(const Robot& robot, body::StartSpec start, body::FaultTimeline faults,
                              std::optional<learning::CompensationOptions> learning) {
  experiments::RunSpec spec;
  spec.robot = robot.spec;
  spec.faults = std::move(faults);
  if (learning) {
    spec.start = experiments::learning_start(learning->mode);
    spec.learning = std::move(learning);
  } else {
    spec.start = std::move(start);
  }
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    value_error(argument_of(e.key()), e.what());
  }
  return spec;
}

}  // namespace multicpg::python
