// The learner a run uses when it names none (docs/learning.md "Which learner a run uses").
#pragma once

#include "body/faults.h"
#include "learning/compensation.h"
#include "learning/learners.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// What the choice of a run's default learner depends on.
struct DefaultLearnerQuery {
  const CompensationOptions& options;  // its mode, steering, period learning and period set
  robot::RobotKind robot = robot::RobotKind::hexapod;
  bool robot_file = false;  // a robot file's body, not the AMOSII's the datasets were walked with
  bool beta_given = false;  // the run sets the annealing's beta: it asks for the annealing
  // The run's faults: the datasets hold leg losses, so a joint, motor, body or sensor fault
  // among them is a body they do not describe.
  const body::FaultTimeline& faults;
};

// Whether every fault of `faults` is a whole leg lost (or its recovery): the scenarios of a
// landscape dataset.
bool leg_losses_only(const body::FaultTimeline& faults);

// The prior where the repository has a landscape dataset of the run's robot walked as the run
// walks and of its period set (repository_dataset: the AMOSII hexapod's and quadruped's, with
// the reflex or without), in robust mode learning periods under leg losses: the learner the live
// tunnel check shows fastest (docs/learning.md "The default run in the tunnel"). The paper's
// annealing everywhere else: paper mode, a beta given, a robot file, the octopod, a fault other
// than a lost leg, a learner told nothing about the fault (the benchmark's price of not knowing
// is highest for the prior), no dataset installed. Resolved, every default filled in
// (resolve_learner).
LearnerChoice default_learner(const DefaultLearnerQuery& query);

}  // namespace multicpg::learning
