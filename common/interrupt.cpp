#include "common/interrupt.h"

#include <signal.h>

#include <atomic>

namespace multicpg {
namespace {

static_assert(SIGINT == 2 && SIGTERM == 15);  // Interrupted::message names them

// Lock-free, so the handler may store to it (async-signal-safe).
std::atomic<int> pending{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int signal) {
  int none = 0;
  pending.compare_exchange_strong(none, signal, std::memory_order_relaxed);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: system calls go on as if nothing happened (the work checks the flag);
  // SA_RESETHAND: a second signal takes its default action and ends the process at once.
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  for (int s : {SIGINT, SIGTERM}) ::sigaction(s, &action, nullptr);
}

void request_interrupt(int signal) {
  on_signal(signal);
}

void clear_interrupt() {
  pending.store(0, std::memory_order_relaxed);
}

int interrupt_signal() {
  return pending.load(std::memory_order_relaxed);
}

void check_interrupted() {
  if (const int s = pending.load(std::memory_order_relaxed); s != 0) throw Interrupted(s);
}

}  // namespace multicpg
