#include "python/args.h"

#include <fmt/format.h>

#include <algorithm>

#include "body/fault_spec.h"
#include "body/faults.h"
#include "common/errors.h"
#include "neural/cpg.h"
#include "robot/morphology.h"

namespace multicpg::python {
namespace {

std::string item(std::string_view name, std::size_t index) {
  return fmt::format("{}[{}]", name, index);
}

bool is_text(py::handle value) {
  return PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()) ||
         PyByteArray_Check(value.ptr());
}

// A period that gives a gait (one of kGaitPeriods, all within the CPG's 1..9).
int gait_period(py::handle value, std::string_view name) {
  const long long p = whole(value, name, Limits<long long>{neural::kMinPeriod, neural::kMaxPeriod});
  if (!robot::is_gait_period(static_cast<int>(p))) {
    value_error(name, robot::no_gait_message(static_cast<int>(p)));
  }
  return static_cast<int>(p);
}

std::size_t leg_of(const robot::Morphology& morph, py::handle value, std::string_view name) {
  if (!PyUnicode_Check(value.ptr())) type_error(name, "a leg name (str)", value);
  return named(name, [&] { return robot::leg_index(morph, value.cast<std::string>()); });
}

// Items of a list-like argument, held (a NumPy array makes each item as it is iterated).
std::vector<py::object> items(py::handle value) {
  std::vector<py::object> out;
  for (py::handle h : value) out.push_back(py::reinterpret_borrow<py::object>(h));
  return out;
}

bool iterable(py::handle value) {
  return !is_text(value) && !PyDict_Check(value.ptr()) && py::isinstance<py::iterable>(value);
}

}  // namespace

std::string type_name(py::handle value) {
  const PyTypeObject* type = Py_TYPE(value.ptr());
  return type->tp_name;
}

void type_error(std::string_view name, std::string_view expected, py::handle got) {
  throw py::type_error(fmt::format("{}: expected {}, got {}", name, expected, type_name(got)));
}

void value_error(std::string_view name, std::string_view message) {
  throw py::value_error(fmt::format("{}: {}", name, message));
}

long long whole(py::handle value, std::string_view name, const Limits<long long>& limits) {
  if (value.is_none() || PyBool_Check(value.ptr()) || PyFloat_Check(value.ptr()) ||
      !PyIndex_Check(value.ptr()) || type_name(value) == "numpy.bool_") {
    type_error(name, "an int", value);
  }
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index) {
    PyErr_Clear();
    type_error(name, "an int", value);
  }
  int overflow = 0;
  const long long x = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (overflow != 0 || x < limits.lo || x > limits.hi) {
    value_error(name, fmt::format("must be in {}, got {}", limits.text(),
                                  py::str(index).cast<std::string>()));
  }
  return x;
}

double real(py::handle value, std::string_view name, const Limits<double>& limits) {
  if (value.is_none() || PyBool_Check(value.ptr()) || is_text(value) ||
      type_name(value) == "numpy.bool_") {
    type_error(name, "a number", value);
  }
  const double x = PyFloat_AsDouble(value.ptr());
  if (x == -1.0 && PyErr_Occurred() != nullptr) {
    PyErr_Clear();
    type_error(name, "a number", value);
  }
  if (!limits.contains(x))
    value_error(name, fmt::format("must be in {}, got {}", limits.text(), x));
  return x;
}

bool flag(py::handle value, std::string_view name) {
  if (!PyBool_Check(value.ptr()) && type_name(value) != "numpy.bool_") {
    type_error(name, "True or False", value);
  }
  return PyObject_IsTrue(value.ptr()) == 1;
}

std::string text(py::handle value, std::string_view name) {
  if (!PyUnicode_Check(value.ptr())) type_error(name, "a str", value);
  return value.cast<std::string>();
}

std::string path(py::handle value, std::string_view name) {
  if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
  const py::object fs = py::reinterpret_steal<py::object>(PyOS_FSPath(value.ptr()));
  if (!fs || !PyUnicode_Check(fs.ptr())) {
    PyErr_Clear();
    type_error(name, "a file name (str or os.PathLike)", value);
  }
  return fs.cast<std::string>();
}

py::object callable_or_none(py::handle value, std::string_view name) {
  if (!value.is_none() && PyCallable_Check(value.ptr()) == 0) {
    type_error(name, "a callable or None", value);
  }
  return py::reinterpret_borrow<py::object>(value);
}

std::uint64_t seed(py::handle value, std::string_view name) {
  return whole(value, name, kSeedLimits);
}

robot::LegSet legs(const robot::Morphology& morph, py::handle value, std::string_view name) {
  if (value.is_none()) return {};
  if (PyUnicode_Check(value.ptr())) {
    return named(name, [&] { return robot::parse_leg_set(morph, value.cast<std::string>()); });
  }
  if (!iterable(value)) type_error(name, "leg names (a list of str, or \"R1,R3\")", value);
  robot::LegSet out;
  const std::vector<py::object> names = items(value);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::size_t leg = leg_of(morph, names[i], item(name, i));
    if (std::find(out.begin(), out.end(), leg) != out.end()) {
      value_error(name, "leg " + morph.legs[leg].name + " is named twice");
    }
    out.push_back(leg);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> periods(const robot::Morphology& morph, py::handle value, std::string_view name,
                         int fallback) {
  constexpr std::string_view kExpected =
      "an int, a dict {leg: period} or one period per leg (list, tuple or array)";
  if (PyUnicode_Check(value.ptr())) {
    return named(
        name, [&] { return robot::parse_period_map(morph, value.cast<std::string>(), fallback); });
  }
  // An int for every leg (not an array: NumPy arrays have __index__ too).
  if (PyIndex_Check(value.ptr()) && PySequence_Check(value.ptr()) == 0 &&
      !PyBool_Check(value.ptr()) && type_name(value) != "numpy.bool_") {
    return std::vector<int>(morph.size(), gait_period(value, name));
  }
  if (PyDict_Check(value.ptr())) {
    std::vector<int> out(morph.size(), fallback);
    for (const auto& [key, period] : py::reinterpret_borrow<py::dict>(value)) {
      const std::size_t leg = leg_of(morph, key, name);
      out[leg] = gait_period(period, fmt::format("{}['{}']", name, morph.legs[leg].name));
    }
    return out;
  }
  // In leg order: a sequence (a set has none). A NumPy array of floats is one too; its items
  // then fail as floats do.
  if (is_text(value) || PySequence_Check(value.ptr()) == 0) type_error(name, kExpected, value);
  const std::vector<py::object> list = items(value);
  if (list.size() != morph.size()) {
    std::string order;
    for (const robot::Leg& leg : morph.legs) order += (order.empty() ? "" : " ") + leg.name;
    value_error(name, fmt::format("the {} takes {} periods, one per leg in the order {}; got {}",
                                  morph.name, morph.size(), order, list.size()));
  }
  std::vector<int> out;
  for (std::size_t i = 0; i < list.size(); ++i) out.push_back(gait_period(list[i], item(name, i)));
  return out;
}

FaultArg make_fault(py::handle legs_value, py::handle step, py::handle kind, py::handle joint,
                    py::handle value, bool recover) {
  FaultArg f;
  f.kind = text(kind, "kind");
  if (!value.is_none()) f.value = real(value, "value", Limits<double>{-1e300, 1e300});
  const body::Malfunction made = named("kind", [&] {
    // a recovery may leave out a value its fault needed (it ends whatever value it had)
    return body::make_kind(f.kind, f.value, recover);
  });
  if (!joint.is_none()) {
    f.joint = text(joint, "joint");
    named("joint", [&] { return robot::parse_joint(*f.joint); });
  }
  const body::Strikes target = body::strikes(made);
  if (target == body::Strikes::joints && !f.joint) {
    value_error("joint",
                fmt::format("a '{}' fault strikes one joint: name it (TC, CTr or FTi)", f.kind));
  }
  if (target == body::Strikes::legs && f.joint) {
    value_error("joint", fmt::format("a '{}' fault strikes whole legs, not a joint", f.kind));
  }
  if (target == body::Strikes::sensor) {
    if (f.joint) value_error("joint", fmt::format("a '{}' fault strikes the yaw sensor", f.kind));
    if (!legs_value.is_none()) {
      value_error("legs", fmt::format("a '{}' fault strikes the yaw sensor, no leg", f.kind));
    }
  } else if (PyUnicode_Check(legs_value.ptr())) {
    const std::string names = legs_value.cast<std::string>();
    std::size_t start = 0;
    while (start <= names.size()) {
      const std::size_t end = names.find_first_of(",+", start);
      f.legs.push_back(names.substr(start, end == std::string::npos ? end : end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
  } else if (iterable(legs_value)) {
    const std::vector<py::object> list = items(legs_value);
    for (std::size_t i = 0; i < list.size(); ++i) f.legs.push_back(text(list[i], item("legs", i)));
  } else {
    type_error("legs", "leg names (a list of str, or \"R1,R3\")", legs_value);
  }
  if (target != body::Strikes::sensor) {
    if (f.legs.empty() || (f.legs.size() == 1 && f.legs.front().empty())) {
      value_error("legs", "name at least one leg, e.g. [\"R1\"]");
    }
    for (const std::string& leg : f.legs) {
      if (leg.empty()) value_error("legs", "an empty leg name");
    }
  }
  f.step = whole(step, "step", Limits<long>{0, body::kMaxSteps});
  f.recover = recover;
  return f;
}

std::string fault_text(const FaultArg& f) {
  std::string out;
  for (const std::string& leg : f.legs) out += (out.empty() ? "" : ",") + leg;
  if (f.legs.empty()) out = body::kSensorTarget;
  if (f.joint) out += "." + *f.joint;
  if (f.kind != kLegFault) out += ":" + f.kind;
  if (f.value) out += fmt::format("={}", *f.value);
  return out + "@" + std::to_string(f.step);
}

body::FaultTimeline faults(const robot::Morphology& morph, py::handle value, std::string_view name,
                           bool recoveries) {
  body::FaultTimeline out;
  if (value.is_none()) return out;
  std::vector<py::object> list;
  if (PyUnicode_Check(value.ptr()) || py::isinstance<FaultArg>(value)) {
    list.push_back(py::reinterpret_borrow<py::object>(value));
  } else if (iterable(value)) {
    list = items(value);
  } else {
    type_error(name, "faults (a list of multicpg.Fault, multicpg.Recovery or \"LEGS@STEP\")",
               value);
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where =
        list.size() == 1 && !iterable(value) ? std::string(name) : item(name, i);
    const py::handle h = list[i];
    if (PyUnicode_Check(h.ptr())) {
      out.push_back(named(
          where, [&] { return body::parse_fault(morph, h.cast<std::string>(), recoveries); }));
      continue;
    }
    if (!py::isinstance<FaultArg>(h)) {
      type_error(where, "a multicpg.Fault, multicpg.Recovery or \"LEGS@STEP\"", h);
    }
    const FaultArg& f = h.cast<const FaultArg&>();
    if (recoveries && !f.recover) {
      value_error(where, "a Fault, not a Recovery (failures go in faults)");
    }
    // The object's own parts were checked when it was made; its legs are checked here, against
    // the robot, through the CLI's parser of its text (one parser, one set of messages).
    out.push_back(named(where, [&] { return body::parse_fault(morph, fault_text(f), f.recover); }));
  }
  return out;
}

}  // namespace multicpg::python
