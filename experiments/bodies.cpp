#include "experiments/bodies.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "common/errors.h"
#include "experiments/run_json.h"
#include "experiments/run_robot.h"
#include "hw/hardware_record.h"
#include "learning/senses.h"
#include "robot/leg_sets.h"
#include "robot/robot_file.h"
#include "sim/fault_effects.h"

namespace multicpg::experiments {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Ids of the two wall geoms (robot/mjcf.h names them); -1 without the tunnel in the scene.
struct Walls {
  int left = -1;
  int right = -1;
  bool is_wall(int geom) const { return geom >= 0 && (geom == left || geom == right); }
};

Walls find_walls(const mjModel* m) {
  return {mj_name2id(m, mjOBJ_GEOM, "wall_left"), mj_name2id(m, mjOBJ_GEOM, "wall_right")};
}

bool wall_contact(const mjModel* m, const mjData* d, const Walls& walls) {
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const bool wall1 = walls.is_wall(c.geom1);
    const bool wall2 = walls.is_wall(c.geom2);
    // Robot geoms hang off body 1 and its children; the world (ground, walls) is body 0.
    if (wall1 != wall2 && m->geom_bodyid[wall1 ? c.geom2 : c.geom1] != 0) return true;
  }
  return false;
}

// The learner's decided trials so far, from its events (the record of a stopped run).
nlohmann::json trace_so_far(const robot::Morphology& morph,
                            const std::vector<body::Event>& events) {
  nlohmann::json trace = nlohmann::json::array();
  for (const body::Event& e : events) {
    if (e.kind != body::EventKind::trial_end) continue;
    trace.push_back({{"episode", e.episode},
                     {"trial", e.trial},
                     {"step", e.step},
                     {"periods", robot::period_map_json(morph, e.periods)},
                     {"deviation_deg", e.deviation_deg},
                     {"accepted", e.accepted}});
  }
  return trace;
}

nlohmann::json events_json(const robot::Morphology& morph, const std::vector<body::Event>& events) {
  nlohmann::json out = nlohmann::json::array();
  for (const body::Event& e : events) {
    nlohmann::json j{{"event", body::to_string(e.kind)}, {"step", e.step}};
    if (!e.legs.empty()) j["legs"] = robot::leg_set_name(morph, e.legs);
    if (e.kind == body::EventKind::detection) j["deviation_deg"] = e.deviation_deg;
    out.push_back(std::move(j));
  }
  return out;
}

class SimulatedBody final : public RunBody {
 public:
  // Owns its stepper, made for the run.
  SimulatedBody(const sim::SimModel& model, const RunSpec& spec, const Watchers& w)
      : owned_(std::make_unique<sim::Stepper>(model, spec.start, spec.faults, w.observer, w.record,
                                              w.record_joints)),
        stepper_(*owned_),
        body_(stepper_),
        walls_(find_walls(model.mj.get())) {}
  // Walks a stepper its caller made.
  explicit SimulatedBody(sim::Stepper& stepper)
      : stepper_(stepper), body_(stepper), walls_(find_walls(stepper.model().mj.get())) {}

  body::Body& body() override { return body_; }
  std::optional<double> along_ground_m() const override {
    const sim::SimModel& model = stepper_.model();
    const sim::Position p = sim::trunk_position(model, stepper_.state());
    return robot::to_ground_frame(model.scene.terrain, {p.x, p.y, p.z})[0];
  }
  std::optional<double> corridor_heading_deg() const override { return 0.0; }
  sim::SimState final_state() override { return std::move(stepper_.state()); }
  bool touches_wall() const override {
    return wall_contact(stepper_.model().mj.get(), stepper_.state().data.get(), walls_);
  }

 private:
  std::unique_ptr<sim::Stepper> owned_;
  sim::Stepper& stepper_;
  sim::SimBody body_;
  Walls walls_;
};

class RealBody final : public RunBody {
 public:
  RealBody(const RunSpec& spec, const HardwareSetup& setup, const sim::SimModel& model,
           const Watchers& w)
      : setup_(setup),
        view_(w.observer != nullptr
                  ? std::make_unique<HardwareView>(model, spec.start, spec.faults, *w.observer)
                  : nullptr),
        sinks_({w.steps, view_.get()}),
        body_(setup.file, setup.map, spec.start, spec.faults, setup.pacing, &sinks_) {}

  body::Body& body() override { return body_; }
  nlohmann::json hardware() const override {
    return hw::hardware_json(setup_.file, setup_.pacing, body_);
  }
  void finish(const std::string& why) override {
    body_.stop(why);
    // The end's stop that could not go out (the port failed after the last step) is told as
    // every stop is (docs/hardware.md "Safety").
    if (body_.stopped() && !body_.stopped()->command_error.empty()) {
      throw hw::HardwareStop(*body_.stopped());
    }
  }
  void stopped(const std::exception& cause) override { body_.stop(cause.what(), true); }
  bool is_hardware() const override { return true; }
  nlohmann::json stopped_record(const RunSpec& spec) const override {
    const robot::Morphology& morph = morphology(spec.robot);
    nlohmann::json record = nlohmann::json::object();
    record["status"] = "stopped";
    record["cause"] = body_.stopped() ? body_.stopped()->cause : "";
    record["robot"] = morph.name;
    record["steps_walked"] = body_.step_count();
    record["trace"] = trace_so_far(morph, body_.events());
    record["events"] = events_json(morph, body_.events());
    if (spec.learning) record["options"] = learning_record(*spec.learning, spec.faults);
    record["hardware"] = hardware();
    return record;
  }

 private:
  const HardwareSetup& setup_;
  std::unique_ptr<HardwareView> view_;
  hw::StepSinks sinks_;
  hw::HardwareBody body_;
};

}  // namespace

hw::BodyMap body_map(const RobotSpec& robot) {
  hw::BodyMap b;
  b.controller = neural::make_controller_model(robot.kind, robot.sim.controller, robot.sim.body);
  const robot::RobotFile map =
      robot.file ? robot.file->file : robot::builtin_robot_file(robot.kind, {});
  for (const robot::LegMap& leg : map.legs) {
    std::array<robot::AngleRange, robot::kJointsPerLeg> windows{};
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) windows[j] = leg.joints[j].window;
    b.windows.push_back(windows);
  }
  b.control_dt = robot.sim.control_dt;
  return b;
}

HardwareSetup hardware_setup(const RunSpec& spec) {
  const robot::Morphology& morph = morphology(spec.robot);
  HardwareSetup s;
  s.file = hw::load_hardware_file(spec.hardware->file, morph);
  try {
    hw::require_hardware_faults(morph, spec.faults);
  } catch (const BadInput& e) {
    throw OptionError("faults", e.what());
  }
  if (spec.learning) {
    within("learning", [&] { learning::require_senses(*spec.learning, s.file.senses_position()); });
  }
  s.map = body_map(spec.robot);
  s.pacing = spec.hardware->lock_step ? hw::Pacing::lock_step : hw::Pacing::real_time;
  return s;
}

HardwareView::HardwareView(const sim::SimModel& model, const body::StartSpec& start,
                           body::FaultTimeline faults, sim::Observer& observer)
    : model_(model), observer_(observer), state_(sim::start_walk_state(model, start.periods)) {
  // The faults are applied as the robot's own events bring them (HardwareView::event).
  (void)faults;
}

void HardwareView::row(const hw::StepRow& row) {
  mjData* d = state_.data.get();
  if (!started_) {
    // Row 0: the robot as it stood before its first step, posed by the first targets.
    started_ = true;
    observer_.on_start(model_, state_);
  }
  const int root = model_.root_qpos;
  if (row.pose.has_position()) {
    d->qpos[root] = row.pose.x;
    d->qpos[root + 1] = row.pose.y;
  }
  // The trunk level at the sensed yaw: w, x, y, z of a turn about the vertical.
  const double half = 0.5 * row.pose.yaw_deg * kRadPerDeg;
  d->qpos[root + 3] = std::cos(half);
  d->qpos[root + 4] = 0.0;
  d->qpos[root + 5] = 0.0;
  d->qpos[root + 6] = std::sin(half);
  for (std::size_t leg = 0; leg < row.targets.size() && leg < model_.legs.size(); ++leg) {
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const sim::JointSlot& slot = model_.legs[leg].joints[j];
      d->qpos[slot.qpos] = slot.sign * row.targets[leg][j];
    }
  }
  state_.controller.step = row.step;
  state_.step = row.step;
  mj_kinematics(sim::physics_model(model_, state_), d);
  observer_.on_step(model_, state_);
}

void HardwareView::event(const body::Event& event) {
  if (event.kind == body::EventKind::fault || event.kind == body::EventKind::recovery) {
    if (event.fault) {
      state_.faults.schedule.apply_now(*event.fault, state_.controller);  // as the robot's
      sim::apply_fault_effect(model_, state_, *event.fault);
    }
  } else if (event.kind == body::EventKind::trial_start) {
    neural::set_periods(model_.controller, state_.controller, event.periods);
  }
  observer_.on_event(model_, state_, event);
}

std::unique_ptr<RunBody> open_body(const RunSpec& spec, const sim::SimModel& model,
                                   const HardwareSetup* setup, const Watchers& watchers) {
  if (spec.hardware) {
    if (setup == nullptr) throw std::logic_error("open_body: a run on hardware needs its setup");
    return std::make_unique<RealBody>(spec, *setup, model, watchers);
  }
  return std::make_unique<SimulatedBody>(model, spec, watchers);
}

std::unique_ptr<RunBody> simulated_body(sim::Stepper& stepper) {
  return std::make_unique<SimulatedBody>(stepper);
}

}  // namespace multicpg::experiments
