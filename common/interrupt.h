// SIGINT and SIGTERM stop a long command cleanly (docs/cli.md "Exit codes and signals"): the
// handler only records the signal (async-signal-safe); the stepping loop (sim::Stepper), the
// runner's task loop and the waits for child processes look at it and throw Interrupted, which
// unwinds like any failure, so temporary files are removed by their owners and saved runs stay for
// a resume; main exits 128 + signal. A second signal ends the process at once (the default action
// is restored).
#pragma once

#include "common/errors.h"

namespace multicpg {

// Installs the handlers for SIGINT and SIGTERM (once, in main; libraries never do).
void install_interrupt_handlers();

// The signal that asked the process to stop, or 0.
int interrupt_signal();

// Asks the work in progress to stop as a signal would, and forgets the request once it has
// stopped: for the Python module, whose interpreter handles the signals itself.
void request_interrupt(int signal);
void clear_interrupt();

// Throws Interrupted if a signal asked the process to stop. Cheap (one relaxed atomic load):
// called every controller step.
void check_interrupted();

}  // namespace multicpg
