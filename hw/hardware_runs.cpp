#include "hw/hardware_runs.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "common/angles.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "common/limits.h"
#include "experiments/run_json.h"
#include "learning/senses.h"
#include "learning/steering.h"
#include "robot/leg_sets.h"

namespace multicpg::hw {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

nlohmann::json errors_json(const LinkErrors& errors) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t k = 0; k < kLinkErrorKinds; ++k) {
    j[std::string(to_string(static_cast<LinkError>(k)))] = errors.counts[k];
  }
  return j;
}

nlohmann::json stop_json(const StopRecord& r) {
  return {{"cause", r.cause},
          {"message", r.message},
          {"fault", r.fault},
          {"step", r.step},
          {"detected_s", r.detected_s},
          {"commanded_s", r.commanded_s},
          {"command_error", r.command_error}};
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

// The record a stopped run leaves, handed to `stopped` before the stop goes on.
void report_stop(const experiments::RunSpec& spec, const HardwareSetup& setup, HardwareBody& walker,
                 const std::exception& e, const StoppedSink& stopped,
                 nlohmann::json record = nlohmann::json::object()) {
  walker.stop(e.what(), true);
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  record["status"] = "stopped";
  record["cause"] = walker.stopped()->cause;
  record["robot"] = morph.name;
  record["steps_walked"] = walker.step_count();
  record["trace"] = trace_so_far(morph, walker.events());
  record["events"] = events_json(morph, walker.events());
  if (spec.learning) record["options"] = experiments::learning_record(*spec.learning, spec.faults);
  record["hardware"] = hardware_json(setup, walker);
  if (stopped) stopped(record);
}

// The steering reflex `reflex` on every later step.
void keep_steering(HardwareBody& walker, const learning::CompensationOptions& options,
                   learning::SteeringState reflex) {
  walker.set_before_step([params = options.steering_params, reflex](HardwareBody& w) mutable {
    neural::ControllerState& c = w.controller();
    c.drive = learning::steer(params, reflex, w.pose(), c.drive);
  });
}

std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace

BodyMap body_map(const sim::SimModel& model) {
  BodyMap b;
  b.controller = model.controller;
  for (const sim::LegSlots& leg : model.legs) b.windows.push_back(leg.windows);
  b.control_dt = model.control_dt;
  return b;
}

HardwareSetup hardware_setup(const experiments::RunSpec& spec, const HardwareFlags& flags) {
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  HardwareSetup s;
  s.file = load_hardware_file(flags.file, morph);
  require_hardware_faults(morph, spec.faults);
  if (spec.learning) {
    within("learning", [&] { learning::require_senses(*spec.learning, s.file.senses_position()); });
  }
  s.body = body_map(experiments::make_model(spec.robot));
  s.pacing = flags.lock_step ? Pacing::lock_step : Pacing::real_time;
  return s;
}

nlohmann::json hardware_json(const HardwareSetup& setup, const HardwareBody& walker) {
  const HardwareFile& f = setup.file;
  nlohmann::json j{
      {"file", f.path.string()},
      {"name", f.name},
      {"checksum", f.checksum},
      {"protocol", to_string(f.protocol)},
      {"pacing", setup.pacing == Pacing::lock_step ? "lock_step" : "real_time"},
      {"senses_position", f.senses_position()},
      {"timing", walker.timing()},
      {"errors",
       {{"bus", errors_json(walker.bus_errors())}, {"yaw", errors_json(walker.yaw_errors())}}},
      {"clamped_targets", walker.clamped_targets()},
      {"stop", walker.stopped() ? stop_json(*walker.stopped()) : nlohmann::json()}};
  return j;
}

StepCsv::StepCsv(std::ostream& out, const HardwareFile& file, const robot::Morphology& morph)
    : out_(out), file_(file) {
  out_ << "step,time_s,x_m,y_m,yaw_deg";
  for (const char* what : {"target_deg", "angle_deg"}) {
    if (std::string(what) == "angle_deg" && file.protocol != Protocol::dynamixel) continue;
    for (const robot::Leg& leg : morph.legs) {
      for (robot::Joint joint : robot::kJoints) {
        out_ << "," << leg.name << "." << robot::to_string(joint) << "_" << what;
      }
    }
  }
  if (file.protocol == Protocol::amosii) {
    for (const robot::Leg& leg : morph.legs) out_ << "," << leg.name << "_contact";
  }
  out_ << ",errors\n";
}

void StepCsv::row(const StepRow& r) {
  out_ << r.step << "," << cell(r.time_s) << "," << cell(r.pose.x) << "," << cell(r.pose.y) << ","
       << cell(r.pose.yaw_deg);
  for (const auto& leg : r.targets) {
    for (double a : leg) out_ << "," << cell(a * kDegPerRad);
  }
  if (file_.protocol == Protocol::dynamixel) {
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        const bool known = i < r.feedback.angles.size() && r.feedback.angles[i][j];
        out_ << "," << (known ? cell(*r.feedback.angles[i][j] * kDegPerRad) : "");
      }
    }
  }
  if (file_.protocol == Protocol::amosii) {
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
      const bool known = i < r.feedback.contacts.size() && r.feedback.contacts[i];
      out_ << "," << (known ? (*r.feedback.contacts[i] ? "1" : "0") : "");
    }
  }
  out_ << "," << r.errors << "\n";
}

HardwareLearning learn_on_hardware(const experiments::RunSpec& spec, const HardwareSetup& setup,
                                   const StoppedSink& stopped, StepSink* steps) {
  const learning::CompensationOptions& options = *spec.learning;
  HardwareBody walker(setup.file, setup.body, spec.start, spec.faults, setup.pacing, steps);
  learning::require_senses(options, walker.pose().has_position());
  HardwareLearning out;
  try {
    out.result = learning::compensate(walker, options);
  } catch (const std::exception& e) {
    report_stop(spec, setup, walker, e, stopped);
    throw;
  }
  walker.stop("the learning run ended");
  out.hardware = hardware_json(setup, walker);
  return out;
}

HardwareWalk walk_on_hardware(const experiments::RunSpec& spec, const HardwareSetup& setup,
                              long settle, long steps, long window, const StoppedSink& stopped,
                              StepSink* sink) {
  HardwareBody walker(setup.file, setup.body, spec.start, spec.faults, setup.pacing, sink);
  HardwareWalk out;
  try {
    walker.steps(settle);
    while (out.steps + window <= steps) {
      const body::Pose2 start = walker.pose();
      walker.steps(window);
      out.steps += window;
      out.windows.push_back(body::measure_window(start, walker.pose()));
    }
    walker.steps(steps - out.steps);
    out.steps = steps;
  } catch (const std::exception& e) {
    nlohmann::json windows = nlohmann::json::array();
    for (const body::WindowMeasure& m : out.windows) windows.push_back(m.yaw_deg);
    report_stop(spec, setup, walker, e, stopped, {{"window_yaw_deg", windows}});
    throw;
  }
  out.final_yaw_deg = walker.pose().yaw_deg;
  walker.stop("the walk ended");
  out.hardware = hardware_json(setup, walker);
  return out;
}

HardwareTunnel tunnel_on_hardware(const experiments::RunSpec& spec, const HardwareSetup& setup,
                                  long max_steps, double length_m, const StoppedSink& stopped) {
  HardwareBody walker(setup.file, setup.body, spec.start, spec.faults, setup.pacing);
  HardwareTunnel out;
  try {
    if (spec.learning) {
      learning::require_senses(*spec.learning, walker.pose().has_position());
      out.learned = learning::compensate(walker, *spec.learning);
      // The reflex holds the tunnel's axis from here, as the simulated tunnel's does.
      if (out.learned->steering) {
        keep_steering(walker, *spec.learning, learning::start_steering(walker.pose()));
      }
    }
    for (const neural::LegState& leg : walker.controller().legs)
      out.periods.push_back(leg.cpg.period);
    const body::Pose2 start = walker.pose();
    const double heading = start.yaw_deg / kDegPerRad;
    while (out.steps < max_steps) {
      walker.step();
      ++out.steps;
      const body::Pose2 p = walker.pose();
      if (!p.has_position()) continue;
      out.forward_m = (p.x - start.x) * std::cos(heading) + (p.y - start.y) * std::sin(heading);
      out.lateral_m = -(p.x - start.x) * std::sin(heading) + (p.y - start.y) * std::cos(heading);
      if (*out.forward_m >= length_m) break;
    }
    out.yaw_change_deg = wrap_degrees(walker.pose().yaw_deg - start.yaw_deg);
    if (out.forward_m) {
      out.deviation_deg = std::atan2(*out.lateral_m, *out.forward_m) * kDegPerRad;
      out.passed = *out.forward_m >= length_m;
    }
  } catch (const std::exception& e) {
    report_stop(spec, setup, walker, e, stopped, {{"tunnel_steps", out.steps}});
    throw;
  }
  walker.stop("the tunnel walk ended");
  out.hardware = hardware_json(setup, walker);
  return out;
}

}  // namespace multicpg::hw
