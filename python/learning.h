// learn, tunnel, Annealer and experiments in Python (python/learning.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace multicpg::python {

void register_learning(pybind11::module_& m);

}  // namespace multicpg::python
