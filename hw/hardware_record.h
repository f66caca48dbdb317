// What a run on a real robot records of its hardware (docs/hardware.md "Outputs"): the file, the
// pacing, the loop's timing, the link errors by kind, the targets clamped and how it stopped; and
// every step as a CSV row.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "hw/hardware_body.h"
#include "hw/hardware_file.h"
#include "robot/morphology.h"

namespace multicpg::hw {

// The file (path, name, checksum, protocol), the pacing, whether it senses the trunk's position,
// the loop's timing, the link errors by kind, the targets clamped, and the stop (null while none).
nlohmann::json hardware_json(const HardwareFile& file, Pacing pacing, const HardwareBody& body);

// "loop: 27.0 Hz (period 37.00 ms, p99 jitter 0.21 ms, 0 overruns), link errors: none": one line
// of a hardware_json record, what walk, learn and tunnel print after a run on a real robot.
std::string hardware_summary(const nlohmann::json& hardware);

// Every step to a CSV: step, time, yaw (and position when sensed), each joint's target and,
// where the hardware reports them, its angle and each foot's contact.
class StepCsv final : public StepSink {
 public:
  StepCsv(std::ostream& out, const HardwareFile& file, const robot::Morphology& morph);
  void row(const StepRow& row) override;

 private:
  std::ostream& out_;
  const HardwareFile& file_;
};

// Several sinks as one, told in order (null ones are skipped).
class StepSinks final : public StepSink {
 public:
  explicit StepSinks(std::vector<StepSink*> all) : all_(std::move(all)) {}
  void row(const StepRow& row) override {
    for (StepSink* s : all_)
      if (s != nullptr) s->row(row);
  }
  void event(const body::Event& event) override {
    for (StepSink* s : all_)
      if (s != nullptr) s->event(event);
  }

 private:
  std::vector<StepSink*> all_;
};

}  // namespace multicpg::hw
