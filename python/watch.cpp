#include "python/watch.h"

#include "python/args.h"
#include "python/values.h"
#include "robot/leg_sets.h"

namespace multicpg::python {

Watch::Watch(py::handle progress, std::string stage, long total, py::object trials,
             const robot::Morphology* morph)
    : stage_(std::move(stage)),
      total_(total),
      trials_(callable_or_none(trials, "observer")),
      morph_(morph),
      last_poll_(std::chrono::steady_clock::now()) {
  if (PyBool_Check(progress.ptr())) {
    if (progress.ptr() == Py_True) {
      progress_ = py::module_::import("multicpg._progress")
                      .attr("Bar")(stage_, total_ > 0 ? py::object(py::int_(total_)) : py::none());
    } else {
      progress_ = py::none();
    }
  } else if (PyCallable_Check(progress.ptr()) != 0) {
    progress_ = py::reinterpret_borrow<py::object>(progress);
  } else {
    type_error("progress", "True, False or a callable", progress);
  }
}

Watch::~Watch() {
  try {
    close();
  } catch (...) {  // a bar that fails to close must not hide why the call ended
    PyErr_Clear();
  }
}

void Watch::on_step(const sim::SimModel& /*model*/, const sim::SimState& /*state*/) {
  ++steps_;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_poll_ < kPollInterval) return;
  last_poll_ = now;
  poll();
}

void Watch::on_event(const sim::SimModel& /*model*/, const sim::SimState& /*state*/,
                     const body::Event& e) {
  if (e.kind != body::EventKind::trial_end) return;
  ++trial_count_;
  deviation_ = e.deviation_deg;
  if (trials_.is_none()) return;
  const py::gil_scoped_acquire acquire;
  const py::object periods = morph_ != nullptr
                                 ? to_python(robot::period_map_json(*morph_, e.periods))
                                 : py::object(py::cast(e.periods));
  trials_(py::dict(py::arg("episode") = e.episode, py::arg("trial") = e.trial,
                   py::arg("step") = e.step, py::arg("periods") = periods,
                   py::arg("deviation_deg") = e.deviation_deg, py::arg("accepted") = e.accepted));
}

void Watch::poll() {
  const py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  report(false);
}

void Watch::report(bool finished) {
  if (progress_.is_none()) return;
  progress_(py::dict(
      py::arg("stage") = stage_, py::arg("steps") = steps_,
      py::arg("total") = total_ > 0 ? py::object(py::int_(total_)) : py::none(),
      py::arg("trials") = trial_count_,
      py::arg("deviation_deg") = deviation_ ? py::object(py::float_(*deviation_)) : py::none(),
      py::arg("finished") = finished));
}

void Watch::finish() {
  report(true);
  close();
}

void Watch::close() {
  if (progress_.is_none()) return;
  const py::object bar = std::move(progress_);
  progress_ = py::none();
  if (py::hasattr(bar, "close")) bar.attr("close")();
}

}  // namespace multicpg::python
