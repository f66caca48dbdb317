// Long calls that can be stopped and watched. A Watch is the observer of a run the API walks
// without the GIL (learn, tunnel, Simulation.step, walk_window, film): every kPollSeconds it
// takes the GIL briefly, lets Python run its signal handlers (Ctrl-C or a Jupyter interrupt
// raises KeyboardInterrupt out of the call; the run stops between two steps, so the objects it
// walked stay usable) and reports progress: a tqdm bar (multicpg/_progress.py), or the caller's
// own callable, or nothing.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <optional>
#include <string>
#include <string_view>

#include "robot/morphology.h"
#include "sim/stepper.h"

namespace multicpg::python {

namespace py = pybind11;

// How often a run looks at signals and reports: well inside the half second a Ctrl-C may take.
inline constexpr std::chrono::milliseconds kPollInterval{100};

class Watch final : public sim::Observer {
 public:
  // progress: True (a bar once the call has run half a second), False, or a callable given a
  // dict per report (stage, steps, total, trials, deviation_deg, finished). `total`: the steps
  // the call walks, 0 when unknown. `trials` (None or a callable) is called after every
  // learning trial with its episode, trial, step, periods, deviation_deg and accepted.
  // Made and destroyed with the GIL held.
  Watch(py::handle progress, std::string stage, long total, py::object trials = py::none(),
        const robot::Morphology* morph = nullptr);
  ~Watch() override;
  Watch(const Watch&) = delete;
  Watch& operator=(const Watch&) = delete;

  void on_step(const sim::SimModel& model, const sim::SimState& state) override;
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override;
  // The last report (finished), with the GIL held; the bar closes.
  void finish();

 private:
  // With the GIL: signals first (throws py::error_already_set), then the report.
  void poll();
  void report(bool finished);
  void close();

  py::object progress_;  // None, or a callable
  std::string stage_;
  long total_;
  py::object trials_;
  const robot::Morphology* morph_;
  long steps_ = 0;
  int trial_count_ = 0;
  std::optional<double> deviation_;
  std::chrono::steady_clock::time_point last_poll_;
};

}  // namespace multicpg::python
