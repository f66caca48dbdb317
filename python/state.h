// multicpg.State (python/state.cpp): a complete copy of a Simulation at one step.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string_view>

#include "learning/steering.h"
#include "python/robots.h"
#include "sim/stepper.h"

namespace multicpg::python {

namespace py = pybind11;

// What Simulation.state() returns: a complete copy of a run, immutable (restore copies it).
struct State {
  std::shared_ptr<Robot> robot;
  std::shared_ptr<const sim::StepperCheckpoint> checkpoint;
  std::optional<learning::SteeringState> steering;  // the reflex, when it steers
};

// A State as bytes: sealed CBOR (common/sealed_cbor.h) of its robot's key, its checkpoint
// (sim/checkpoint.h) and the reflex; and back (ValueError naming `name` for damaged bytes).
py::bytes state_bytes(const State& s);
State state_from_bytes(py::handle data, std::string_view name);

void register_state(py::module_& m);

}  // namespace multicpg::python
