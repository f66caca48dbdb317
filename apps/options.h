// Parsing and checks shared by the subcommands; each throws BadInput with one clear line.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::apps {

// Periods that give a gait (SPEC §1: 1 = stop, 4 tripod, 5 tetrapod, 6 transition, 8, 9 waves).
inline const std::set<int> kGaitPeriods{1, 4, 5, 6, 8, 9};

// Throws unless value > 0.
void require_positive(long value, const std::string& flag);
void require_positive(double value, const std::string& flag);

// Throws unless `period` is in 1-9 (what the CPG can be set to).
void require_cpg_period(int period, const std::string& flag);
// Throws unless `period` is a gait period, naming the allowed ones.
void require_gait_period(int period, const std::string& flag);

// A step number: a whole number in 0..sim::kMaxSteps, nothing else (no sign, no junk).
long parse_step(const std::string& text, const std::string& flag);

// "--periods 4" (every leg) or "--periods R1=5,R2=4" (unnamed legs keep `fallback`).
std::vector<int> parse_periods(const robot::Morphology& morph, const std::string& spec,
                               int fallback = 4);

}  // namespace multicpg::apps
