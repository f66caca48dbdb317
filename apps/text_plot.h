// Terminal pictures: gait diagrams (paper Fig. 2) and traces, for humans reading a terminal.
#pragma once

#include <string>
#include <vector>

namespace multicpg::apps {

// Rows = legs, columns = steps: '#' stance (paper Fig. 2: filled = support), '.' swing.
// Long records wrap into blocks of `width` steps, each block headed by its first step.
std::string gait_diagram(const std::vector<std::string>& legs,
                         const std::vector<std::vector<bool>>& swing, long first_step,
                         std::size_t width = 100);

// A value in [0, 1] per column drawn as `rows` lines of text (highest row first).
std::string strip_chart(const std::string& label, const std::vector<double>& values, int rows = 5);

}  // namespace multicpg::apps
