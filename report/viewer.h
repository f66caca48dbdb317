// The interactive viewer: a window showing the simulated robot walking in real time,
// the camera following the trunk, disabled legs red, with keys to pause, step, disable legs and
// switch synchronisation.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::report {

// Step numbers count controller steps from the start, as in sim::WalkSpec.
struct ViewerSpec {
  // Periods (as sim::walk: equal periods keep the clients synchronised, unequal ones free them)
  // and warm-up (default: a running, locked controller).
  body::StartSpec start;
  body::FaultTimeline faults;
  long steps = 0;  // quit after this many steps; 0 = when the user quits
};

// Opens a window on the display and runs until the user quits (Esc, Q, closing the window) or
// spec.steps are done; returns the number of controller steps taken. The spec must be valid
// (the CLI checks it). Throws BadInput with one line when there is no display,
// RuntimeFailure if OpenGL cannot be set up or the physics becomes unstable.
//
// Uses the window's GLX context: call it in a process that has not rendered headless (EGL or
// OSMesa), since MuJoCo binds to one GL platform per process.
long run_viewer(const sim::SimModel& model, const ViewerSpec& spec);

}  // namespace multicpg::report
