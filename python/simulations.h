// multicpg.Simulation, multicpg.State, render, film and measure_window (python/simulations.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace multicpg::python {

void register_simulations(pybind11::module_& m);

}  // namespace multicpg::python
