// The learning options set by a name or by a switch, declared once as the numeric ones are
// (learning/number_options.h): each one's name (the CLI's --FLAG, Python's keyword with '_' for
// '-'), its key in a run's record and an experiment file's [learning] (learning/json.h, whose type
// macros name the same members; tests/test_compensation.cpp checks that they do), whether robust
// mode alone has it, its help text, and how it reads and writes CompensationOptions. The CLI's
// flags (apps/learning_options.cpp) and Python's keywords (python/run_args.cpp) are made from
// these tables. The learner, the annealing's beta and the seed are not here: the learner's
// default depends on the run (learning/default_learner.h), beta is the annealing's option
// (learning/learners.h), and the seed is each run's (experiment files derive it).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "learning/compensation.h"

namespace multicpg::learning {

// An option that takes one of a few names.
struct NameOption {
  std::string_view flag;                // "mode": --mode, Python's mode
  std::string_view key;                 // its key in a record: "mode"
  std::string_view help;                // what --help says of it
  bool robust_only;                     // robust mode's alone: paper mode refuses it
  std::vector<std::string> (*names)();  // the names it takes, the default first
  void (*set)(CompensationOptions&, std::string_view);  // throws BadInput naming the names
  std::string_view (*get)(const CompensationOptions&);
};

// In the order --help lists them.
inline const std::array<NameOption, 2> kLearningNames{
    NameOption{"mode", "mode",
               "robust (yaw and path angle, several windows to accept, monitoring, steering) or "
               "paper (paper §3 exactly: one window, yaw only)",
               false,
               [] {
                 return std::vector<std::string>{std::string(to_string(Mode::robust)),
                                                 std::string(to_string(Mode::paper))};
               },
               [](CompensationOptions& o, std::string_view text) { o.mode = parse_mode(text); },
               [](const CompensationOptions& o) { return to_string(o.mode); }},
    NameOption{
        "steering", "steering",
        "robust mode: reflex (orientation reflex on the VRN steering inputs) or off", true,
        [] {
          return std::vector<std::string>{std::string(to_string(Steering::reflex)),
                                          std::string(to_string(Steering::off))};
        },
        [](CompensationOptions& o, std::string_view text) { o.steering = parse_steering(text); },
        [](const CompensationOptions& o) { return to_string(o.steering); }},
};

// An option on by default and switched off: the CLI's --no-FLAG, Python's keyword a bool.
struct SwitchOption {
  std::string_view flag;  // "period-learning": --no-period-learning, Python's period_learning
  std::string_view key;   // its key in a record: "learn_periods"
  std::string_view help;  // what --help says of --no-FLAG
  bool robust_only;
  bool& (*field)(CompensationOptions&);
};

inline const std::array<SwitchOption, 2> kLearningSwitches{
    SwitchOption{"period-learning", "learn_periods",
                 "robust mode: keep the periods, compensate by steering alone", true,
                 [](CompensationOptions& o) -> bool& { return o.learn_periods; }},
    SwitchOption{"tell-fault", "tell_fault",
                 "tell the learner nothing about the fault: it searches every leg's period, the "
                 "failed legs' too (the price of not knowing; docs/learning.md \"What a learner "
                 "is told\")",
                 false, [](CompensationOptions& o) -> bool& { return o.tell_fault; }},
};

}  // namespace multicpg::learning
