// Threads that run one piece of work side by side (the runner's, the learner benchmark's,
// reproduce's stages), started all or none: a thread the system refuses (an address-space or
// process limit, `--jobs 4096` under `ulimit -v`) is one line, never std::terminate on threads
// left joinable.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace multicpg {

class WorkerThreads {
 public:
  // Starts `count` threads that each run `work` once. The threads wait until all are started;
  // when one cannot be, those started end without running `work` and RuntimeFailure says how
  // many the system gave ("cannot start thread 38 of 4096 (Resource temporarily unavailable):
  // ask for fewer jobs"). `work` must not throw (each caller keeps its first failure itself).
  WorkerThreads(std::size_t count, std::function<void()> work);
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;
  ~WorkerThreads();  // joins

  // Waits until every thread has run `work`.
  void join();

 private:
  enum class Start { waiting, go, cancelled };

  void release(Start start);

  std::function<void()> work_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable changed_;
  Start start_ = Start::waiting;
};

}  // namespace multicpg
