// multicpg.replay's compiled half (python/multicpg/replay.py is the other): 3D replay pages
// (docs/replay.md) of a Simulation's next steps and of learn()'s results.
#pragma once

#include <pybind11/pybind11.h>

namespace multicpg::python {

// Adds _replay_simulation and _replay_result to the module.
void register_replay(pybind11::module_& m);

}  // namespace multicpg::python
