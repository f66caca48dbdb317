// Faults drawn in colour, the same in films, pictures and the viewer: a disabled leg red, as the
// paper draws it (Figs. 7, 11), and each other kind in its own colour on the part it strikes (a
// joint's segment, the tibia, the foot, the whole leg). A sensor fault has no part: captions name
// it.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <string>
#include <vector>

#include "body/faults.h"
#include "report/render.h"
#include "sim/sim.h"

namespace multicpg::report {

// The colour of a fault kind: leg red, locked orange, passive yellow, weak purple, short blue,
// slip cyan; the sensor kinds grey (drawn nowhere).
Rgba kind_colour(const body::Malfunction& kind);

// The geoms of `model`'s robot that the faults in force strike, each with its kind's colour.
Colouring fault_colours(const sim::SimModel& model, const body::FaultTimeline& in_force);

// The faults in force as a caption: "R1+R3, R2.CTr:locked, imu:drift=0.5", or "none".
std::string faults_caption(const robot::Morphology& morph, const body::FaultTimeline& in_force);

}  // namespace multicpg::report
