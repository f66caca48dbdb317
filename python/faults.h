// multicpg.Fault and multicpg.Recovery (python/faults.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace multicpg::python {

void register_faults(pybind11::module_& m);

}  // namespace multicpg::python
