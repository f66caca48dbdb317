#include "python/state.h"

#include <nlohmann/json.hpp>
#include <string>

#include "common/sealed_cbor.h"
#include "learning/json.h"
#include "python/args.h"
#include "python/typed.h"
#include "sim/checkpoint.h"

namespace multicpg::python {

using Json = nlohmann::json;

namespace {

constexpr const char* kStateFormat = "multicpg state";
constexpr int kStateVersion = 1;

}  // namespace

py::bytes state_bytes(const State& s) {
  const Json document{{"format", kStateFormat},
                      {"version", kStateVersion},
                      {"robot", robot_key(s.robot->spec)},
                      {"checkpoint", sim::checkpoint_json(*s.robot->model, *s.checkpoint)},
                      {"steering", s.steering ? Json(*s.steering) : Json()}};
  std::string bytes;
  {
    const py::gil_scoped_release release;
    bytes = seal_cbor(document);
  }
  return py::bytes(bytes);
}

State state_from_bytes(py::handle data, std::string_view name) {
  if (!PyBytes_Check(data.ptr()) && !PyByteArray_Check(data.ptr()) &&
      !PyMemoryView_Check(data.ptr())) {
    type_error(name, "the bytes of a multicpg.State", data);
  }
  const py::bytes copy = PyBytes_Check(data.ptr())
                             ? py::reinterpret_borrow<py::bytes>(data)
                             : py::reinterpret_steal<py::bytes>(PyBytes_FromObject(data.ptr()));
  const std::string bytes = copy;
  Json document;
  document = named(name, [&] { return unseal_cbor(bytes); });
  try {
    if (!document.is_object() || document.value("format", "") != kStateFormat ||
        document.at("version").get<int>() != kStateVersion) {
      value_error(name, "not a multicpg.State of this version");
    }
    State s;
    s.robot = robot_from_key(document.at("robot"), name);
    const Json& checkpoint = document.at("checkpoint");
    s.checkpoint = std::make_shared<const sim::StepperCheckpoint>(
        named(name, [&] { return sim::checkpoint_from_json(*s.robot->model, checkpoint); }));
    if (!document.at("steering").is_null()) {
      s.steering = document.at("steering").get<learning::SteeringState>();
    }
    return s;
  } catch (const Json::exception& e) {
    value_error(name, std::string("the state is damaged: ") + e.what());
  }
}

// A run, stepped through sim::Stepper. Methods that walk release the GIL.

void register_state(py::module_& m) {
  namespace mp = multicpg::python;
  using py::arg;
  py::class_<mp::State>(
      m, "State",
      "A complete copy of a Simulation at one step (Simulation.state()): MuJoCo's state, the\n"
      "controller, step counters, the fault schedule and the steering reflex. Restore it into a\n"
      "Simulation of an equal Robot to continue bit for bit from there. Immutable; picklable\n"
      "(to_bytes(), from_bytes()), so runs can be checkpointed and sent to other processes; a\n"
      "damaged or forged one raises ValueError.")
      .def_property_readonly(
          "robot", [](const mp::State& s) { return s.robot; }, "the Robot it walks")
      .def_property_readonly(
          "step_count", [](const mp::State& s) { return s.checkpoint->walked; },
          "controller steps walked (warm-up excluded)")
      .def_property_readonly(
          "time", [](const mp::State& s) { return s.checkpoint->state.data->time; },
          "simulated time, s")
      .def("to_bytes", &mp::state_bytes,
           "The state as bytes (sealed CBOR with a checksum; what pickle stores).")
      .def_static(
          "from_bytes", [](mp::BytesArg data) { return mp::state_from_bytes(data, "data"); },
          arg("data"), "The State to_bytes() gave. Raises ValueError for damaged or foreign bytes.")
      .def("__copy__", [](py::object self) { return self; })
      .def("__deepcopy__", [](py::object self, mp::AnyArg) { return self; })
      .def("__repr__",
           [](const mp::State& s) {
             return "<multicpg.State of " + mp::robot_repr(*s.robot) + " at step " +
                    std::to_string(s.checkpoint->walked) + ">";
           })
      .def(py::pickle([](const mp::State& s) -> py::object { return mp::state_bytes(s); },
                      [](const py::object& data) { return mp::state_from_bytes(data, "state"); }));
}

}  // namespace multicpg::python
