#include "common/worker_threads.h"

#include <string>
#include <system_error>
#include <utility>

#include "common/errors.h"

namespace multicpg {

WorkerThreads::WorkerThreads(std::size_t count, std::function<void()> work)
    : work_(std::move(work)) {
  threads_.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    try {
      threads_.emplace_back([this] {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return start_ != Start::waiting; });
        const bool go = start_ == Start::go;
        lock.unlock();
        if (go) work_();
      });
    } catch (const std::system_error& e) {
      release(Start::cancelled);
      join();
      throw RuntimeFailure("cannot start thread " + std::to_string(i + 1) + " of " +
                           std::to_string(count) + " (" + e.code().message() +
                           "): ask for fewer jobs");
    }
  }
  release(Start::go);
}

WorkerThreads::~WorkerThreads() {
  release(Start::cancelled);  // no effect once they were let go
  join();
}

void WorkerThreads::release(Start start) {
  {
    const std::lock_guard lock(mutex_);
    if (start_ != Start::waiting) return;
    start_ = start;
  }
  changed_.notify_all();
}

void WorkerThreads::join() {
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
}

}  // namespace multicpg
