#include "report/replay/rerun.h"

#include "body/fault_spec.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "experiments/learning_run.h"
#include "experiments/run_json.h"
#include "experiments/run_spec.h"
#include "experiments/sweep.h"
#include "report/replay/page.h"
#include "sim/walk.h"

namespace multicpg::report {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The file a `learn --out DIR` run keeps its result in.
constexpr const char* kLearnResultFile = "learning.json";

std::string quoted(const std::string& name) {
  return "'" + name + "'";
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// The run file's bytes: a regular file of at most kMaxRecordBytes (a FIFO or device is refused
// without waiting on it).
std::string read_run_file(const fs::path& path) {
  return read_input_file(path, kMaxRecordBytes, kMaxRecordText, "a run file");
}

json read_json(const fs::path& path) {
  const std::string text = read_run_file(path);
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw BadInput(quoted(path.string()) +
                   " is not a whole JSON document (truncated or damaged): " + first_line(e.what()));
  }
}

// Checks the run as validate does, its errors naming the file.
void check(const experiments::RunSpec& spec, const std::string& name) {
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    throw BadInput(name + ": " + e.key() + " " + e.what());
  }
}

// Whether every value `again` holds is the one `saved` holds (a Python result may hold more).
bool reruns_as_saved(const json& saved, const json& again) {
  for (const auto& [key, value] : again.items()) {
    if (!saved.contains(key) || saved.at(key) != value) return false;
  }
  return true;
}

[[noreturn]] void differs(const std::string& name) {
  throw BadInput(name +
                 " does not rerun as saved: it was made with other simulation options than these "
                 "(terrain, body, servo gain: give them as flags) or by another version of "
                 "multicpg");
}

std::string faults_title(const robot::Morphology& morph, const body::FaultTimeline& faults) {
  std::string out;
  for (const body::Fault& f : faults) {
    out += (out.empty() ? "" : ", ") + body::malfunction_text(morph, f) +
           (f.recover ? " recovers" : " fails") + " at step " + std::to_string(f.step);
  }
  return out.empty() ? "no fault" : out;
}

RerunReplay rerun_experiment_run(const fs::path& file) {
  const json saved = experiments::parse_sealed(read_run_file(file), file);
  const fs::path dir = file.parent_path().parent_path();
  const experiments::RecordedSweep recorded = experiments::read_sweep(dir);
  const std::string id = file.stem().string();
  const experiments::PlannedRun* planned = experiments::find_run(recorded.sweep, id);
  if (planned == nullptr || !saved.contains("result")) {
    throw BadInput(quoted(file.string()) + " is not a run of the experiment in " +
                   quoted(dir.string()));
  }
  const experiments::RunSpec& spec = planned->spec;
  RerunReplay out;
  ReplayRecorder recorder;
  const json result = experiments::run_sweep_task(spec, &recorder);
  if (saved.at("result") != result) differs(quoted(file.string()));
  out.recording = recorder.recording();
  out.title = "run " + id + " of " + dir.filename().string() + ": " +
              experiments::morphology(spec.robot).name + ", " +
              faults_title(experiments::morphology(spec.robot), spec.faults);
  return out;
}

RerunReplay rerun_walk(const json& saved, const std::string& name, const sim::SimOptions& sim) {
  const experiments::RecordedWalk recorded = experiments::read_walk_json(saved, name, sim);
  const experiments::RunSpec& spec = recorded.spec;
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  check(spec, name);
  const sim::SimModel model = experiments::make_model(spec.robot);
  ReplayRecorder recorder;
  sim::WalkSpec walk;
  walk.start = spec.start;
  walk.faults = spec.faults;
  walk.settle = recorded.settle;
  walk.steps = recorded.steps;
  // Checked before a step is walked: a record edited to 10^8 steps is no replay.
  if (!report::kReplayStepLimits.contains(walk.steps)) {
    throw BadInput(name + ": steps " + std::to_string(walk.steps) + " is outside " +
                   report::kReplayStepLimits.text() +
                   ", the steps a replay holds (docs/replay.md)");
  }
  walk.window = recorded.window;
  walk.keep_record = false;
  walk.observer = &recorder;
  sim::WalkResult r;
  try {
    r = sim::walk(model, walk);
  } catch (const OptionError& e) {
    throw BadInput(name + ": " + e.key() + " " + e.what());
  }
  // What the walk measured decides whether it is the saved one: any other option moves the robot.
  const json again{{"distance_m", r.distance_m},
                   {"final_yaw_deg", r.final_yaw_deg},
                   {"window_deviations_deg", r.window_deviations_deg}};
  if (!reruns_as_saved(saved, again)) differs(name);
  return {recorder.recording(), "walk: " + morph.name + ", " + faults_title(morph, spec.faults)};
}

// What kind of result `saved` is, by the keys its command writes.
enum class Saved { learning, walk, tunnel, unknown };

Saved kind_of(const json& saved) {
  if (!saved.is_object()) return Saved::unknown;
  if (saved.contains("options") && saved.contains("trace") && saved.contains("status")) {
    return Saved::learning;
  }
  if (saved.contains("window_deviations_deg") && saved.contains("warmup")) return Saved::walk;
  if (saved.contains("touched_wall")) return Saved::tunnel;
  return Saved::unknown;
}

}  // namespace

RerunReplay rerun_learning(const json& saved, const std::string& name, const sim::SimOptions& sim,
                           sim::Observer* watch) {
  try {
    const experiments::RunSpec spec = experiments::read_learn_json(saved, name, sim);
    const learning::CompensationOptions& options = *spec.learning;
    check(spec, name);
    const sim::SimModel model = experiments::make_model(spec.robot);
    ReplayRecorder recorder;
    sim::Observers watched({&recorder, watch});  // a null watch is skipped
    const experiments::LearningRun run = experiments::run_learning(model, spec, 0, &watched);
    if (!reruns_as_saved(saved, experiments::learn_json(spec, run.result))) differs(name);
    const robot::Morphology& morph = experiments::morphology(spec.robot);
    return {recorder.recording(), "learn: " + morph.name + ", " + faults_title(morph, spec.faults) +
                                      ", " + std::string(learning::to_string(options.mode)) +
                                      " mode"};
  } catch (const json::exception& e) {
    throw BadInput(name + " is not a learning result of this version of multicpg (" +
                   first_line(e.what()) + ")");
  }
}

bool is_experiment_run(const fs::path& path) {
  std::error_code error;
  return path.parent_path().filename() == "runs" &&
         fs::exists(path.parent_path().parent_path() / "experiment.json", error);
}

RerunReplay rerun_saved(const fs::path& path, const sim::SimOptions& sim) {
  std::error_code error;
  if (fs::is_directory(path, error)) return rerun_saved(path / kLearnResultFile, sim);
  if (is_experiment_run(path)) return rerun_experiment_run(path);
  const json saved = read_json(path);
  const std::string name = quoted(path.string());
  switch (kind_of(saved)) {
    case Saved::learning:
      return rerun_learning(saved, name, sim);
    case Saved::walk:
      try {
        return rerun_walk(saved, name, sim);
      } catch (const json::exception& e) {
        throw BadInput(name + " is not a walk result of this version of multicpg (" +
                       first_line(e.what()) + ")");
      }
    case Saved::tunnel:
      throw BadInput(name +
                     " is a tunnel result, which does not record the legs that failed: make its "
                     "replay with `multicpg tunnel ... --replay FILE.html`");
    case Saved::unknown:
      break;
  }
  throw BadInput(name +
                 " is not a run this version of multicpg replays (a run file DIR/runs/ID.json, "
                 "or the JSON of learn or walk)");
}

}  // namespace multicpg::report
