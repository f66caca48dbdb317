#include "python/values.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "python/args.h"

namespace multicpg::python {

using Json = nlohmann::json;

namespace {

// A leg's place in morphology order (robot/morphology.cpp: the right legs front to back, then the
// left), from its name "R1".."Rn", "L1".."Ln"; none for any other key.
std::optional<std::pair<int, long>> leg_place(const std::string& key) {
  if (key.size() < 2 || (key[0] != 'R' && key[0] != 'L') || key[1] == '0') return std::nullopt;
  long number = 0;
  for (std::size_t i = 1; i < key.size(); ++i) {
    if (key[i] < '0' || key[i] > '9' || i > 3) return std::nullopt;
    number = number * 10 + (key[i] - '0');
  }
  return std::pair{key[0] == 'R' ? 0 : 1, number};
}

// An object's keys in the order its dict shows them: JSON objects keep their keys sorted (L1 before
// R1), so an object of legs alone is put back in leg order; any other keeps the sorted order.
std::vector<std::string> key_order(const Json& object) {
  std::vector<std::string> keys;
  bool legs = !object.empty();
  for (const auto& [key, value] : object.items()) {
    keys.push_back(key);
    legs = legs && leg_place(key).has_value();
  }
  if (legs) {
    std::sort(keys.begin(), keys.end(), [](const std::string& a, const std::string& b) {
      return *leg_place(a) < *leg_place(b);
    });
  }
  return keys;
}

}  // namespace

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
      for (const std::string& key : key_order(j)) out[py::str(key)] = to_python(j.at(key));
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
