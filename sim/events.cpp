#include "sim/events.h"

#include <algorithm>
#include <string>

#include "common/errors.h"

namespace multicpg::sim {

const char* to_string(EventKind kind) {
  switch (kind) {
    case EventKind::fault:
      return "fault";
    case EventKind::recovery:
      return "recovery";
    case EventKind::detection:
      return "detection";
    case EventKind::trial_start:
      return "trial_start";
    case EventKind::trial_end:
      return "trial_end";
    case EventKind::episode_end:
      return "episode_end";
  }
  return "event";
}

void validate(const robot::Morphology& morph, const FaultTimeline& faults) {
  std::vector<bool> failed(morph.size(), false);
  long previous = 0;
  for (const Fault& f : faults) {
    const char* what = f.recover ? "--recover" : "--fault";
    if (f.step < 0 || f.step > kMaxSteps) {
      throw BadInput(std::string(what) + " step must be in 0.." + std::to_string(kMaxSteps) +
                     ", got " + std::to_string(f.step));
    }
    if (f.step < previous) throw BadInput("faults must be listed in step order");
    previous = f.step;
    if (f.legs.empty()) throw BadInput(std::string(what) + " names no leg");
    std::vector<bool> seen(morph.size(), false);
    for (std::size_t leg : f.legs) {
      if (leg >= morph.size()) {
        throw BadInput("the " + morph.name + " has no leg number " + std::to_string(leg));
      }
      const std::string& name = morph.legs[leg].name;
      if (seen[leg]) throw BadInput("leg " + name + " is listed twice in one fault");
      seen[leg] = true;
      if (f.recover && !failed[leg]) {
        throw BadInput("leg " + name + " recovers at step " + std::to_string(f.step) +
                       " but has not failed before");
      }
      if (!f.recover && failed[leg]) {
        throw BadInput("leg " + name + " fails at step " + std::to_string(f.step) +
                       " but has already failed");
      }
      failed[leg] = !f.recover;
    }
    if (std::all_of(failed.begin(), failed.end(), [](bool b) { return b; })) {
      throw BadInput("every leg of the " + morph.name + " has failed at step " +
                     std::to_string(f.step) + ": it cannot walk");
    }
  }
}

}  // namespace multicpg::sim
