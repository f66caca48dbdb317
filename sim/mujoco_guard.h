// MuJoCo's warnings and fatal errors, kept away from stdout and MUJOCO_LOG.TXT; its fatal errors
// (mju_error) as exceptions in a process that asks for it.
//
// MuJoCo is C: its error handler must not return (2.2.2 carries on with the broken state) and a
// C++ exception must not unwind through its frames, so by default the handler ends the process
// (install_mujoco_handlers). A process that must survive a failed call (the Python
// module: one bad call must not end the interpreter) calls recover_mujoco_errors(). From then on a
// MuJoCo call made through mujoco_call runs under setjmp, and the handler longjmps back to it.
// That is sound because only MuJoCo's C frames and the handler lie between the two, none with a
// destructor (the C++ rule for longjmp); mujoco_call then throws RuntimeFailure, which unwinds
// our own frames as any exception does. What MuJoCo left half done is undone by the caller
// (sim_step resets the mjData stack, the renderer frees its context). A MuJoCo error outside
// mujoco_call, or in a process that did not ask, still ends the process with one line.
#pragma once

#include <array>
#include <csetjmp>
#include <string>

#include "common/errors.h"

namespace multicpg::sim {

// Routes MuJoCo's warnings (kept for sim_step's error) and fatal errors (one line on stderr,
// exit 1) away from stdout, MUJOCO_LOG.TXT and its "Press Enter" prompt. Idempotent;
// make_sim_model calls it, the CLI calls it first thing.
void install_mujoco_handlers();

// "MuJoCo warning 'bad qacc': <its last message on this thread>" for warning number `warning`
// (mjWARN_*), as sim_step reports it.
std::string mujoco_warning(int warning);

// Makes MuJoCo's fatal errors inside mujoco_call RuntimeFailures from now on (process-wide).
void recover_mujoco_errors();
bool recovering_mujoco_errors();

// Where the handler jumps to: one per mujoco_call in progress on this thread.
struct MujocoJump {
  std::jmp_buf buffer;
  MujocoJump* previous = nullptr;
  std::array<char, 512> message{};  // MuJoCo's text, cut to fit
};
MujocoJump*& armed_mujoco_jump();  // this thread's innermost, or null

// Runs `call` (one MuJoCo call, its captures trivially destructible). Throws RuntimeFailure
// ("MuJoCo error: ...") when MuJoCo reports a fatal error in it and recover_mujoco_errors() was
// called; otherwise such an error ends the process.
template <class Call>
void mujoco_call(const Call& call) {
  if (!recovering_mujoco_errors()) {
    call();
    return;
  }
  MujocoJump jump;
  jump.previous = armed_mujoco_jump();
  if (setjmp(jump.buffer) == 0) {
    armed_mujoco_jump() = &jump;
    call();
    armed_mujoco_jump() = jump.previous;
    return;
  }
  armed_mujoco_jump() = jump.previous;
  throw RuntimeFailure(std::string("MuJoCo error: ") + jump.message.data());
}

}  // namespace multicpg::sim
