// Python arguments to the typed values of the libraries, each checked before it reaches them:
// a wrong type raises TypeError, a wrong value ValueError, both naming the parameter as Python
// code writes it ("periods: ...", "faults[1]: ..."), with the limits the CLI checks
// (common/limits.h and the Limits next to each option). pybind11's own conversions are not used
// for arguments: their errors name C++ types, and they accept what they should not (True as 1,
// 10**30 overflowing).
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "body/events.h"
#include "common/limits.h"
#include "robot/leg_sets.h"
#include "robot/morphology.h"

namespace multicpg::python {

namespace py = pybind11;

// The Python type of a value, as an error names it ("float", "NoneType", "numpy.float64").
std::string type_name(py::handle value);
[[noreturn]] void type_error(std::string_view name, std::string_view expected, py::handle got);
[[noreturn]] void value_error(std::string_view name, std::string_view message);

// Runs `parse` (a library parser throwing BadInput) and raises its message as a ValueError
// prefixed with `name`.
template <class Parse>
auto named(std::string_view name, const Parse& parse) {
  try {
    return parse();
  } catch (const BadInput& e) {
    value_error(name, e.what());
  }
}

// An int (or anything with __index__, such as numpy.int64; not bool) in `limits`.
long long whole(py::handle value, std::string_view name, const Limits<long long>& limits);
template <class T>
T whole(py::handle value, std::string_view name, const Limits<T>& limits) {
  return static_cast<T>(whole(
      value, name,
      Limits<long long>{static_cast<long long>(limits.lo), static_cast<long long>(limits.hi)}));
}
// A real number (int or float; not bool, not NaN or infinite) in `limits`.
double real(py::handle value, std::string_view name, const Limits<double>& limits);
// True or False (also numpy.bool_).
bool flag(py::handle value, std::string_view name);
// A str.
std::string text(py::handle value, std::string_view name);
// A str or os.PathLike naming a file.
std::string path(py::handle value, std::string_view name);
// None or a callable.
py::object callable_or_none(py::handle value, std::string_view name);
// A seed: common/limits.h kSeedLimits.
std::uint64_t seed(py::handle value, std::string_view name);

// Legs: None (none), "R1,R3" / "R1+R3", or an iterable of leg names.
robot::LegSet legs(const robot::Morphology& morph, py::handle value, std::string_view name);
// Periods: an int (every leg), {"R1": 5} (others keep `fallback`), one per leg in leg order (a
// list, tuple, range or NumPy array), or the CLI's text "R1=5,R2=4". Each must give a gait.
std::vector<int> periods(const robot::Morphology& morph, py::handle value, std::string_view name,
                         int fallback = robot::kDefaultPeriod);

// A fault as Python writes it (multicpg.Fault, multicpg.Recovery): what breaks (kind, and for
// a joint fault the joint, for a kind with a value its value, body/faults.h), on which legs (none
// for the yaw sensor's kinds), before which step. Its legs are names, checked against a robot
// when a run uses it; the kind, joint and value are checked when it is made.
struct FaultArg {
  std::string kind;
  std::vector<std::string> legs;
  long step = 0;
  bool recover = false;
  std::optional<std::string> joint;
  std::optional<double> value;
};
// The paper's fault: the whole leg holds its disabled posture.
inline constexpr std::string_view kLegFault = "leg";
FaultArg make_fault(py::handle legs, py::handle step, py::handle kind, py::handle joint,
                    py::handle value, bool recover);
// The CLI's text of a fault, "R1,R3@600", "R2.CTr:locked@100", "imu:noise=1@0".
std::string fault_text(const FaultArg& f);

// A fault timeline entry list: None, one item or an iterable of items, each a Fault, a Recovery
// or the CLI's text "R1,R3@600" (a failure, or in `recoveries` a recovery).
body::FaultTimeline faults(const robot::Morphology& morph, py::handle value, std::string_view name,
                           bool recoveries);

}  // namespace multicpg::python
