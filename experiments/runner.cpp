#include "experiments/runner.h"

#include <limits.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <functional>
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
#include "common/input_file.h"
#include "common/interrupt.h"
#include "common/json_diff.h"
#include "common/random.h"
#include "common/worker_threads.h"
#include "experiments/processes.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kKeyRunDigits = 3;
constexpr int kJsonIndent = 2;
constexpr long kSecondsPerMinute = 60;
constexpr long kSecondsPerHour = 3600;

void check_keys(const std::vector<Task>& tasks) {
  std::set<std::string> seen;
  for (const Task& t : tasks) {
    if (!key_names_a_file(t.key)) {
      throw BadInput("run key '" + t.key +
                     "' cannot name a file (letters, digits, + - _ . =, at most " +
                     std::to_string(max_key_length()) + " characters)");
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

// What OUT/experiment.json holds and a resume must match: the arguments and the run keys.
nlohmann::json experiment_record(const std::vector<Task>& tasks, const nlohmann::json& arguments) {
  nlohmann::json keys = nlohmann::json::array();
  for (const Task& t : tasks) keys.push_back(t.key);
  return {{"arguments", arguments}, {"runs", keys}};
}

// "arguments.seed, arguments.sim.servo_gain": every key whose value differs.
std::string what_differs(const nlohmann::json& stored, const nlohmann::json& now) {
  std::string out;
  const std::vector<std::string> keys = json_differences(stored, now);
  for (const std::string& k : keys) out += (out.empty() ? "" : ", ") + k;
  return out;
}

// Makes OUT/runs and claims OUT for these arguments, or checks an earlier claim matches.
void claim_out_dir(const fs::path& out, const std::vector<Task>& tasks,
                   const nlohmann::json& arguments) {
  const fs::path record_path = out / "experiment.json";
  const nlohmann::json record = experiment_record(tasks, arguments);
  if (std::optional<nlohmann::json> stored = read_sealed(record_path)) {
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
  write_file_atomic(record_path, sealed(record).dump(kJsonIndent) + "\n");
}

// Appends this session's provenance to OUT/provenance.json, one entry per start or resume. Kept
// apart from experiment.json, which holds only what decides the results, so equal experiments
// give equal files wherever and however they ran.
void record_session(const fs::path& out, const nlohmann::json& provenance) {
  const fs::path path = out / "provenance.json";
  nlohmann::json sessions = nlohmann::json::array();
  std::error_code ec;
  if (fs::exists(path, ec)) {
    sessions = nlohmann::json::parse(
        read_input_file(path, kMaxRecordBytes, kMaxRecordText, "a provenance record"), nullptr,
        false);
    if (!sessions.is_array()) {
      throw BadInput("'" + path.string() + "' is damaged (not a JSON array); delete it");
    }
  }
  sessions.push_back(provenance);
  write_file_atomic(path, sessions.dump(kJsonIndent) + "\n");
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
  Progress(bool enabled, const std::string& label, std::size_t total, std::size_t loaded)
      : enabled_(enabled),
        // Lines of several experiments at once cannot share one line in place.
        in_place_(enabled && label.empty() && ::isatty(STDERR_FILENO) != 0),
        prefix_(label.empty() ? "" : label + ": "),
        total_(total),
        done_(loaded),
        start_(Clock::now()) {
    if (enabled_ && loaded > 0) {
      std::cerr << prefix_ << "resuming: " << loaded << " of " << total << " runs already done\n";
    }
  }

  void run_finished() {
    ++done_;
    ++ran_;
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double left = elapsed / static_cast<double>(ran_) * static_cast<double>(total_ - done_);
    std::ostringstream line;
    line << prefix_ << "runs " << done_ << "/" << total_ << ", " << duration(elapsed)
         << " elapsed, about " << duration(left) << " left";
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
  std::string prefix_;
  std::size_t total_;
  std::size_t done_;
  std::size_t ran_ = 0;
  Clock::time_point start_;
};

// The out dir's side of run_tasks, in the only or the primary process: OUT claimed and locked,
// saved runs loaded, and each new result saved the moment it arrives, whether computed by this
// process's threads (run_local) or, under MPI, by another process.
class Session {
 public:
  Session(const std::vector<Task>& tasks, const RunnerOptions& options)
      : tasks_(tasks),
        out_(options.out_dir),
        // Held until every run is saved: a second process on OUT is refused instead of mixing
        // its runs in.
        lock_(writable(options.out_dir)) {
    // Under the lock no other multicpg writes here, so temporary files are strays of killed runs.
    remove_stray_temps(out_);
    claim_out_dir(out_, tasks, options.arguments);
    record_session(out_, options.provenance);
    outcome_.results.resize(tasks.size());
    for (std::size_t i = 0; i < tasks.size(); ++i) {
      if (std::optional<nlohmann::json> saved = load_run(out_, tasks[i])) {
        outcome_.results[i] = std::move(*saved);
        ++outcome_.loaded;
      } else {
        todo_.push_back(i);
      }
    }
    progress_.emplace(options.progress, options.progress_label, tasks.size(),
                      static_cast<std::size_t>(outcome_.loaded));
  }

  // The index of the next task to compute; none once every task is handed out, one failed or
  // a signal asked the process to stop (common/interrupt.h: the runs in flight stop too, the
  // saved ones stay for a resume).
  std::optional<std::size_t> next() {
    if (stop_ || interrupt_signal() != 0) return std::nullopt;
    const std::size_t n = next_++;
    if (n >= todo_.size()) return std::nullopt;
    return todo_[n];
  }

  // Saves and keeps the result of task `i`.
  void finished(std::size_t i, nlohmann::json result) {
    try {
      save_run(out_, tasks_[i], result);
    } catch (...) {
      failed(std::current_exception());
      return;
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    outcome_.results[i] = std::move(result);
    ++outcome_.ran;
    progress_->run_finished();
  }

  // No new task starts; end() rethrows the first failure.
  void failed(std::exception_ptr error) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_) failure_ = std::move(error);
    stop_ = true;
  }

  // Computes tasks on `jobs` threads until none is left or one failed.
  void run_local(const TaskFunction& fn, int jobs) {
    auto worker = [&] {
      while (const std::optional<std::size_t> i = next()) {
        try {
          finished(*i, fn(tasks_[*i]));
        } catch (...) {
          failed(std::current_exception());
        }
      }
    };
    try {
      WorkerThreads(std::min(todo_.size(), static_cast<std::size_t>(jobs)), worker).join();
    } catch (const RuntimeFailure&) {
      failed(std::current_exception());  // no thread ran a task
    }
  }

  // Every result, or the first failure rethrown (Interrupted when a signal stopped the runs).
  RunnerOutcome end() {
    progress_->close();
    if (failure_) std::rethrow_exception(failure_);
    check_interrupted();  // tasks were left undone
    return std::move(outcome_);
  }

 private:
  static const fs::path& writable(const fs::path& dir) {
    ensure_writable_dir(dir / "runs");
    return dir;
  }

  const std::vector<Task>& tasks_;
  fs::path out_;
  DirLock lock_;
  RunnerOutcome outcome_;
  std::vector<std::size_t> todo_;
  std::optional<Progress> progress_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;  // guards outcome_, progress_ and failure_
  std::exception_ptr failure_;
};

#ifdef MULTICPG_MPI
// run_tasks across the processes of an MPI job. The primary (rank 0) keeps OUT and hands out the
// runs one at a time as processes ask for them; each other process asks for as many runs as it
// has threads, sends each result back as JSON text and asks again, until told to stop. Each
// message to the primary gets exactly one reply (a task or stop), so when run_tasks returns no
// message is left in flight. At the end the primary sends every process the results (or the
// failure), so all of them go on with the same outcome and fail alike.

// Message tags. To the primary: kAsk (empty), kResult {"index","result"}, kFailed
// {"index","error"}. From it: kTask (the task index as text) and kStop (empty).
enum Tag : int { kAsk = 1, kResult, kFailed, kTask, kStop };

// An exception as JSON, so another process can throw its like (same kind, same message).
nlohmann::json describe(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const Interrupted& e) {
    return {{"kind", "interrupted"}, {"signal", e.signal()}, {"message", e.what()}};
  } catch (const BadInput& e) {
    return {{"kind", "bad_input"}, {"message", e.what()}};
  } catch (const RuntimeFailure& e) {
    return {{"kind", "runtime_failure"}, {"message", e.what()}};
  } catch (const std::exception& e) {
    return {{"kind", "error"}, {"message", e.what()}};
  } catch (...) {
    return {{"kind", "error"}, {"message", "unknown error"}};
  }
}

std::exception_ptr exception_from(const nlohmann::json& described) {
  const std::string kind = described.at("kind");
  const std::string message = described.at("message");
  if (kind == "interrupted") {
    return std::make_exception_ptr(Interrupted(described.at("signal").get<int>()));
  }
  if (kind == "bad_input") return std::make_exception_ptr(BadInput(message));
  if (kind == "runtime_failure") return std::make_exception_ptr(RuntimeFailure(message));
  return std::make_exception_ptr(std::runtime_error(message));
}

RunnerOutcome coordinate(const std::vector<Task>& tasks, const TaskFunction& fn,
                         const RunnerOptions& options) {
  agree_to_start();
  std::optional<Session> session;
  std::exception_ptr setup_failure;
  try {
    session.emplace(tasks, options);
  } catch (...) {
    setup_failure = std::current_exception();
  }
  // This process computes too; its main thread answers the others.
  std::thread local;
  if (session) local = std::thread([&] { session->run_local(fn, options.jobs); });

  const int processes = process_count();
  std::vector<int> in_flight(static_cast<std::size_t>(processes), 0);
  std::vector<bool> stopped(static_cast<std::size_t>(processes), false);
  stopped[kPrimaryRank] = true;
  const auto all_done = [&] {
    return std::all_of(stopped.begin(), stopped.end(), [](bool s) { return s; }) &&
           std::all_of(in_flight.begin(), in_flight.end(), [](int n) { return n == 0; });
  };
  while (!all_done()) {
    std::optional<Message> m = take_message(std::nullopt);
    if (!m) {
      pause_between_polls();
      continue;
    }
    const auto from = static_cast<std::size_t>(m->from);
    // Our own messages; a damaged one fails the run like any error.
    const auto read = [&](const std::function<void(nlohmann::json)>& use) {
      --in_flight[from];
      try {
        use(nlohmann::json::parse(m->text));
      } catch (const nlohmann::json::exception&) {
        session->failed(std::current_exception());
      }
    };
    if (m->tag == kFailed) {
      read([&](nlohmann::json body) { session->failed(exception_from(body.at("error"))); });
    }
    // The answer goes out before the result is saved: the process computes its next run
    // meanwhile instead of waiting for the disk.
    const std::optional<std::size_t> task = session ? session->next() : std::nullopt;
    if (task) {
      send_message(m->from, kTask, std::to_string(*task));
      ++in_flight[from];
    } else {
      send_message(m->from, kStop, "");
      stopped[from] = true;
    }
    if (m->tag == kResult) {
      read([&](nlohmann::json body) {
        session->finished(body.at("index"), std::move(body.at("result")));
      });
    }
  }
  if (local.joinable()) local.join();

  std::exception_ptr failure = setup_failure;
  RunnerOutcome outcome;
  if (!failure) {
    try {
      outcome = session->end();
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (failure) {
    broadcast_from_primary(nlohmann::json{{"failure", describe(failure)}}.dump());
    std::rethrow_exception(failure);
  }
  broadcast_from_primary(nlohmann::json{
      {"results", outcome.results},
      {"loaded", outcome.loaded},
      {"ran", outcome.ran}}.dump());
  return outcome;
}

RunnerOutcome serve_primary(const std::vector<Task>& tasks, const TaskFunction& fn,
                            const RunnerOptions& options) {
  agree_to_start();
  std::mutex mutex;  // guards assigned, answers and quit
  std::condition_variable changed;
  std::deque<std::size_t> assigned;
  std::deque<std::pair<Tag, std::string>> answers;  // what to send the primary
  bool quit = false;
  auto worker = [&] {
    std::unique_lock lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return quit || !assigned.empty(); });
      if (assigned.empty()) return;
      const std::size_t i = assigned.front();
      assigned.pop_front();
      lock.unlock();
      std::pair<Tag, std::string> answer;
      try {
        answer = {kResult, nlohmann::json{{"index", i}, {"result", fn(tasks[i])}}.dump()};
      } catch (...) {
        answer = {
            kFailed,
            nlohmann::json{{"index", i}, {"error", describe(std::current_exception())}}.dump()};
      }
      lock.lock();
      answers.push_back(std::move(answer));
      changed.notify_all();
    }
  };
  WorkerThreads pool(static_cast<std::size_t>(options.jobs), worker);

  int busy = 0;  // tasks assigned and not yet answered
  bool told_to_stop = false;
  const auto tell = [&](Tag tag, const std::string& text) {
    send_message(kPrimaryRank, tag, text);
    const Message reply = wait_for_message(kPrimaryRank);
    if (reply.tag == kStop) {
      told_to_stop = true;
      return;
    }
    const std::lock_guard<std::mutex> lock(mutex);
    assigned.push_back(std::stoull(reply.text));
    ++busy;
    changed.notify_all();
  };
  const auto quit_workers = [&] {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      quit = true;
    }
    changed.notify_all();
  };
  try {
    for (;;) {
      while (!told_to_stop && busy < options.jobs) tell(kAsk, "");
      if (busy == 0) break;
      std::pair<Tag, std::string> answer;
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return !answers.empty(); });
        answer = std::move(answers.front());
        answers.pop_front();
      }
      --busy;
      tell(answer.first, answer.second);
    }
  } catch (...) {
    quit_workers();  // the pool joins its threads as the failure unwinds past it
    throw;
  }
  quit_workers();
  pool.join();

  const nlohmann::json end = nlohmann::json::parse(broadcast_from_primary(""));
  if (end.contains("failure")) std::rethrow_exception(exception_from(end.at("failure")));
  RunnerOutcome outcome;
  outcome.results = end.at("results").get<std::vector<nlohmann::json>>();
  outcome.loaded = end.at("loaded");
  outcome.ran = end.at("ran");
  return outcome;
}
#endif

}  // namespace

std::uint64_t derive_seed(std::uint64_t base_seed, std::string_view key) {
  return splitmix64(splitmix64(base_seed) ^ fnv1a64(key));
}

std::size_t max_key_length() {
  constexpr std::string_view kRunFileExtension = ".json";
  return NAME_MAX - kRunFileExtension.size() - kTempMarker.size() - kMaxPidDigits;
}

bool key_names_a_file(std::string_view key) {
  if (key.empty() || key.front() == '.' || key.size() > max_key_length()) return false;
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
  // The cores this process may run on: fewer than the machine's when mpirun (or taskset, or a
  // batch system) binds it.
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (::sched_getaffinity(0, sizeof allowed, &allowed) == 0) {
    return std::max(1, CPU_COUNT(&allowed));
  }
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
  // Checked alike in every process, before any of them waits on another.
  validate(options);
  check_keys(tasks);
#ifdef MULTICPG_MPI
  if (process_count() > 1) {
    return is_primary_process() ? coordinate(tasks, fn, options)
                                : serve_primary(tasks, fn, options);
  }
#endif
  Session session(tasks, options);
  session.run_local(fn, options.jobs);
  return session.end();
}

void check_out_dir(const std::vector<Task>& tasks, const RunnerOptions& options) {
  validate(options);
  check_keys(tasks);
  const fs::path& out = options.out_dir;
  if (std::optional<nlohmann::json> stored = read_sealed(out / "experiment.json")) {
    const nlohmann::json record = experiment_record(tasks, options.arguments);
    if (*stored != record) {
      throw BadInput("'" + out.string() + "' holds an experiment made with other " +
                     what_differs(*stored, record) + "; use another output directory");
    }
  }
  std::error_code ec;
  if (!fs::is_directory(out / "runs", ec)) return;
  for (const Task& task : tasks) load_run(out, task);
}

std::optional<nlohmann::json> read_sealed(const std::filesystem::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  return parse_sealed(read_input_file(path, kMaxRecordBytes, kMaxRecordText, "a run record"), path);
}

}  // namespace multicpg::experiments
