// Where two JSON records differ, as dotted key paths: what a refused resume or merge names.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace multicpg {

// The dotted path ("arguments.sim.servo_gain") of every leaf where `a` and `b` differ, in key
// order, below `path`; a key only one side has differs whole. Empty when they are equal.
std::vector<std::string> json_differences(const nlohmann::json& a, const nlohmann::json& b,
                                          const std::string& path = "");

}  // namespace multicpg
