// Replays of saved runs (`multicpg replay RUN`, Python's multicpg.replay of a result): runs are
// deterministic, so the run a file records is made again with a ReplayRecorder attached, and the
// result it gives is checked against the file's before the replay is trusted (docs/replay.md).
//
// What can be replayed:
// - an experiment's run file, DIR/runs/ID.json (`multicpg run`, `experiment`, `reproduce`): its
//   experiment's record, DIR/experiment.json, holds every option of the run;
// - a learning result: `learn --json` (or `learn --out DIR`'s learning.json, or DIR itself);
// - a walk: `walk --json`.
// Learning and walk results record the robot, its faults, the learning options and the time
// steps, not the rest of the simulation (terrain, body, servo gain): those come from the options
// passed here, and a result made with others does not rerun as saved (refused, naming it).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "report/replay/recording.h"
#include "sim/sim.h"

namespace multicpg::report {

struct RerunReplay {
  Recording recording;
  std::string title;  // what the run was ("learn: hexapod, R1 failed at step 0, paper mode")
};

// The run saved at `path` (a run file, a JSON result or a `learn --out` directory) made again
// and recorded; `sim` is the simulation a learning or walk result is made again with (its time
// steps are the result's). Throws BadInput, one line naming the file, for a file that is missing,
// unreadable, no regular file (a FIFO is refused without waiting on it, a device without reading
// it), larger than kMaxRecordBytes (common/input_file.h), truncated or damaged, of another kind or
// another version of multicpg, whose robot file changed, or whose run does not rerun as saved.
RerunReplay rerun_saved(const std::filesystem::path& path, const sim::SimOptions& sim);

// Whether `path` is an experiment's run file (DIR/runs/ID.json beside DIR/experiment.json), which
// records every option of its simulation itself.
bool is_experiment_run(const std::filesystem::path& path);

// A learning result (the JSON of `learn --json`) made again and recorded; `name` names it in
// messages ("'learn.json'", "the result"). `watch`, if given, sees every step too (Python's
// Ctrl-C stops the run from it). Throws BadInput as rerun_saved does.
RerunReplay rerun_learning(const nlohmann::json& result, const std::string& name,
                           const sim::SimOptions& sim, sim::Observer* watch = nullptr);

}  // namespace multicpg::report
