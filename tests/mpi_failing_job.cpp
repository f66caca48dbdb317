// A job for test_mpi that fails on purpose, on a process other than the primary, in one of two
// places, to check that every process ends and exactly one line is printed:
//   mpi_failing_job OUT in-run      every run fails on the processes other than the primary
//   mpi_failing_job OUT before-run  process 1 fails before it reaches run_tasks
#include <chrono>
#include <exception>
#include <string>
#include <thread>

#include "common/errors.h"
#include "experiments/processes.h"
#include "experiments/runner.h"

namespace {

using namespace multicpg;
using namespace multicpg::experiments;

constexpr int kRuns = 12;
// Long enough that every process asks for runs before the primary's threads take them all.
constexpr auto kRunTime = std::chrono::milliseconds(50);

void job(const std::string& out, const std::string& where) {
  if (where == "before-run" && process_rank() == 1) throw BadInput("process 1 cannot start");
  RunnerOptions options;
  options.jobs = 1;
  options.out_dir = out;
  options.progress = false;
  std::vector<Task> tasks;
  for (int i = 0; i < kRuns; ++i) tasks.push_back({run_key("fail", i), "fail", i, 0, {}});
  run_tasks(
      tasks,
      [&](const Task& task) {
        std::this_thread::sleep_for(kRunTime);
        if (where == "in-run" && !is_primary_process()) {
          throw RuntimeFailure(task.key + " failed on process " + std::to_string(process_rank()));
        }
        return nlohmann::json{{"key", task.key}};
      },
      options);
}

}  // namespace

int main(int argc, char** argv) {
  ProcessGroup processes(argc, argv);
  if (argc != 3) return processes.finish({2, "usage: mpi_failing_job OUT in-run|before-run"});
  try {
    job(argv[1], argv[2]);
  } catch (const BadInput& e) {
    return processes.finish({2, std::string("mpi_failing_job: ") + e.what()});
  } catch (const FailedElsewhere& e) {
    return processes.finish({e.code(), ""});
  } catch (const std::exception& e) {
    return processes.finish({1, std::string("mpi_failing_job: ") + e.what()});
  }
  return processes.finish({});
}
