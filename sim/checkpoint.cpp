#include "sim/checkpoint.h"

#include <fmt/format.h>
#include <mujoco/mjxmacro.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

#include "body/course_json.h"
#include "common/checksum.h"
#include "common/errors.h"
#include "neural/json.h"

namespace multicpg::sim {
namespace {

using Json = nlohmann::json;
constexpr const char* kFormat = "multicpg checkpoint";
// Version 3: the mjData arrays of checkpoint.h, the controller (neural/json.h), joint targets,
// step counters, warning counts, the fault schedule (what came, so what is in force) and what the
// faults in force do (sim/fault_state.h: joint conditions, the yaw sensor's error and its random
// state, and the arrays of the run's own model that differ from the shared one). Version 2 also
// held the faults in force apart from the schedule.
constexpr int kVersion = 3;
// Controller and physics step counters stay below a warm-up plus a run, each at most kMaxSteps.
constexpr long kMaxCounter = 2 * body::kMaxSteps;

[[noreturn]] void bad(const std::string& what) {
  throw BadInput("the state " + what);
}

// One mjData array of n numbers: its bytes, and back (size checked against the model's).
Json array_bytes(const mjtNum* values, int n) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(values);
  return Json::binary(std::vector<std::uint8_t>(bytes, bytes + n * sizeof(mjtNum)));
}

void read_array(const Json& doc, const char* key, mjtNum* values, int n) {
  const auto& bytes = doc.at(key).get_binary();
  if (bytes.size() != static_cast<std::size_t>(n) * sizeof(mjtNum)) {
    bad(fmt::format("has {} bytes of mjData.{}, the model takes {}", bytes.size(), key,
                    static_cast<std::size_t>(n) * sizeof(mjtNum)));
  }
  if (n > 0) std::memcpy(values, bytes.data(), bytes.size());
}

// The mjData arrays of checkpoint.h with their sizes in `m`.
struct ArraySlot {
  const char* key;
  mjtNum* mjData::*field;
  int size;
};
std::vector<ArraySlot> saved_arrays(const mjModel* m) {
  return {{"qpos", &mjData::qpos, m->nq},
          {"qvel", &mjData::qvel, m->nv},
          {"act", &mjData::act, m->na},
          {"qacc_warmstart", &mjData::qacc_warmstart, m->nv},
          {"ctrl", &mjData::ctrl, m->nu},
          {"qfrc_applied", &mjData::qfrc_applied, m->nv},
          {"xfrc_applied", &mjData::xfrc_applied, 6 * m->nbody},
          {"mocap_pos", &mjData::mocap_pos, 3 * m->nmocap},
          {"mocap_quat", &mjData::mocap_quat, 4 * m->nmocap},
          {"userdata", &mjData::userdata, m->nuserdata},
          {"sensordata", &mjData::sensordata, m->nsensordata}};
}

// Calls visit(name, bytes of `a`'s array, bytes of `b`'s array, size in bytes) for every array
// of mjModel (mjxmacro.h's list), so a run's own model can be saved as its differences from the
// shared one: whatever a fault or mj_setConst changed, without listing it here.
template <class Visit>
void each_model_array(const mjModel* a, const mjModel* b, Visit visit) {
  const mjModel* m = a;
  MJMODEL_POINTERS_PREAMBLE(m)
  (void)nq, (void)nv, (void)na, (void)nu, (void)nmocap;
#define X(type, name, nr, nc)                                        \
  visit(#name, reinterpret_cast<const std::uint8_t*>(a->name),       \
        reinterpret_cast<std::uint8_t*>(const_cast<type*>(b->name)), \
        sizeof(type) * static_cast<std::size_t>(m->nr) * static_cast<std::size_t>(nc));
  MJMODEL_POINTERS
#undef X
}

Json own_model_json(const SimModel& model, const SimState& state) {
  if (!state.faults.model) return nullptr;
  const mjModel* shared = model.mj.get();
  const mjModel* own = state.faults.model.get();
  Json arrays = Json::object();
  each_model_array(
      shared, own,
      [&](const char* name, const std::uint8_t* base, const std::uint8_t* mine, std::size_t size) {
        if (size > 0 && std::memcmp(base, mine, size) != 0) {
          arrays[name] = Json::binary(std::vector<std::uint8_t>(mine, mine + size));
        }
      });
  const auto* stat = reinterpret_cast<const std::uint8_t*>(&own->stat);
  return {{"arrays", arrays},
          {"stat", Json::binary(std::vector<std::uint8_t>(stat, stat + sizeof(mjStatistic)))}};
}

// The run's own model: the shared one with the saved arrays.
std::shared_ptr<const mjModel> own_model_from_json(const SimModel& model, const Json& doc) {
  mjModel* copy = mj_copyModel(nullptr, model.mj.get());
  if (copy == nullptr) throw RuntimeFailure("MuJoCo: cannot copy the model");
  std::shared_ptr<const mjModel> own(copy, mj_deleteModel);
  const Json& arrays = doc.at("arrays");
  std::size_t used = 0;
  each_model_array(
      model.mj.get(), copy,
      [&](const char* name, const std::uint8_t*, std::uint8_t* mine, std::size_t size) {
        if (!arrays.contains(name)) return;
        const auto& bytes = arrays.at(name).get_binary();
        if (bytes.size() != size) {
          bad(fmt::format("has {} bytes of mjModel.{}, the model takes {}", bytes.size(), name,
                          size));
        }
        std::memcpy(mine, bytes.data(), size);
        ++used;
      });
  if (used != arrays.size()) bad("names an mjModel array this model does not have");
  const auto& stat = doc.at("stat").get_binary();
  if (stat.size() != sizeof(mjStatistic)) bad("has a damaged mjModel.stat");
  std::memcpy(&copy->stat, stat.data(), sizeof(mjStatistic));
  return own;
}

Json effects_json(const SimModel& model, const SimState& state) {
  const FaultState& e = state.faults;
  Json joints = Json::array();
  for (const auto& leg : e.joints) {
    Json row = Json::array();
    for (const JointCondition& j : leg) row.push_back({static_cast<int>(j.servo), j.torque_scale});
    joints.push_back(row);
  }
  std::ostringstream random;
  random << e.sensor.random;
  return {{"joints", joints},
          {"sensor",
           {{"drift_deg_per_s", e.sensor.drift_deg_per_s},
            {"drift_deg", e.sensor.drift_deg},
            {"noise_sigma_deg", e.sensor.noise_sigma_deg},
            {"noise_deg", e.sensor.noise_deg},
            {"random", random.str()}}},
          {"model", own_model_json(model, state)}};
}

void read_effects(const SimModel& model, const Json& doc, FaultState& e) {
  const Json& joints = doc.at("joints");
  if (!joints.is_array() || joints.size() != model.legs.size()) {
    bad(fmt::format("has joint conditions for {} legs, the model {}", joints.size(),
                    model.legs.size()));
  }
  e.joints.assign(model.legs.size(), {});
  for (std::size_t leg = 0; leg < e.joints.size(); ++leg) {
    if (joints[leg].size() != robot::kJointsPerLeg) bad("has a damaged joint condition");
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const int servo = joints[leg][j].at(0).get<int>();
      const double scale = joints[leg][j].at(1).get<double>();
      if (servo < 0 || servo > static_cast<int>(JointCondition::Servo::passive) ||
          !(scale > 0.0 && scale <= 1.0)) {
        bad("has a damaged joint condition");
      }
      e.joints[leg][j] = {static_cast<JointCondition::Servo>(servo), scale};
    }
  }
  const Json& sensor = doc.at("sensor");
  e.sensor.drift_deg_per_s = sensor.at("drift_deg_per_s").get<double>();
  e.sensor.drift_deg = sensor.at("drift_deg").get<double>();
  e.sensor.noise_sigma_deg = sensor.at("noise_sigma_deg").get<double>();
  e.sensor.noise_deg = sensor.at("noise_deg").get<double>();
  for (double v : {e.sensor.drift_deg_per_s, e.sensor.drift_deg, e.sensor.noise_sigma_deg,
                   e.sensor.noise_deg}) {
    if (!std::isfinite(v)) bad("has a damaged yaw sensor error");
  }
  std::istringstream random(sensor.at("random").get<std::string>());
  random >> e.sensor.random;
  if (!random) bad("has a damaged yaw sensor random state");
  e.model.reset();
  if (!doc.at("model").is_null()) e.model = own_model_from_json(model, doc.at("model"));
}

void check_counter(const char* what, long value) {
  if (value < 0 || value > kMaxCounter) {
    bad(fmt::format("has {} = {}, outside 0..{}", what, value, kMaxCounter));
  }
}

// A controller state `model` can be in: stepping it indexes only what exists.
void check_controller(const SimModel& model, const neural::ControllerState& c,
                      const body::FaultSchedule& faults) {
  const neural::ControllerModel& cm = model.controller;
  if (c.legs.size() != cm.size()) {
    bad(fmt::format("has {} legs, the {} {}", c.legs.size(), cm.morphology.name, cm.size()));
  }
  check_counter("controller.step", c.step);
  for (std::size_t i = 0; i < c.legs.size(); ++i) {
    const neural::LegState& leg = c.legs[i];
    const std::string& name = cm.morphology.legs[i].name;
    if (leg.cpg.period < neural::kMinPeriod || leg.cpg.period > neural::kMaxPeriod) {
      bad(fmt::format("gives leg {} period {}, outside {}..{}", name, leg.cpg.period,
                      neural::kMinPeriod, neural::kMaxPeriod));
    }
    if (leg.cpg.counter < 0 || leg.cpg.counter > leg.cpg.period) {
      bad(fmt::format("gives leg {} a CPG counter of {} at period {}", name, leg.cpg.counter,
                      leg.cpg.period));
    }
    check_counter("post.window_counter", leg.post.window_counter);
    const std::size_t ring = neural::make_delay_line(cm.legs[i].delay).ring.size();
    if (leg.delay.ring.size() != ring || leg.delay.head >= ring) {
      bad(fmt::format("gives leg {} a delay line of {} entries at {}, the model {}", name,
                      leg.delay.ring.size(), leg.delay.head, ring));
    }
    if (leg.disabled != faults.failed(i)) {
      bad(fmt::format("has leg {} {} while its faults say {}", name,
                      leg.disabled ? "disabled" : "working",
                      faults.failed(i) ? "failed" : "working"));
    }
  }
}

}  // namespace

std::string model_fingerprint(const SimModel& model) {
  std::string made_of = model.xml;
  made_of += '\n' + Json(model.controller.params).dump();
  made_of += fmt::format("\n{:a} {:a} {}", model.control_dt, model.physics_dt, model.substeps);
  const auto servo = [&](const JointSlot& slot) {
    const robot::ServoSpec& s = slot.servo.spec;
    made_of += fmt::format("\n{:a} {:a} {:a} {:a} {:a} {:a} {:a}", s.max_velocity, s.gain, s.power,
                           s.damp, s.armature, s.loop_gain, slot.servo.range);
  };
  for (const LegSlots& leg : model.legs) {
    for (const JointSlot& slot : leg.joints) servo(slot);
  }
  for (const JointSlot& slot : model.backbone) servo(slot);
  return checksum_text(made_of);
}

Json checkpoint_json(const SimModel& model, const StepperCheckpoint& checkpoint) {
  const mjModel* m = model.mj.get();
  const mjData* d = checkpoint.state.data.get();
  Json data = Json::object();
  data["time"] = d->time;
  for (const ArraySlot& a : saved_arrays(m)) data[a.key] = array_bytes(d->*a.field, a.size);
  Json warnings = Json::array();
  for (const mjWarningStat& w : d->warning) warnings.push_back({w.lastinfo, w.number});
  data["warning"] = warnings;

  const body::FaultSchedule& f = checkpoint.state.faults.schedule;
  return {{"format", kFormat},
          {"version", kVersion},
          {"robot", model.controller.morphology.name},
          {"model", model_fingerprint(model)},
          {"mjdata", data},
          {"controller", checkpoint.state.controller},
          {"targets", checkpoint.state.targets},
          {"step", checkpoint.state.step},
          {"warnings_seen", checkpoint.state.warnings},
          {"faults", {{"timeline", f.timeline()}, {"come", f.come()}, {"applied", f.applied()}}},
          {"effects", effects_json(model, checkpoint.state)},
          {"walked", checkpoint.walked}};
}

StepperCheckpoint checkpoint_from_json(const SimModel& model, const Json& doc) {
  try {
    if (!doc.is_object() || doc.value("format", "") != kFormat) {
      bad("is not a multicpg simulation state");
    }
    if (doc.at("version").get<int>() != kVersion) {
      bad(fmt::format("has version {}, this build reads {}", doc.at("version").dump(), kVersion));
    }
    const std::string& name = model.controller.morphology.name;
    const std::string robot = doc.at("robot").get<std::string>();
    if (robot != name) bad("comes from a simulation of the " + robot + ", not the " + name);
    if (doc.at("model").get<std::string>() != model_fingerprint(model)) {
      bad("comes from a simulation of another " + name +
          " model (other time steps, servos, scene or controller parameters)");
    }

    const mjModel* m = model.mj.get();
    StepperCheckpoint c{SimState{}, 0};
    c.state.data.reset(mj_makeData(m));
    if (!c.state.data) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
    mjData* d = c.state.data.get();
    const Json& data = doc.at("mjdata");
    d->time = data.at("time").get<double>();
    for (const ArraySlot& a : saved_arrays(m)) read_array(data, a.key, d->*a.field, a.size);
    const Json& warnings = data.at("warning");
    if (!warnings.is_array() || warnings.size() != mjNWARNING) bad("has no MuJoCo warning counts");
    for (int w = 0; w < mjNWARNING; ++w) {
      d->warning[w].lastinfo = warnings[w].at(0).get<int>();
      d->warning[w].number = warnings[w].at(1).get<int>();
    }

    const Json& faults = doc.at("faults");
    c.state.faults.schedule = body::FaultSchedule(
        model.controller.morphology, faults.at("timeline").get<body::FaultTimeline>(),
        faults.at("come").get<std::size_t>(), faults.at("applied").get<std::vector<body::Fault>>());
    read_effects(model, doc.at("effects"), c.state.faults);
    c.state.controller = doc.at("controller").get<neural::ControllerState>();
    check_controller(model, c.state.controller, c.state.faults.schedule);
    c.state.targets = doc.at("targets").get<std::vector<robot::LegAngles>>();
    if (c.state.targets.size() != model.legs.size()) {
      bad(fmt::format("has joint targets for {} legs, the model {}", c.state.targets.size(),
                      model.legs.size()));
    }
    c.state.step = doc.at("step").get<long>();
    check_counter("step", c.state.step);
    c.state.warnings = doc.at("warnings_seen").get<std::array<int, mjNWARNING>>();
    c.walked = doc.at("walked").get<long>();
    if (c.walked < 0 || c.walked > body::kMaxSteps) {
      bad(fmt::format("has walked {} steps, outside 0..{}", c.walked, body::kMaxSteps));
    }
    return c;
  } catch (const Json::exception& e) {
    bad(std::string("is damaged: ") + e.what());
  }
}

}  // namespace multicpg::sim
