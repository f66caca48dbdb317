// Parsing and checks shared by the subcommands; each throws BadInput with one clear line.
#pragma once

#include <string>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::apps {

// Throws unless `period` is a gait period, naming the allowed ones.
void require_gait_period(int period, const std::string& flag);

// robot::parse_leg_set / parse_period_map with the flag named in the error ("--periods: ...").
std::vector<std::size_t> parse_leg_flag(const robot::Morphology& morph, const std::string& text,
                                        const std::string& flag);
std::vector<int> parse_periods_flag(const robot::Morphology& morph, const std::string& text,
                                    const std::string& flag);

}  // namespace multicpg::apps
