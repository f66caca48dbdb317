// A run's checkpoint (sim::StepperCheckpoint) as a JSON document and back: what the Python
// module pickles, so a simulation can be saved, sent to another process and continued there
// bit for bit (in a simulation of an equal model).
//
// MuJoCo 2.2.2 has no mj_getState, so the document holds the mjData arrays a step reads before it
// writes them: time, qpos, qvel, act, qacc_warmstart (the constraint solver's warm start), ctrl,
// qfrc_applied, xfrc_applied, mocap_pos, mocap_quat, userdata, and the warning counters
// sim_step compares. It also holds sensordata, which mj_step computes before it integrates, so
// between steps it is one physics step old and the yaw and touch readings come from it (sim.h).
// Every other mjData array is an output that the next mj_step recomputes from these before
// anything reads it (positions, inertias, contacts, constraint rows), or scratch (the stack);
// restoring into a fresh mjData without mj_forward therefore continues exactly as the original.
// The arrays are stored as their bytes (doubles bit for bit, the host's byte order).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::sim {

// What a checkpoint belongs to: the checksum of everything its model is made from (the MJCF,
// the controller's parameters, the time steps and the servos). Equal robots with equal options
// give equal fingerprints.
std::string model_fingerprint(const SimModel& model);

nlohmann::json checkpoint_json(const SimModel& model, const StepperCheckpoint& checkpoint);

// Throws BadInput (one line, saying what is wrong) for a document of another format or version,
// of another model (model_fingerprint), with an array of the wrong size, a controller state
// `model` cannot be in (leg count, periods, delay lines, a failed leg that is not disabled) or
// faults that could not have happened.
StepperCheckpoint checkpoint_from_json(const SimModel& model, const nlohmann::json& document);

}  // namespace multicpg::sim
