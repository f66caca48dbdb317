#include "python/values.h"

#include "python/args.h"

namespace multicpg::python {

using Json = nlohmann::json;

py::object to_python(const Json& j) {
  switch (j.type()) {
    case Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(j.get<double>());
    case Json::value_t::string:
      return py::str(j.get<std::string>());
    case Json::value_t::array: {
      py::list out;
      for (const Json& item : j) out.append(to_python(item));
      return out;
    }
    case Json::value_t::object: {
      py::dict out;
      for (const auto& [key, value] : j.items()) out[py::str(key)] = to_python(value);
      return out;
    }
    default:
      return py::none();
  }
}

Json to_json(py::handle value, std::string_view name) {
  // json.dumps knows which Python values are plain data (and refuses NaN here, as JSON does).
  const py::object dumps = py::module_::import("json").attr("dumps");
  std::string text;
  try {
    text = dumps(value, py::arg("allow_nan") = false).cast<std::string>();
  } catch (const py::error_already_set& e) {
    if (!e.matches(PyExc_TypeError) && !e.matches(PyExc_ValueError)) throw;
    type_error(name, "plain data (dict, list, str, int, float, bool, None)", value);
  }
  return Json::parse(text);
}

py::tuple pickled_tuple(const py::object& state, std::size_t size, const std::string& what) {
  if (!py::isinstance<py::tuple>(state) || py::len(state) != size) {
    throw py::value_error(what + ": not a pickled multicpg." + what);
  }
  return py::reinterpret_borrow<py::tuple>(state);
}

}  // namespace multicpg::python
