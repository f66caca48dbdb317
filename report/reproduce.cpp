#include "report/reproduce.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <iostream>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/table.h"
#include "common/worker_threads.h"
#include "experiments/landscape.h"
#include "experiments/learner_benchmark.h"
#include "experiments/results_page.h"
#include "experiments/runner.h"
#include "experiments/scenarios.h"
#include "report/stages/stage.h"
#include "sim/json.h"

namespace multicpg::report {
namespace {

namespace fs = std::filesystem;

// Periods-alone learning as docs/learning.md measures it: 20 trials per episode.
constexpr int kPeriodsAloneMaxTrials = 20;
constexpr Sizes kFull{experiments::kScenarioRuns,
                      experiments::kScenarioRuns,
                      experiments::kBetaRuns,
                      learning::kDefaultMaxTrials,
                      {},
                      4,
                      2,
                      400,
                      experiments::kDefaultLandscapeWindows,
                      {},
                      kPeriodsAloneMaxTrials,
                      learning::kDefaultMaxEpisodes,
                      experiments::kDefaultBenchmarkSeeds,
                      true};
// The quick landscape: 27 of the 125 combinations (the fastest and the two slowest gaits), two
// windows each, so that it adds seconds, not a minute.
constexpr std::array<int, 3> kQuickLandscapePeriods{4, 8, 9};
// The quick β study caps its runs at 60 trials, under a third of the paper's 200: a β = 0
// (random search) run that reaches the paper's cap walks 296,000 steps. It leaves out β = 0.1 and
// 0.3, the slowest after random search (70 and 27 trials in a quick run at seed 1, two fifths of
// the study's CPU time), so that β = 0 still needs the most trials by its own count, not by the
// cap.
constexpr int kQuickBetaMaxTrials = 60;
constexpr std::array<double, 5> kQuickBetaValues{0.0, 0.5, 1.0, 5.0, 10.0};
// The quick periods-alone learning: one episode of 10 trials (the full one: up to 10 episodes
// of 20, a minute of CPU for a scenario that never holds).
constexpr int kQuickPeriodsAloneTrials = 10;
constexpr int kQuickPeriodsAloneEpisodes = 1;
// The quick learner benchmark: 3 seeds per scenario and learner (the full one: 100), seconds.
constexpr int kQuickBenchmarkSeeds = 3;
// Quick films: the learning film and the tunnel's at 16 and 32 controller steps per frame (the
// full: 4 and 2), the walking films 6 s of real time (160 steps at 27 Hz; the full: 400 steps).
// A frame costs about 37 ms of software rendering (docs/benchmarks.md).
constexpr int kQuickLearningFilmSpeed = 16;
constexpr int kQuickTunnelFilmSpeed = 32;
constexpr long kQuickWalkFilmSteps = 160;
constexpr Sizes kQuick{1,
                       1,
                       1,
                       kQuickBetaMaxTrials,
                       kQuickBetaValues,
                       kQuickLearningFilmSpeed,
                       kQuickTunnelFilmSpeed,
                       kQuickWalkFilmSteps,
                       2,
                       kQuickLandscapePeriods,
                       kQuickPeriodsAloneTrials,
                       kQuickPeriodsAloneEpisodes,
                       kQuickBenchmarkSeeds,
                       false};

// The stages asked for and every stage they need, in the table's (the report's) order.
std::vector<const Stage*> selected(const std::vector<std::string>& only) {
  std::vector<std::string_view> wanted;
  std::function<void(std::string_view)> want = [&](std::string_view id) {
    if (std::find(wanted.begin(), wanted.end(), id) != wanted.end()) return;
    wanted.push_back(stage_by_id(id).id);
    for (std::string_view need : stage_by_id(id).needs) want(need);
  };
  for (const std::string& id : only) want(id);
  std::vector<const Stage*> out;
  for (const Stage& s : reproduce_stages()) {
    if (only.empty() || std::find(wanted.begin(), wanted.end(), s.id) != wanted.end()) {
      out.push_back(&s);
    }
  }
  return out;
}

// A record an earlier run left in the report folder, parsed (nlohmann's exception when it is not
// JSON); BadInput naming it when it is no regular file (common/input_file.h) or too large.
nlohmann::json read_record(const fs::path& file, std::string_view what) {
  return nlohmann::json::parse(read_input_file(file, kMaxRecordBytes, kMaxRecordText, what));
}

class Reproduction {
 public:
  explicit Reproduction(const ReproduceOptions& o)
      : o_(o),
        ctx_{o, o.quick ? kQuick : kFull, [this](const std::string& line) { progress(line); }},
        start_(std::chrono::steady_clock::now()) {}

  void run() {
    ensure_writable_dir(o_.out);
    check_arguments();
    stages_ = selected(o_.only);
    sections_.resize(stages_.size());
    done_.assign(stages_.size(), false);
    started_.assign(stages_.size(), false);
    const int workers = std::max(
        1, std::min<int>(o_.jobs > 0 ? o_.jobs : experiments::default_jobs(), stages_.size()));
    WorkerThreads(static_cast<std::size_t>(workers), [this] { work(); }).join();
    if (failure_) std::rethrow_exception(failure_);
    write_results_page();
    write_file_atomic(o_.out / "index.html",
                      index_html("multicpg: the paper reproduced", intro(), sections_));
    progress("wrote " + (o_.out / "index.html").string());
    std::cout << verdict_line(sections_) << std::endl;  // the run's verdict, as the page opens
  }

 private:
  // Takes the first stage not started whose needs are done, early ones first (stage.h), until none
  // is left or one failed.
  void work() {
    std::unique_lock lock(mutex_);
    for (;;) {
      std::size_t next = stages_.size();
      bool left = false;
      for (std::size_t i = 0; i < stages_.size(); ++i) {
        if (started_[i]) continue;
        left = true;
        if (ready(i) && (next == stages_.size() || (stages_[i]->early && !stages_[next]->early))) {
          next = i;
        }
      }
      if (failure_ || !left) break;
      if (next == stages_.size()) {
        changed_.wait(lock);
        continue;
      }
      started_[next] = true;
      lock.unlock();
      std::exception_ptr error;
      try {
        sections_[next] = run_stage(*stages_[next]);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (error && !failure_) failure_ = error;
      done_[next] = true;
      changed_.notify_all();
    }
    changed_.notify_all();
  }

  bool ready(std::size_t i) const {
    for (std::string_view need : stages_[i]->needs) {
      for (std::size_t j = 0; j < stages_.size(); ++j) {
        if (stages_[j]->id == need && !done_[j]) return false;
      }
    }
    return true;
  }

  Section run_stage(const Stage& stage) {
    const std::string id(stage.id);
    const fs::path saved = o_.out / "sections" / (id + ".json");
    if (fs::exists(saved)) {
      progress(id + ": already done");
      try {
        return section_from_json(read_record(saved, "a saved section"));
      } catch (const nlohmann::json::exception&) {
        throw BadInput("'" + saved.string() +
                       "' is not a saved section; delete it to run the stage again");
      }
    }
    const auto begin = std::chrono::steady_clock::now();
    progress(id + ": started");
    Section section = stage.run(ctx_);
    section.seconds = seconds_since(begin);
    ensure_writable_dir(saved.parent_path());
    write_file_atomic(saved, to_json(section).dump(2) + "\n");
    progress(id + ": done in " + fixed(section.seconds, 0) + " s");
    return section;
  }

  std::string intro() const {
    return std::string(
               "Ren et al., \"Multiple chaotic central pattern generators with learning "
               "for legged locomotion and malfunction compensation\", Information "
               "Sciences 2015, reproduced with multicpg in MuJoCo") +
           (o_.sim.model == robot::kDefaultBodyModel
                ? ""
                : " with the body model " + std::string(robot::to_string(o_.sim.model))) +
           (o_.quick ? " (quick run: " + counted(ctx_.sizes.hexapod_runs, "learning run") +
                           " per scenario and " + std::to_string(ctx_.sizes.beta_runs) +
                           " per β, faster videos)"
                     : "") +
           ". The verdict table first: each claim of the paper, its number, ours, whether it "
           "reproduced (by the rule the claim states) and the section that shows it. Each "
           "section says what the paper reports and what we measured; every figure has its SVG "
           "and the CSV behind it. Tables of the experiments: results.md.";
  }

  static double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  void progress(const std::string& line) {
    if (!o_.progress) return;
    const std::lock_guard lock(progress_mutex_);
    std::cerr << "reproduce " << fixed(seconds_since(start_), 0) << " s: " << line << "\n";
  }

  // A folder made with other options is not resumed (the sections would not match).
  void check_arguments() const {
    const nlohmann::json args{
        {"quick", o_.quick}, {"seed", o_.seed}, {"model", o_.sim.model}, {"body", o_.sim.body}};
    const fs::path file = o_.out / "reproduce.json";
    if (fs::exists(file)) {
      nlohmann::json old;
      try {
        old = read_record(file, "a reproduce record");
      } catch (const nlohmann::json::exception&) {
        throw BadInput("'" + file.string() + "' is not a reproduce record");
      }
      if (old != args) {
        throw BadInput("'" + o_.out.string() + "' holds a reproduction made with other options (" +
                       old.dump() + "); use another --out");
      }
      return;
    }
    write_file_atomic(file, args.dump() + "\n");
  }

  void write_results_page() const {
    experiments::ResultsInputs in;
    in.hexapod = read_if_present("hexapod");
    in.quadruped = read_if_present("quadruped");
    in.beta = read_if_present("beta");
    if (!in.hexapod && !in.quadruped && !in.beta) return;
    in.command = "multicpg reproduce --out " + o_.out.string() + (o_.quick ? " --quick" : "") +
                 (o_.sim.model == robot::kDefaultBodyModel
                      ? ""
                      : " --model " + std::string(robot::to_string(o_.sim.model)));
    write_file_atomic(o_.out / "results.md", experiments::results_markdown(in));
  }

  std::optional<experiments::ExperimentTable> read_if_present(const std::string& name) const {
    const fs::path d = o_.out / "experiments" / name;
    if (!fs::exists(d / "summary.json")) return std::nullopt;
    return experiments::read_experiment(d);
  }

  ReproduceOptions o_;
  StageContext ctx_;
  std::chrono::steady_clock::time_point start_;
  std::vector<const Stage*> stages_;
  std::vector<Section> sections_;
  std::vector<bool> started_, done_;
  std::exception_ptr failure_;
  std::mutex mutex_, progress_mutex_;
  std::condition_variable changed_;
};

}  // namespace

std::string stage_of_figure(std::string_view figure) {
  const std::string_view name = figure_by_name(figure).name;  // BadInput for unknown names
  for (const Stage& s : reproduce_stages()) {
    for (std::string_view f : s.figures) {
      if (f == name) return std::string(s.id);
    }
  }
  // Stages.EveryFigureIsDrawnByExactlyOneStage keeps the registry and the table in step.
  throw std::logic_error("figure '" + std::string(name) + "' is drawn by no reproduce stage");
}

void reproduce(const ReproduceOptions& options) {
  for (const std::string& id : options.only) stage_by_id(id);  // BadInput for unknown ids
  Reproduction(options).run();
}

}  // namespace multicpg::report
