// Robots and terrains in Python: multicpg.Robot (a robot and its compiled model, shared by every
// Simulation of an equal robot) and multicpg.Terrain.
#include "python/robots.h"

#include <pybind11/stl.h>

#include "common/errors.h"
#include "experiments/run_spec.h"
#include "python/args.h"
#include "python/typed.h"
#include "robot/body_json.h"
#include "robot/body_models.h"
#include "robot/terrain.h"
#include "sim/json.h"
#include "sim/robot_file.h"

namespace multicpg::python {

using Json = nlohmann::json;

std::string sim_argument(const std::string& key) {
  if (key == "scene.tunnel") return "tunnel";
  if (key.rfind("scene.terrain", 0) == 0) return "terrain";
  if (key.rfind("body.", 0) == 0) {
    const std::string rest = key.substr(5);
    const std::size_t end = rest.find_first_of(".[");
    return "body['" + rest.substr(0, end) + "']";
  }
  return key;
}

robot::Terrain terrain_arg(py::handle value, std::string_view name) {
  if (py::isinstance<robot::Terrain>(value)) return value.cast<robot::Terrain>();
  if (!PyUnicode_Check(value.ptr())) {
    type_error(name, "a multicpg.Terrain or its text (\"flat\", \"slope:5\", \"rough:0.01\")",
               value);
  }
  return named(name, [&] { return robot::parse_terrain(value.cast<std::string>()); });
}

namespace {

// The body: a named model's parameters (robot/body_models.h) with the keys of `body` (a dict of
// parameter name to value, robot/body_params.h) set.
void set_body(sim::SimOptions& options, py::handle model, py::handle body) {
  const std::string model_name = text(model, "model");
  options.model = named("model", [&] { return robot::parse_body_model(model_name); });
  options.body = robot::body_params(options.model);
  if (body.is_none()) return;
  if (!PyDict_Check(body.ptr())) type_error("body", "a dict of body parameters", body);
  Json params = options.body;
  for (const auto& [key_value, value] : py::reinterpret_borrow<py::dict>(body)) {
    const std::string key = text(key_value, "body's keys");
    const std::string where = "body['" + key + "']";
    if (!params.contains(key) || key == "leg_postures") {
      std::string known;
      for (const auto& item : params.items()) {
        if (item.key() != "leg_postures") known += (known.empty() ? "" : ", ") + item.key();
      }
      value_error(where, "is not a body parameter (known: " + known + ")");
    }
    if (key == "disabled_posture") {
      if (PyUnicode_Check(value.ptr()) || PySequence_Check(value.ptr()) == 0) {
        type_error(where, "three numbers: TC, CTr, FTi (-1..1)", value);
      }
      const auto triple = py::reinterpret_borrow<py::sequence>(value);
      if (triple.size() != 3) value_error(where, "takes three values: TC, CTr, FTi (-1..1)");
      params[key] = {{"tc", real(triple[0], where + "[0]", robot::kPostureLimits)},
                     {"ctr", real(triple[1], where + "[1]", robot::kPostureLimits)},
                     {"fti", real(triple[2], where + "[2]", robot::kPostureLimits)}};
    } else {
      params[key] = real(value, where, Limits<double>{-1e9, 1e9});
    }
  }
  options.body = params.get<robot::BodyParams>();
}

}  // namespace

std::shared_ptr<Robot> robot_of(experiments::RobotSpec spec) {
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    value_error(sim_argument(e.key().starts_with("sim.") ? e.key().substr(4) : e.key()), e.what());
  }
  // Equal robots share one compiled model while any of them lives (unpickled states each need
  // their robot's).
  static experiments::ModelCache models;
  auto r = std::make_shared<Robot>();
  r->model = models.model(spec);
  r->spec = std::move(spec);
  return r;
}

Json robot_key(const experiments::RobotSpec& spec) {
  Json key{{"robot", std::string(robot::to_string(spec.kind))}, {"sim", spec.sim}};
  experiments::record_robot_file(key, spec);
  return key;
}

// Robot.from_file: a robot file (docs/robots.md "Your robot: robot files"); a bad one is a
// ValueError with the CLI's one line (the file, the key, what is wrong).
std::shared_ptr<const experiments::RunRobotFile> load_robot_file(const std::string& path) {
  try {
    return experiments::load_run_robot_file(path);
  } catch (const BadInput& e) {
    throw py::value_error(e.what());
  }
}

Params sim_params() {
  return {{"control_dt", py::float_(sim::kDefaultControlDt)},
          {"physics_dt", py::none()},
          {"servo_gain", py::none()},
          {"terrain", py::str("flat")},
          {"model", py::str(std::string(robot::to_string(robot::kDefaultBodyModel)))},
          {"body", py::none()}};
}

sim::SimOptions sim_options(const Keywords& k, bool tunnel) {
  sim::SimOptions options;
  options.scene.tunnel = tunnel;
  options.scene.terrain = terrain_arg(k["terrain"], "terrain");
  set_body(options, k["model"], k["body"]);
  options.control_dt = real(k["control_dt"], "control_dt", sim::kControlDtLimits);
  if (!k["physics_dt"].is_none()) {
    options.physics_dt = real(k["physics_dt"], "physics_dt", sim::kPhysicsDtLimits);
  }
  if (!k["servo_gain"].is_none()) {
    options.servo_gain = real(k["servo_gain"], "servo_gain", sim::kServoGainLimits);
  }
  return options;
}

const Signature& robot_signature() {
  // Never destroyed: its Python objects must not outlive the interpreter.
  static const auto* s = new Signature("Robot", {{"name", py::str("hexapod")}},
                                       join({{{"tunnel", py::bool_(false)}}, sim_params()}));
  return *s;
}

std::shared_ptr<Robot> make_robot(const Keywords& k) {
  const std::string name = text(k["name"], "name");
  const sim::SimOptions options = sim_options(k, flag(k["tunnel"], "tunnel"));
  if (sim::is_robot_file(name)) {
    auto file = load_robot_file(name);
    return robot_of({file->file.layout, file, options});
  }
  const robot::RobotKind kind = named("name", [&] {
    try {
      return robot::parse_robot(name);
    } catch (const BadInput& e) {
      throw BadInput(std::string(e.what()) + ", or a robot file FILE.toml");
    }
  });
  return robot_of({kind, nullptr, options});
}

std::shared_ptr<Robot> with_terrain(const std::shared_ptr<Robot>& robot, py::handle terrain) {
  if (terrain.is_none()) return robot;
  experiments::RobotSpec spec = robot->spec;
  spec.sim.scene.terrain = terrain_arg(terrain, "terrain");
  return robot_of(std::move(spec));
}

experiments::RobotSpec recorded_robot(const Json& key, std::string_view name) {
  try {
    return experiments::recorded_robot(key);
  } catch (const OptionError& e) {
    value_error(name, e.key() + ": " + e.what());
  }
}

// A robot read back from its key (a pickled Robot or State).
std::shared_ptr<Robot> robot_from_key(const Json& key, std::string_view name) {
  try {
    const sim::SimOptions options = key.at("sim").get<sim::SimOptions>();
    experiments::RobotSpec spec = recorded_robot(key, name);
    spec.sim = options;
    return robot_of(std::move(spec));
  } catch (const Json::exception& e) {
    value_error(name, std::string("not a multicpg robot: ") + e.what());
  }
}

// A robot argument: a Robot, or a robot name for a Robot with default options.
std::shared_ptr<Robot> robot_arg(py::handle robot, std::string_view name) {
  if (py::isinstance<Robot>(robot)) return robot.cast<std::shared_ptr<Robot>>();
  if (!PyUnicode_Check(robot.ptr())) {
    type_error(name,
               "a multicpg.Robot, a robot name (hexapod, quadruped, octopod) or a robot file "
               "FILE.toml",
               robot);
  }
  const std::string text = robot.cast<std::string>();
  if (sim::is_robot_file(text)) {
    auto file = load_robot_file(text);
    return robot_of({file->file.layout, file, sim::SimOptions{}});
  }
  const robot::RobotKind kind = named(name, [&] { return robot::parse_robot(text); });
  return robot_of({kind, nullptr, sim::SimOptions{}});
}

std::string robot_repr(const Robot& r) {
  const sim::SimOptions defaults;
  std::string out =
      "multicpg.Robot('" + (r.spec.file ? r.spec.file->record.path : r.morph().name) + "'";
  if (r.spec.sim.scene.tunnel) out += ", tunnel=True";
  if (r.spec.sim.control_dt != defaults.control_dt) {
    out += ", control_dt=" + py::repr(py::float_(r.spec.sim.control_dt)).cast<std::string>();
  }
  if (r.spec.sim.physics_dt != defaults.physics_dt) {
    out += ", physics_dt=" + py::repr(py::float_(r.spec.sim.physics_dt)).cast<std::string>();
  }
  if (r.spec.sim.servo_gain != defaults.servo_gain) {
    out += ", servo_gain=" + py::repr(py::float_(r.spec.sim.servo_gain)).cast<std::string>();
  }
  if (r.spec.sim.scene.terrain != robot::Terrain{}) {
    out += ", terrain='" + robot::terrain_text(r.spec.sim.scene.terrain) + "'";
  }
  if (r.spec.sim.model != defaults.model) {
    out += ", model='" + std::string(robot::to_string(r.spec.sim.model)) + "'";
  }
  if (r.spec.sim.body != robot::body_params(r.spec.sim.model)) out += ", body=...";
  return out + ")";
}

void register_robots(py::module_& m) {
  namespace mp = multicpg::python;
  using py::arg;
  py::class_<multicpg::robot::Terrain>(
      m, "Terrain",
      "The ground (robot/terrain.h, docs/faults.md): Terrain('slope:5') reads the CLI's text;\n"
      "Terrain.flat(), .slope(deg, heading_deg=0), .rough(height_m, seed=1) and\n"
      ".steps(height_m, depth_m) make one. Immutable, comparable, hashable and picklable;\n"
      "str() gives its text. Robot(terrain=...) takes one or its text.")
      .def(py::init([](mp::StrArg text) { return mp::terrain_arg(text, "text"); }),
           arg("text") = "flat")
      .def_static(
          "flat", [] { return multicpg::robot::Terrain{}; }, "level ground")
      .def_static(
          "slope",
          [](mp::FloatArg deg, mp::FloatArg heading) {
            multicpg::robot::Slope t;
            t.slope_deg = mp::real(deg, "deg", multicpg::robot::kSlopeLimits);
            t.heading_deg = mp::real(heading, "heading_deg", multicpg::robot::kHeadingLimits);
            return multicpg::robot::Terrain{t};
          },
          arg("deg"), arg("heading_deg") = 0.0,
          "a plane rising `deg` (0..30) towards `heading_deg` (+ = left of the start heading)")
      .def_static(
          "rough",
          [](mp::FloatArg height, mp::IntArg seed) {
            multicpg::robot::Rough t;
            t.height_m = mp::real(height, "height_m", multicpg::robot::kBumpLimits);
            t.seed = mp::seed(seed, "seed");
            return multicpg::robot::Terrain{t};
          },
          arg("height_m"), arg("seed") = 1,
          "random bumps up to `height_m` (0.001..0.05 m), the same for the same seed")
      .def_static(
          "steps",
          [](mp::FloatArg height, mp::FloatArg depth) {
            multicpg::robot::Steps t;
            t.height_m = mp::real(height, "height_m", multicpg::robot::kBumpLimits);
            t.depth_m = mp::real(depth, "depth_m", multicpg::robot::kStepDepthLimits);
            return multicpg::robot::Terrain{t};
          },
          arg("height_m"), arg("depth_m"),
          "past a 0.5 m flat start the floor steps up `height_m` (0.001..0.05 m) for `depth_m` "
          "(0.05..1 m), down for `depth_m`, and so on")
      .def_property_readonly(
          "kind",
          [](const multicpg::robot::Terrain& t) {
            return std::string(multicpg::robot::terrain_name(t));
          },
          "flat, slope, rough or steps")
      .def("__eq__",
           [](const multicpg::robot::Terrain& a, py::object b) -> py::object {
             if (!py::isinstance<multicpg::robot::Terrain>(b))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(a == b.cast<multicpg::robot::Terrain>());
           })
      .def("__hash__",
           [](const multicpg::robot::Terrain& t) {
             return py::hash(py::str(multicpg::robot::terrain_text(t)));
           })
      .def("__str__",
           [](const multicpg::robot::Terrain& t) { return multicpg::robot::terrain_text(t); })
      .def("__repr__",
           [](const multicpg::robot::Terrain& t) {
             return "multicpg.Terrain('" + multicpg::robot::terrain_text(t) + "')";
           })
      .def(py::pickle(
          [](const multicpg::robot::Terrain& t) {
            return py::object(py::str(multicpg::robot::terrain_text(t)));
          },
          [](const py::object& text) { return mp::terrain_arg(text, "Terrain"); }));

  static const std::string robot_init_doc =
      robot_signature().text("__init__", "None") +
      "\n\nname: hexapod, quadruped, octopod, or a robot file FILE.toml (docs/robots.md).";
  py::class_<mp::Robot, std::shared_ptr<mp::Robot>> robot_class(
      m, "Robot",
      "A robot (hexapod, quadruped or octopod) and its MuJoCo model, shared read-only by every\n"
      "Simulation of it. tunnel=True adds the 3.0 m x 1.2 m corridor of paper §5. control_dt\n"
      "(s per controller step), physics_dt (MuJoCo's step; None: the largest <= 5 ms that divides\n"
      "control_dt) and servo_gain (1/s; None: lpzrobots', scaled to control_dt) are the\n"
      "CLI's --control-dt, --physics-dt, --servo-gain; terrain (a Terrain or the CLI's text), "
      "model\n"
      "('paper-sim' or 'real') and body (a dict of body parameters, {'slip': 0.02}) are its\n"
      "--terrain, --model and Body flags (docs/cli.md \"The body\"). Robots are equal (and hash\n"
      "equal) when made of the same name and options; a State of one restores into a Simulation\n"
      "of any equal one.");
  {
    const OwnSignatures own;
    robot_class.def(py::init([](const py::args& args, const py::kwargs& kwargs) {
                      return mp::make_robot(mp::robot_signature().read(args, kwargs));
                    }),
                    robot_init_doc.c_str());
  }
  robot_class
      .def_static(
          "from_file",
          [](const std::string& path) {
            auto file = mp::load_robot_file(path);
            return mp::robot_of({file->file.layout, file, {}});
          },
          arg("path"),
          "The robot of a robot file (a TOML leg map over an MJCF, docs/robots.md \"Your robot:\n"
          "robot files\"), usable wherever a Robot is; its name is its layout's. Raises "
          "ValueError\n"
          "(one line: the file, the key, what is wrong) for a bad file.")
      .def_property_readonly(
          "file",
          [](const mp::Robot& r) -> py::object {
            if (!r.spec.file) return py::none();
            return py::str(r.spec.file->record.path);
          },
          "the robot file it was read from, or None for a built-in robot")
      .def_property_readonly(
          "name", [](const mp::Robot& r) { return r.morph().name; }, "robot name")
      .def_property_readonly(
          "legs",
          [](const mp::Robot& r) {
            std::vector<std::string> out;
            for (const auto& leg : r.morph().legs) out.push_back(leg.name);
            return out;
          },
          "leg names R1..Rn, L1..Ln (the order of every per-leg array)")
      .def_property_readonly(
          "joints",
          [](const mp::Robot&) {
            std::vector<std::string> out;
            for (auto j : multicpg::robot::kJoints) out.emplace_back(multicpg::robot::to_string(j));
            return out;
          },
          "joint names of a leg: TC, CTr, FTi (the order of the joint axis)")
      .def_property_readonly(
          "joint_names",
          [](const mp::Robot& r) {
            std::vector<std::string> out;
            for (const auto& leg : r.morph().legs) {
              for (auto j : multicpg::robot::kJoints) {
                out.push_back(leg.name + "_" + std::string(multicpg::robot::to_string(j)));
              }
            }
            return out;
          },
          "every joint's MJCF name, R1_TC, R1_CTr, R1_FTi, R2_TC, ...")
      .def_property_readonly(
          "tunnel", [](const mp::Robot& r) { return r.spec.sim.scene.tunnel; },
          "whether the corridor of paper §5 is in the scene")
      .def_property_readonly(
          "terrain", [](const mp::Robot& r) { return r.spec.sim.scene.terrain; }, "the ground")
      .def_property_readonly(
          "model",
          [](const mp::Robot& r) {
            return std::string(multicpg::robot::to_string(r.spec.sim.model));
          },
          "the body model its parameters started from: 'paper-sim' or 'real' (docs/fidelity.md)")
      .def_property_readonly(
          "body",
          [](const mp::Robot& r) {
            const nlohmann::json params = r.spec.sim.body;
            return py::module_::import("json").attr("loads")(params.dump());
          },
          "the body's parameters (robot/body_params.h), as a dict")
      .def_property_readonly(
          "control_dt", [](const mp::Robot& r) { return r.model->control_dt; },
          "simulated seconds per controller step")
      .def_property_readonly(
          "physics_dt", [](const mp::Robot& r) { return r.model->physics_dt; },
          "MuJoCo time step, s")
      .def_property_readonly(
          "default_settle_steps",
          [](const mp::Robot& r) {
            return multicpg::learning::default_settle_steps(r.model->controller);
          },
          "unmeasured steps after a period change in paper mode (337 for the hexapod)")
      .def(
          "settle_steps",
          [](const mp::Robot& r, mp::PeriodsArg periods) {
            return multicpg::learning::locked_settle_steps(
                r.model->controller, mp::periods(r.morph(), periods, "periods"));
          },
          arg("periods"),
          "Unmeasured steps robust mode walks after setting these periods: the slowest CPG's\n"
          "lock plus the longest delay line (863 for a hexapod with a leg at 4).")
      .def(
          "mjcf", [](const mp::Robot& r) { return r.model->xml; },
          "The MJCF text of the model (what `multicpg model` prints).")
      .def("__eq__",
           [](const mp::Robot& a, py::object b) -> py::object {
             if (!py::isinstance<mp::Robot>(b))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(a.spec == b.cast<const mp::Robot&>().spec);
           })
      // Of what equality compares exactly (no floating-point number), so equal robots hash
      // equal.
      .def("__hash__",
           [](const mp::Robot& r) {
             const multicpg::experiments::RobotSpec& s = r.spec;
             return py::hash(py::make_tuple(std::string(multicpg::robot::to_string(s.kind)),
                                            s.file ? s.file->record.checksum_toml : std::string(),
                                            s.sim.scene.tunnel,
                                            std::string(multicpg::robot::to_string(s.sim.model))));
           })
      .def("__repr__", [](const mp::Robot& r) { return mp::robot_repr(r); })
      .def("__copy__", [](py::object self) { return self; })
      .def("__deepcopy__", [](py::object self, mp::AnyArg) { return self; })
      .def(py::pickle(
          [](const mp::Robot& r) -> py::object { return py::str(mp::robot_key(r.spec).dump()); },
          [](const py::object& key) {
            const std::string text = mp::text(key, "Robot");
            const nlohmann::json j =
                nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
            if (j.is_discarded()) mp::value_error("Robot", "not a pickled multicpg.Robot");
            return mp::robot_from_key(j, "Robot");
          }));
}

}  // namespace multicpg::python
