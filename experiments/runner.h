// Many independent runs on J threads, each saved as soon as it finishes, so an interrupted
// experiment started again with the same arguments continues where it stopped (docs/learning.md
// "Running experiments"). Under mpirun the runs are shared among the processes too
// (experiments/processes.h). Results never depend on J or the processes: each run's seed comes from
// its key, never from thread, process or order.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/limits.h"

namespace multicpg::experiments {

// One run of an experiment.
struct Task {
  std::string key;    // stable and unique; names the run file OUT/runs/<key>.json
  std::string group;  // the table row it belongs to: a scenario name or a beta
  int run = 0;        // index within the group
  std::uint64_t seed = 0;
  nlohmann::json params;  // what the task function needs (disabled legs, beta, ...)
};

// Computes one run's result. Must depend only on the task (never on time or thread) and be
// safe to call from several threads at once.
using TaskFunction = std::function<nlohmann::json(const Task&)>;

// The seed of run `key` in an experiment seeded with `base_seed`: FNV-1a of the key mixed with
// the base by SplitMix64, so it is the same on every machine and for every thread count.
std::uint64_t derive_seed(std::uint64_t base_seed, std::string_view key);

// The longest run key: its run file "<key>.json" and that file's temporary sibling
// ("<key>.json.tmp<pid>", common/atomic_file.h) must fit in a file name (NAME_MAX bytes).
std::size_t max_key_length();
// Whether `key` can name a run file: letters, digits, + - _ . =, not starting with a dot, at most
// max_key_length() characters.
bool key_names_a_file(std::string_view key);

// "<group>_run<NNN>": the key of run `run` of `group`.
std::string run_key(std::string_view group, int run);

// The cores this process may run on (all cores unless it is bound to fewer; at least 1).
int default_jobs();
// Parallel runs a user may ask for: far more than any machine's cores is a typo.
inline constexpr Limits<int> kJobsLimits{1, 4096};

struct RunnerOptions {
  std::filesystem::path out_dir;
  int jobs = default_jobs();
  // Everything that decides the results (not the thread count), as a JSON object. Stored in
  // OUT/experiment.json; resuming with different arguments is refused.
  nlohmann::json arguments = nlohmann::json::object();
  // Where the results come from (common/provenance.h): appended to OUT/provenance.json at every
  // start and resume, never compared (a resume may come from another shell or machine).
  nlohmann::json provenance = nlohmann::json::object();
  bool progress = true;  // runs done, elapsed and time left on stderr
  // Names whose runs the progress lines count when several experiments run at once
  // ("experiment hexapod: runs 3/24, ..."); empty = no name.
  std::string progress_label;
};

// Throws BadInput (one line) for jobs < 1 or an empty output directory.
void validate(const RunnerOptions& options);

struct RunnerOutcome {
  std::vector<nlohmann::json> results;  // one per task, in task order
  int loaded = 0;                       // runs found finished in OUT/runs
  int ran = 0;                          // runs computed now
};

// Runs every task not yet saved in OUT/runs and returns all results. Throws BadInput if OUT
// was made with other arguments (naming each differing key, "arguments.learning.seed") or tasks,
// if a key is repeated or cannot name a file, if another process is running in OUT
// (OUT/.multicpg.lock), or if a saved file is damaged (naming it). Removes temporary files of
// killed runs (*.tmp<pid>) from OUT first. If a task throws, no new task starts, the runs in
// flight finish and are saved, and the first exception is rethrown: starting again repeats only
// the runs not saved.
// Under mpirun with several processes, every process calls run_tasks with the same tasks (they
// run the same command): the primary (rank 0) does all of the above and hands the runs out one
// at a time to whichever process (or thread of its own) is free, the others compute them on
// `jobs` threads each; every process returns the same outcome or throws the same error.
RunnerOutcome run_tasks(const std::vector<Task>& tasks, const TaskFunction& fn,
                        const RunnerOptions& options);

// What run_tasks would refuse of OUT, checked without writing or running anything: an
// experiment.json of other arguments or tasks, a damaged or foreign run file (BadInput naming
// it). For experiments run one after another (a landscape set), so that a damaged later one is
// refused before an earlier one resumes.
void check_out_dir(const std::vector<Task>& tasks, const RunnerOptions& options);

// OUT/experiment.json and each run file carry "checksum": checksum_text (common/checksum.h) of
// the canonical dump of the rest of the object. parse_sealed returns the object without it;
// throws BadInput naming `path` when `text` is not a JSON object, has no checksum or the checksum
// does not match (an edited or damaged file).
nlohmann::json parse_sealed(const std::string& text, const std::filesystem::path& path);
// The sealed record saved in `path` (parse_sealed), or nothing when there is no file there.
// Throws BadInput (one line naming it) for one that is no regular file (common/input_file.h),
// larger than kMaxRecordBytes or unreadable.
std::optional<nlohmann::json> read_sealed(const std::filesystem::path& path);

}  // namespace multicpg::experiments
