#include "hw/hardware_body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "body/fault_spec.h"
#include "common/angles.h"
#include "common/errors.h"
#include "common/interrupt.h"

namespace multicpg::hw {
namespace {

std::string stop_message(const StopRecord& r, StopAction action) {
  std::string text = "hardware stop after step " + std::to_string(r.step) + ": " + r.cause;
  if (!r.command_error.empty()) return text + "; the stop could not be sent: " + r.command_error;
  return text + (action == StopAction::posture ? "; robot commanded to its safe posture"
                                               : "; every servo's torque off");
}

// The cause a stop names for the errors of the step that made it (the worst kind first).
std::string bus_cause(const HardwareFile& file, const std::vector<StepError>& errors, int steps) {
  const std::string in_a_row = std::to_string(steps) + " control steps in a row";
  for (const StepError& e : errors) {
    if (e.kind == LinkError::missing) {
      return "servo " + file.servo_name(e.servo) + " stopped answering (" + in_a_row + ")";
    }
  }
  for (const StepError& e : errors) {
    if (e.kind == LinkError::timeout) {
      return "bus timeout: no answer in " + in_a_row + " (timeout " +
             std::to_string(file.timeout_ms) + " ms)";
    }
  }
  for (const StepError& e : errors) {
    if (e.kind == LinkError::bad_checksum) {
      return "repeated checksum errors: bad answers in " + in_a_row + " (last: " + e.what + ")";
    }
  }
  return "repeated bad answers in " + in_a_row + " (last: " + errors.back().what + ")";
}

}  // namespace

HardwareBody::HardwareBody(const HardwareFile& file, BodyMap body, const body::StartSpec& start,
                           body::FaultTimeline faults, Pacing pacing, StepSink* sink)
    : file_(file),
      body_(std::move(body)),
      faults_(body_.controller.morphology, std::move(faults)),
      clock_(pacing == Pacing::real_time ? body_.control_dt : 0.0),
      sink_(sink) {
  require_hardware_faults(body_.controller.morphology, faults_.timeline());
  // Not sensed until a POSE line says otherwise (body::Pose2: never a made-up position).
  pose_.x = pose_.y = std::numeric_limits<double>::quiet_NaN();
  bus_ = open_bus(file_);
  if (file_.yaw.source == YawSource::line) yaw_ = std::make_unique<YawLine>(file_);
  try {
    start_check();
  } catch (const RuntimeFailure& e) {
    // A port that fails during the check (an emulator that ended) is a failed check as well.
    const std::string what = e.what();
    throw RuntimeFailure((what.starts_with("start-up check: ") ? what : "start-up check: " + what) +
                         "; nothing has moved");
  }
  // The controller starts as every body's does (body/start.h), the faults due at step 0 before
  // its warm-up.
  controller_ = body::start_controller(body_.controller, start.periods);
  faults_.apply_due(0, controller_);
  for (const body::Fault& f : faults_.applied()) {
    const body::Event e = body::fault_event(f);
    if (sink_ != nullptr) sink_->event(e);
    events_.push_back(e);
  }
  body::warm_up_controller(body_.controller, controller_, start.warmup);
}

HardwareBody::~HardwareBody() {
  stop("the run ended");
}

void HardwareBody::start_check() {
  Feedback feedback;
  bus_->start_check(feedback);
  std::vector<StepError> errors;
  if (!read_yaw(errors, feedback)) {
    throw RuntimeFailure("start-up check: the yaw does not arrive (" +
                         (errors.empty() ? std::string("no reading") : errors.front().what) + ")");
  }
}

bool HardwareBody::read_yaw(std::vector<StepError>& errors, const Feedback& feedback) {
  if (file_.yaw.source == YawSource::board) {
    if (!feedback.yaw_deg) {
      ++board_yaw_errors_.counts[static_cast<std::size_t>(LinkError::timeout)];
      errors.push_back(
          {LinkError::timeout,
           "yaw input " + std::to_string(file_.yaw.board_port) + " reads no heading (0 or 255)",
           -1});
      return false;
    }
    pose_.yaw_deg = wrap_degrees(*feedback.yaw_deg);
    return true;
  }
  const std::optional<yaw_line::Reading> r = yaw_->poll(errors);
  if (!r) return false;
  pose_.yaw_deg = wrap_degrees(r->yaw_deg);
  if (r->x_m) {
    pose_.x = *r->x_m;
    pose_.y = *r->y_m;
  }
  return true;
}

LinkErrors HardwareBody::yaw_errors() const {
  return yaw_ ? yaw_->errors() : board_yaw_errors_;
}

JointCounts HardwareBody::counts(
    const std::vector<std::array<double, robot::kJointsPerLeg>>& angles) {
  JointCounts c;
  for (std::size_t i = 0; i < file_.legs.size(); ++i) {
    std::array<int, robot::kJointsPerLeg> leg{};
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const ServoJoint& servo = file_.legs[i].joints[j];
      if (angles[i][j] < servo.limits.lo || angles[i][j] > servo.limits.hi) ++clamped_;
      leg[j] = servo.counts(angles[i][j]);
    }
    c.legs.push_back(leg);
  }
  if (file_.backbone) c.backbone = file_.backbone->counts(0.0);  // held at 0, as in simulation
  return c;
}

void HardwareBody::step() {
  if (stopped_) throw std::logic_error("HardwareBody::step after the robot stopped");
  if (const int signal = interrupt_signal(); signal != 0) {
    const Interrupted stop_signal(signal);
    stop(stop_signal.what(), true);
    throw stop_signal;
  }
  const std::size_t came = faults_.applied().size();
  faults_.apply_due(walked_, controller_);
  for (std::size_t i = came; i < faults_.applied().size(); ++i) {
    body::Event e = body::fault_event(faults_.applied()[i]);
    e.step = walked_;
    if (sink_ != nullptr) sink_->event(e);
    events_.push_back(e);
  }
  neural::controller_step(body_.controller, controller_);
  StepRow row;
  row.step = walked_ + 1;
  for (std::size_t i = 0; i < body_.windows.size(); ++i) {
    const neural::MotorCommands& m = controller_.legs[i].command;
    const auto& w = body_.windows[i];
    row.targets.push_back({robot::joint_angle(w[0], m.tc), robot::joint_angle(w[1], m.ctr),
                           robot::joint_angle(w[2], m.fti)});
    for (double a : row.targets.back()) {
      if (!std::isfinite(a)) fail("the controller's joint targets are not finite numbers");
    }
  }
  const JointCounts c = counts(row.targets);
  row.time_s = monotonic_s(clock_.wait_for_slot());
  std::vector<StepError> bus_errors;
  std::vector<StepError> yaw_errors;
  try {
    bus_->exchange(c, row.feedback, bus_errors);
  } catch (const RuntimeFailure& e) {
    ++walked_;
    fail(e.what());
  }
  bool yaw = false;
  try {
    yaw = read_yaw(yaw_errors, row.feedback);
  } catch (const RuntimeFailure& e) {
    // The yaw line's port failed (it may close before the bus's): a stop like the bus's.
    ++walked_;
    fail(e.what());
  }
  clock_.exchanged();
  ++walked_;
  row.pose = pose_;
  row.errors = static_cast<int>(bus_errors.size() + yaw_errors.size());
  if (sink_ != nullptr) sink_->row(row);
  bad_steps_ = bus_errors.empty() ? 0 : bad_steps_ + 1;
  silent_steps_ = yaw ? 0 : silent_steps_ + 1;
  if (bad_steps_ >= file_.max_errors) fail(bus_cause(file_, bus_errors, bad_steps_));
  if (silent_steps_ >= file_.max_errors) {
    fail("yaw sensor silent: no reading in " + std::to_string(silent_steps_) +
         " control steps in a row (last: " + yaw_errors.back().what + ")");
  }
}

void HardwareBody::steps(long n) {
  for (long i = 0; i < n; ++i) step();
}

void HardwareBody::emit(const body::Event& event) {
  body::Event e = event;
  e.step = walked_;
  if (sink_ != nullptr) sink_->event(e);
  events_.push_back(std::move(e));
}

void HardwareBody::fail(const std::string& cause) {
  const double detected = monotonic_s();
  stop(cause, true);
  stopped_->detected_s = detected;
  throw HardwareStop(*stopped_);
}

void HardwareBody::stop(const std::string& cause, bool fault) {
  if (stopped_) return;
  StopRecord r;
  r.cause = cause;
  r.fault = fault;
  r.step = walked_;
  r.detected_s = monotonic_s();
  if (walked_ == 0) {
    // Nothing has moved since the start-up check left every servo where it was: nothing to stop.
    r.message = "stopped before the first step: " + cause;
    stopped_ = r;
    return;
  }
  try {
    bus_->stop(safe_posture_counts(file_), file_.stop);
    r.commanded_s = monotonic_s();
  } catch (const RuntimeFailure& e) {
    r.command_error = e.what();
  }
  r.message = stop_message(r, file_.stop);
  stopped_ = r;
}

void require_hardware_faults(const robot::Morphology& morph, const body::FaultTimeline& faults) {
  for (const body::Fault& f : faults) {
    if (!std::holds_alternative<body::LegFault>(f.kind) || f.joint) {
      throw BadInput("fault '" + body::malfunction_text(morph, f) +
                     "': on hardware only the paper's leg fault can be enacted (the controller "
                     "holds the leg's posture); the others are a real robot's own physics and "
                     "sensors");
    }
  }
}

}  // namespace multicpg::hw
