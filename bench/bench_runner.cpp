// The experiment runner's cost per run, apart from the runs' own work: TASKS runs that
// each sleep SLEEP_MS (no CPU, so other load on the machine barely matters) and return a result
// of a learning run's size, on JOBS threads, in one process or under mpirun. Ideal wall time:
// TASKS x SLEEP_MS / (threads in all processes); the rest is the runner (saving each run, and
// under MPI the messages). Usage: bench_runner TASKS SLEEP_MS JOBS OUT_DIR
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <thread>

#include "experiments/processes.h"
#include "experiments/runner.h"

namespace {

using namespace multicpg::experiments;

// Bytes of text in a result, about a paper-mode learning run's (its run file is ~2 KB).
constexpr std::size_t kResultBytes = 1500;

void bench(char** argv) {
  const int count = std::atoi(argv[1]);
  const auto sleep = std::chrono::milliseconds(std::atoi(argv[2]));
  RunnerOptions options;
  options.jobs = std::atoi(argv[3]);
  options.out_dir = argv[4];
  options.progress = false;
  std::vector<Task> tasks;
  for (int i = 0; i < count; ++i) tasks.push_back({run_key("bench", i), "bench", i, 0, {}});
  if (is_primary_process()) std::filesystem::remove_all(options.out_dir);

  const auto start = std::chrono::steady_clock::now();
  run_tasks(
      tasks,
      [&](const Task& task) {
        std::this_thread::sleep_for(sleep);
        return nlohmann::json{{"key", task.key}, {"padding", std::string(kResultBytes, 'x')}};
      },
      options);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!is_primary_process()) return;
  const int slots = options.jobs * process_count();
  const double ideal = static_cast<double>(count) * std::chrono::duration<double>(sleep).count() /
                       static_cast<double>(slots);
  std::printf(
      "%d runs of %lld ms, %d process(es) x %d thread(s): %.3f s (ideal %.3f s), overhead "
      "%.2f ms per run per thread\n",
      count, static_cast<long long>(sleep.count()), process_count(), options.jobs, wall, ideal,
      1000.0 * (wall - ideal) * static_cast<double>(slots) / static_cast<double>(count));
}

}  // namespace

int main(int argc, char** argv) {
  ProcessGroup processes(argc, argv);
  if (argc != 5) return processes.finish({2, "usage: bench_runner TASKS SLEEP_MS JOBS OUT_DIR"});
  try {
    bench(argv);
  } catch (const std::exception& e) {
    return processes.finish({1, std::string("bench_runner: ") + e.what()});
  }
  return processes.finish({});
}
