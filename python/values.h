// Values between the libraries and Python: JSON as the objects json.loads gives (and back), and
// vectors as NumPy arrays.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace multicpg::python {

namespace py = pybind11;

// nlohmann::json -> the Python objects json.loads would give.
py::object to_python(const nlohmann::json& j);
// Plain Python data (dict, list, str, numbers, bools, None) -> JSON; anything else is a
// TypeError naming `name`.
nlohmann::json to_json(py::handle value, std::string_view name);

template <typename T>
py::array_t<T> array(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// The tuple a pickled object of `what` holds.
py::tuple pickled_tuple(const py::object& state, std::size_t size, const std::string& what);

}  // namespace multicpg::python
