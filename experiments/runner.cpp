#include "experiments/runner.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "common/atomic_file.h"
#include "common/checksum.h"
#include "common/dir_lock.h"
#include "common/errors.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// SplitMix64 (Steele, Lea, Flood 2014) constants.
constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;
constexpr std::uint64_t kMix1 = 0xbf58476d1ce4e5b9ULL;
constexpr std::uint64_t kMix2 = 0x94d049bb133111ebULL;

constexpr int kKeyRunDigits = 3;
constexpr int kJsonIndent = 2;
constexpr long kSecondsPerMinute = 60;
constexpr long kSecondsPerHour = 3600;

std::uint64_t splitmix64(std::uint64_t x) {
  x += kGoldenGamma;
  x = (x ^ (x >> 30)) * kMix1;
  x = (x ^ (x >> 27)) * kMix2;
  return x ^ (x >> 31);
}

void check_keys(const std::vector<Task>& tasks) {
  std::set<std::string> seen;
  for (const Task& t : tasks) {
    if (!key_names_a_file(t.key)) {
      throw BadInput("run key '" + t.key + "' cannot name a file (letters, digits, + - _ . =)");
    }
    if (!seen.insert(t.key).second) throw BadInput("run key '" + t.key + "' is repeated");
  }
}

constexpr const char* kChecksumField = "checksum";

// `record` with its checksum: of its canonical dump (compact, keys sorted, numbers in shortest
// round-trip form), which parsing and dumping again reproduces exactly.
nlohmann::json sealed(nlohmann::json record) {
  record[kChecksumField] = checksum_text(record.dump());
  return record;
}

// The sealed record saved in `path`, if the file exists.
std::optional<nlohmann::json> read_sealed(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return parse_sealed(text.str(), path);
}

// What OUT/experiment.json holds and a resume must match: the arguments and the run keys.
nlohmann::json experiment_record(const std::vector<Task>& tasks, const nlohmann::json& arguments) {
  nlohmann::json keys = nlohmann::json::array();
  for (const Task& t : tasks) keys.push_back(t.key);
  return {{"arguments", arguments}, {"runs", keys}};
}

constexpr const char* kProvenanceField = "provenance";

// Adds to `out` the dotted path of every leaf where `a` and `b` differ
// ("arguments.sim.servo_gain").
void differing_keys(const nlohmann::json& a, const nlohmann::json& b, const std::string& path,
                    std::vector<std::string>& out) {
  if (a.is_object() && b.is_object()) {
    std::set<std::string> names;
    for (const nlohmann::json* side : {&a, &b}) {
      for (const auto& item : side->items()) names.insert(item.key());
    }
    for (const std::string& n : names) {
      const std::string child = path.empty() ? n : path + "." + n;
      if (!a.contains(n) || !b.contains(n)) {
        out.push_back(child);
      } else {
        differing_keys(a.at(n), b.at(n), child, out);
      }
    }
  } else if (a != b) {
    out.push_back(path);
  }
}

// "arguments.seed, arguments.sim.servo_gain": every key whose value differs.
std::string what_differs(const nlohmann::json& stored, const nlohmann::json& now) {
  std::vector<std::string> keys;
  differing_keys(stored, now, "", keys);
  std::string out;
  for (const std::string& k : keys) out += (out.empty() ? "" : ", ") + k;
  return out;
}

// Makes OUT/runs and claims OUT for these arguments, or checks an earlier claim matches.
void claim_out_dir(const fs::path& out, const std::vector<Task>& tasks,
                   const nlohmann::json& arguments, const nlohmann::json& provenance) {
  const fs::path record_path = out / "experiment.json";
  const nlohmann::json record = experiment_record(tasks, arguments);
  if (std::optional<nlohmann::json> stored = read_sealed(record_path)) {
    stored->erase(kProvenanceField);
    if (*stored != record) {
      throw BadInput("'" + out.string() + "' holds an experiment made with other " +
                     what_differs(*stored, record) + "; use another output directory");
    }
    return;
  }
  for (const fs::directory_entry& e : fs::directory_iterator(out / "runs")) {
    if (e.path().extension() == ".json") {
      throw BadInput("'" + (out / "runs").string() +
                     "' holds runs but no experiment.json; use another output directory");
    }
  }
  nlohmann::json saved = record;
  saved[kProvenanceField] = provenance;
  write_file_atomic(record_path, sealed(saved).dump(kJsonIndent) + "\n");
}

fs::path run_path(const fs::path& out, const Task& task) {
  return out / "runs" / (task.key + ".json");
}

// The saved result of `task`, if it finished in an earlier session.
std::optional<nlohmann::json> load_run(const fs::path& out, const Task& task) {
  const fs::path path = run_path(out, task);
  std::optional<nlohmann::json> saved = read_sealed(path);
  if (!saved) return std::nullopt;
  if (!saved->is_object() || saved->value("key", "") != task.key ||
      saved->value("seed", std::uint64_t{0}) != task.seed || !saved->contains("result")) {
    throw BadInput("'" + path.string() + "' is not the run " + task.key +
                   "; delete it and start again");
  }
  return saved->at("result");
}

void save_run(const fs::path& out, const Task& task, const nlohmann::json& result) {
  const nlohmann::json saved{{"key", task.key},   {"group", task.group},   {"run", task.run},
                             {"seed", task.seed}, {"params", task.params}, {"result", result}};
  write_file_atomic(run_path(out, task), sealed(saved).dump(kJsonIndent) + "\n");
}

std::string duration(double seconds) {
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= kSecondsPerHour) {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / kSecondsPerHour,
                  (s % kSecondsPerHour) / kSecondsPerMinute);
  } else if (s >= kSecondsPerMinute) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / kSecondsPerMinute, s % kSecondsPerMinute);
  } else {
    std::snprintf(buf, sizeof buf, "%lds", s);
  }
  return buf;
}

// Runs done of total, elapsed, estimated time left: one line rewritten in place on a
// terminal, plain lines otherwise (logs).
class Progress {
 public:
  Progress(bool enabled, std::size_t total, std::size_t loaded)
      : enabled_(enabled),
        in_place_(enabled && ::isatty(STDERR_FILENO) != 0),
        total_(total),
        done_(loaded),
        start_(Clock::now()) {
    if (enabled_ && loaded > 0) {
      std::cerr << "resuming: " << loaded << " of " << total << " runs already done\n";
    }
  }

  void run_finished() {
    ++done_;
    ++ran_;
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double left = elapsed / static_cast<double>(ran_) * static_cast<double>(total_ - done_);
    std::ostringstream line;
    line << "runs " << done_ << "/" << total_ << ", " << duration(elapsed) << " elapsed, about "
         << duration(left) << " left";
    if (in_place_) {
      std::cerr << "\r" << line.str() << "\033[K" << (done_ == total_ ? "\n" : "") << std::flush;
    } else {
      std::cerr << line.str() << "\n";
    }
  }

  // Ends an in-place line that was cut short (a failed run).
  void close() {
    if (in_place_ && ran_ > 0 && done_ < total_) std::cerr << "\n";
  }

 private:
  bool enabled_;
  bool in_place_;
  std::size_t total_;
  std::size_t done_;
  std::size_t ran_ = 0;
  Clock::time_point start_;
};

}  // namespace

std::uint64_t derive_seed(std::uint64_t base_seed, std::string_view key) {
  return splitmix64(splitmix64(base_seed) ^ fnv1a64(key));
}

bool key_names_a_file(std::string_view key) {
  if (key.empty() || key.front() == '.') return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '-' || c == '_' || c == '.' || c == '=';
  });
}

std::string run_key(std::string_view group, int run) {
  char digits[16];
  std::snprintf(digits, sizeof digits, "%0*d", kKeyRunDigits, run);
  return std::string(group) + "_run" + digits;
}

int default_jobs() {
  return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

void validate(const RunnerOptions& options) {
  if (options.jobs < 1) {
    throw BadInput("jobs must be at least 1, got " + std::to_string(options.jobs));
  }
  if (options.out_dir.empty()) throw BadInput("empty output directory");
  if (!options.arguments.is_object()) {
    throw std::logic_error("runner arguments must be a JSON object");
  }
}

nlohmann::json parse_sealed(const std::string& text, const fs::path& path) {
  const auto damaged = [&](const std::string& why) {
    return BadInput("'" + path.string() + "' is damaged (" + why + "); delete it and start again");
  };
  nlohmann::json record = nlohmann::json::parse(text, nullptr, false);
  if (record.is_discarded()) throw damaged("not JSON");
  if (!record.is_object()) throw damaged("not a JSON object");
  const auto stored = record.find(kChecksumField);
  if (stored == record.end() || !stored->is_string()) throw damaged("no checksum");
  const std::string expected = stored->get<std::string>();
  record.erase(stored);
  if (checksum_text(record.dump()) != expected) throw damaged("checksum does not match");
  return record;
}

RunnerOutcome run_tasks(const std::vector<Task>& tasks, const TaskFunction& fn,
                        const RunnerOptions& options) {
  validate(options);
  check_keys(tasks);
  ensure_writable_dir(options.out_dir / "runs");
  // Held until every run is saved: a second process on OUT is refused instead of mixing its runs
  // in. Under the lock no other multicpg writes here, so temporary files are strays of killed runs.
  const DirLock lock(options.out_dir);
  remove_stray_temps(options.out_dir);
  claim_out_dir(options.out_dir, tasks, options.arguments, options.provenance);

  RunnerOutcome outcome;
  outcome.results.resize(tasks.size());
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    if (std::optional<nlohmann::json> saved = load_run(options.out_dir, tasks[i])) {
      outcome.results[i] = std::move(*saved);
      ++outcome.loaded;
    } else {
      todo.push_back(i);
    }
  }

  Progress progress(options.progress, tasks.size(), static_cast<std::size_t>(outcome.loaded));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // guards outcome, progress and failure
  std::exception_ptr failure;
  auto worker = [&] {
    while (!stop) {
      const std::size_t n = next++;
      if (n >= todo.size()) return;
      const Task& task = tasks[todo[n]];
      try {
        nlohmann::json result = fn(task);
        save_run(options.out_dir, task, result);
        const std::lock_guard<std::mutex> lock(mutex);
        outcome.results[todo[n]] = std::move(result);
        ++outcome.ran;
        progress.run_finished();
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
    }
  };
  const std::size_t threads = std::min(todo.size(), static_cast<std::size_t>(options.jobs));
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  progress.close();
  if (failure) std::rethrow_exception(failure);
  return outcome;
}

}  // namespace multicpg::experiments
