// The Python API's module: multicpg._multicpg, re-exported by the package python/multicpg.
// Robots (python/robots.h), faults, states and simulations, learning and the tunnel each have a
// file; every argument is checked there before it reaches the libraries (python/args.h,
// python/keywords.h): a wrong type raises TypeError, a wrong value ValueError, each naming the
// Python parameter; a failed run raises RuntimeError. Results are the CLI's JSON as Python
// objects. Long runs release the GIL, so Python threads run in parallel, and look at signals as
// they go (python/watch.h). MuJoCo's fatal errors become RuntimeError here instead of ending the
// interpreter (sim/mujoco_guard.h).
#include <mujoco/mujoco.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/provenance.h"
#include "learning/annealing.h"
#include "learning/compensation.h"
#include "learning/landscapes.h"
#include "learning/steering.h"
#include "python/args.h"
#include "python/ask_tell.h"
#include "python/faults.h"
#include "python/learning.h"
#include "python/replay.h"
#include "python/robots.h"
#include "python/simulations.h"
#include "python/state.h"
#include "python/typed.h"
#include "report/render.h"
#include "robot/leg_sets.h"
#include "sim/mujoco_guard.h"
#include "sim/stepper.h"

namespace py = pybind11;
namespace mp = multicpg::python;

PYBIND11_MODULE(_multicpg, m) {
  namespace learning = multicpg::learning;
  namespace sim = multicpg::sim;
  namespace body = multicpg::body;
  namespace report = multicpg::report;
  using py::arg;
  m.doc() = "multicpg: multiple chaotic CPGs driving MuJoCo robots, and their learning.";
  mp::register_replay(m);
  // One bad call must not end the interpreter: MuJoCo's fatal errors become RuntimeError.
  sim::recover_mujoco_errors();
  // Bad input is the caller's mistake (CLI exit 2), a failed run is not (CLI exit 1).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const multicpg::OptionError& e) {
      PyErr_SetString(PyExc_ValueError, (e.key() + " " + e.what()).c_str());
    } catch (const multicpg::BadInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const multicpg::Interrupted&) {
      // SIGINT asked the work to stop (an experiment, python/learning.cpp).
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const multicpg::RuntimeFailure& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const nlohmann::json::exception& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.attr("__version__") = MULTICPG_VERSION;
  m.def(
      "build_info",
      [] {
        const nlohmann::json info = multicpg::build_info(mj_versionString());
        return py::dict(arg("version") = info.at("version").get<std::string>(),
                        arg("git_commit") = info.at("git_commit").get<std::string>(),
                        arg("mujoco_version") = info.at("mujoco_version").get<std::string>(),
                        arg("compiler") = info.at("compiler").get<std::string>(),
                        arg("pybind11_version") = std::to_string(PYBIND11_VERSION_MAJOR) + "." +
                                                  std::to_string(PYBIND11_VERSION_MINOR) + "." +
                                                  std::to_string(PYBIND11_VERSION_PATCH));
      },
      "What this module is: version (the project's), git_commit it was built from ('+dirty'\n"
      "with uncommitted changes, 'unknown' outside a git checkout), mujoco_version, compiler\n"
      "and pybind11_version.");
  m.def(
      "landscape_dataset",
      [](mp::RobotArg robot, mp::BoolArg reflex) {
        return learning::repository_dataset(mp::robot_arg(robot)->spec.kind,
                                            mp::flag(reflex, "reflex"))
            .string();
      },
      arg("robot") = "hexapod", py::kw_only(), arg("reflex") = false,
      "The landscape dataset the prior-based learner learns from when its options name none,\n"
      "of `robot` (a Robot, a robot name or a robot file: its layout's) walked with the\n"
      "steering reflex or not (`reflex`: for robust runs that steer), as the path of its files\n"
      "without their extension, found on the search path: $MULTICPG_DATA, the data installed\n"
      "with this package, the source tree's data/ (docs/python.md \"Datasets\"). ValueError\n"
      "naming every place looked when none has it.");

  // The CLI's defaults and limits, for Python code that walks the same runs (multicpg.env).
  m.attr("DEFAULT_THRESHOLD_DEG") = learning::kDefaultThresholdDeg;
  m.attr("DEFAULT_WINDOW_STEPS") = learning::kDefaultWindowSteps;
  m.attr("DEFAULT_MAX_TRIALS") = learning::kDefaultMaxTrials;
  m.attr("DEFAULT_BETA") = learning::kDefaultBeta;
  m.attr("DEFAULT_HOLD_WINDOWS") = learning::kDefaultHoldWindows;
  m.attr("DEFAULT_MONITOR_WINDOWS") = learning::kDefaultMonitorWindows;
  m.attr("DEFAULT_MAX_EPISODES") = learning::kDefaultMaxEpisodes;
  m.attr("DETECTION_WINDOWS") = learning::kDefaultDetectionWindows;
  m.attr("STEERING_MAX_EFFORT") = learning::SteeringParams{}.max_effort;
  m.attr("PERIOD_SET") = py::tuple(py::cast(learning::AnnealingParams{}.period_set));
  m.attr("GAIT_PERIODS") = py::tuple(py::cast(std::vector<int>(
      multicpg::robot::kGaitPeriods.begin(), multicpg::robot::kGaitPeriods.end())));
  m.attr("MAX_STEPS") = body::kMaxSteps;
  {
    std::vector<std::string> names;
    for (const learning::LearnerInfo& l : learning::learner_list()) names.emplace_back(l.name);
    m.attr("LEARNERS") = py::tuple(py::cast(names));  // every registered learner, by name
  }
  m.attr("FRAME_SIDE_LIMITS") =
      py::make_tuple(report::kFrameSideLimits.lo, report::kFrameSideLimits.hi);

  mp::register_faults(m);
  mp::register_robots(m);
  mp::register_state(m);
  mp::register_simulations(m);
  mp::register_learning(m);
  mp::register_ask_tell(m);

  m.def(
      "_test_mujoco_error",
      [](const std::string& message) {
        const char* text = message.c_str();
        sim::mujoco_call([text] { mju_error(text); });
      },
      arg("message"),
      "Raises MuJoCo's fatal error inside a guarded call (a test of sim/mujoco_guard.h): it\n"
      "must come back as RuntimeError, the module usable.");
}
