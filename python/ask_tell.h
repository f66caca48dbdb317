// multicpg.Learner, the ask/tell learner in Python (python/ask_tell.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace multicpg::python {

void register_ask_tell(pybind11::module_& m);

}  // namespace multicpg::python
