#include "sim/mujoco_guard.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <string_view>

#include "common/enum_names.h"

namespace multicpg::sim {
namespace {

// MuJoCo reports instability through mjData's warning counters, which sim_step checks; its
// default handler would also print to stdout and append to MUJOCO_LOG.TXT. Keep the last message
// of this thread for the error instead.
thread_local std::string last_warning;

void keep_warning(const char* message) {
  last_warning = message;
}

// MuJoCo's fatal errors (e.g. an offscreen buffer larger than OpenGL allows). The default handler
// prints to stdout, appends to MUJOCO_LOG.TXT and waits for Enter. mju_error must not return to
// MuJoCo (2.2.2 carries on with the broken state if the handler returns). Inside mujoco_call of a
// process that recovers (mujoco_guard.h) it jumps back there. Otherwise the ways to leave it
// early are unsound here: a C++ exception would unwind through MuJoCo's C frames (undefined
// behaviour, and its mjData stack would stay half-allocated); longjmp would skip the destructors
// of our C++ frames. So: one line on stderr, then _Exit(1). _Exit, not exit: other runner threads
// may still be simulating and must not see static destructors run. A temporary output file it
// leaves (*.tmp<pid>) is removed by the next experiment in that folder.
std::atomic<bool> recovering{false};

[[noreturn]] void fatal_error(const char* message) {
  if (MujocoJump* jump = armed_mujoco_jump(); jump != nullptr) {
    // Nothing with a destructor is made on this path (it is skipped by the jump).
    std::snprintf(jump->message.data(), jump->message.size(), "%s", message);
    std::longjmp(jump->buffer, 1);
  }
  std::string line = std::string("multicpg: MuJoCo error: ") + message;
  std::replace(line.begin(), line.end(), '\n', ' ');
  line += '\n';
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fflush(stderr);
  std::_Exit(1);
}

// MuJoCo's warnings (mjtWarning) as sim_step's errors name them.
constexpr auto kWarningNames = enum_names<int>({{mjWARN_INERTIA, "singular inertia"},
                                                {mjWARN_CONTACTFULL, "contact buffer full"},
                                                {mjWARN_CNSTRFULL, "constraint buffer full"},
                                                {mjWARN_VGEOMFULL, "visual geom buffer full"},
                                                {mjWARN_BADQPOS, "bad qpos"},
                                                {mjWARN_BADQVEL, "bad qvel"},
                                                {mjWARN_BADQACC, "bad qacc"},
                                                {mjWARN_BADCTRL, "bad ctrl"}});

}  // namespace

void install_mujoco_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = keep_warning;
    mju_user_error = fatal_error;
  });
}

std::string mujoco_warning(int warning) {
  const std::string_view name = kWarningNames.name(warning);
  return "MuJoCo warning '" + std::string(name.empty() ? "warning" : name) + "': " + last_warning;
}

void recover_mujoco_errors() {
  install_mujoco_handlers();
  recovering = true;
}

bool recovering_mujoco_errors() {
  return recovering;
}

MujocoJump*& armed_mujoco_jump() {
  thread_local MujocoJump* jump = nullptr;
  return jump;
}

}  // namespace multicpg::sim
