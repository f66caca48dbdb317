// Faults in Python: multicpg.Fault and multicpg.Recovery, a run's fault timeline as immutable
// objects (their checks and the CLI's text are python/args.h's).
#include "python/faults.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "python/args.h"
#include "python/typed.h"
#include "python/values.h"

namespace multicpg::python {
namespace {

std::string fault_repr(const FaultArg& f) {
  py::list names;
  for (const std::string& leg : f.legs) names.append(leg);
  std::string out = std::string(f.recover ? "multicpg.Recovery" : "multicpg.Fault") + "(";
  if (!f.legs.empty()) out += "legs=" + py::repr(names).cast<std::string>() + ", ";
  out += "step=" + std::to_string(f.step);
  if (f.kind != kLegFault) out += ", kind='" + f.kind + "'";
  if (f.joint) out += ", joint='" + *f.joint + "'";
  if (f.value) out += ", value=" + py::repr(py::float_(*f.value)).cast<std::string>();
  return out + ")";
}

py::tuple fault_state(const FaultArg& f) {
  return py::make_tuple(
      f.legs.empty() ? py::object(py::none()) : py::object(py::tuple(py::cast(f.legs))), f.step,
      f.kind, f.joint ? py::object(py::str(*f.joint)) : py::none(),
      f.value ? py::object(py::float_(*f.value)) : py::none());
}

// The tuple a pickled object of `what` holds.
// A Recovery is a Fault whose legs work again.
struct RecoveryArg : FaultArg {};

}  // namespace

void register_faults(py::module_& m) {
  namespace mp = multicpg::python;
  using py::arg;
  py::class_<mp::FaultArg>(
      m, "Fault",
      "What breaks before controller step `step` of a run (paper §4; docs/faults.md).\n"
      "kind: 'leg' (the whole leg holds its disabled posture, the paper's fault), 'locked' (a\n"
      "joint stuck at the angle it had, or at `value` rad), 'passive' (a joint's motor off),\n"
      "'weak' (the torque limit times `value` in (0, 1]), 'short' (the tibia shortened to\n"
      "`value` of its length), 'slip' (the foot's friction times `value`), 'drift' (the yaw\n"
      "sensor drifts `value` deg/s) or 'noise' (the yaw sensor's noise, `value` deg).\n"
      "legs: leg names, as a list or 'R1,R3' (None for the sensor's kinds); joint: 'TC', 'CTr'\n"
      "or 'FTi' for one joint of each leg (locked and passive need one). Legs are checked\n"
      "against the robot when a run uses the fault. A Fault is immutable, comparable, hashable\n"
      "and picklable; str() gives the CLI's text, e.g. 'R2.CTr:locked@600'.")
      .def(py::init([](mp::LegsArg legs, mp::IntArg step, mp::StrArg kind, mp::OptionalStrArg joint,
                       mp::OptionalFloatArg value) {
             return mp::make_fault(legs, step, kind, joint, value, false);
           }),
           arg("legs") = py::none(), arg("step") = 0, py::kw_only(), arg("kind") = mp::kLegFault,
           arg("joint") = py::none(), arg("value") = py::none())
      .def_property_readonly(
          "kind", [](const mp::FaultArg& f) { return f.kind; },
          "what breaks: leg, locked, passive, weak, short, slip, drift or noise")
      .def_property_readonly(
          "legs", [](const mp::FaultArg& f) { return py::tuple(py::cast(f.legs)); },
          "the legs, as named (empty for the yaw sensor)")
      .def_property_readonly(
          "joint", [](const mp::FaultArg& f) { return f.joint; },
          "the joint of each leg, or None for whole legs")
      .def_property_readonly(
          "value", [](const mp::FaultArg& f) { return f.value; },
          "the kind's value (factor, fraction, angle, deg/s or deg), or None")
      .def_property_readonly(
          "step", [](const mp::FaultArg& f) { return f.step; },
          "the controller step it comes before")
      .def_property_readonly(
          "recover", [](const mp::FaultArg& f) { return f.recover; },
          "True for a Recovery: what broke works again")
      .def("__eq__",
           [](const mp::FaultArg& a, py::object b) -> py::object {
             if (!py::isinstance<mp::FaultArg>(b))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const auto& f = b.cast<const mp::FaultArg&>();
             return py::bool_(a.kind == f.kind && a.legs == f.legs && a.step == f.step &&
                              a.recover == f.recover && a.joint == f.joint && a.value == f.value);
           })
      .def("__hash__",
           [](const mp::FaultArg& f) {
             return py::hash(py::make_tuple(mp::fault_state(f), f.recover));
           })
      .def("__repr__", &mp::fault_repr)
      .def("__str__", &mp::fault_text)
      .def(py::pickle([](const mp::FaultArg& f) -> py::object { return mp::fault_state(f); },
                      [](const py::object& state) {
                        const py::tuple t = mp::pickled_tuple(state, 5, "Fault");
                        return mp::make_fault(t[0], t[1], t[2], t[3], t[4], false);
                      }));
  py::class_<mp::RecoveryArg, mp::FaultArg>(
      m, "Recovery",
      "What broke works again before controller step `step` (paper §2.3: when every leg works\n"
      "again the clients resynchronise). Arguments as for Fault; a value may be left out.")
      .def(py::init([](mp::LegsArg legs, mp::IntArg step, mp::StrArg kind, mp::OptionalStrArg joint,
                       mp::OptionalFloatArg value) {
             mp::RecoveryArg r;
             static_cast<mp::FaultArg&>(r) = mp::make_fault(legs, step, kind, joint, value, true);
             return r;
           }),
           arg("legs") = py::none(), arg("step") = 0, py::kw_only(), arg("kind") = mp::kLegFault,
           arg("joint") = py::none(), arg("value") = py::none())
      .def(py::pickle([](const mp::RecoveryArg& f) -> py::object { return mp::fault_state(f); },
                      [](const py::object& state) {
                        const py::tuple t = mp::pickled_tuple(state, 5, "Recovery");
                        mp::RecoveryArg r;
                        static_cast<mp::FaultArg&>(r) =
                            mp::make_fault(t[0], t[1], t[2], t[3], t[4], true);
                        return r;
                      }));
}

}  // namespace multicpg::python
