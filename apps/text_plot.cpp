#include "apps/text_plot.h"

#include <algorithm>
#include <sstream>

namespace multicpg::apps {

std::string gait_diagram(const std::vector<std::string>& legs,
                         const std::vector<std::vector<bool>>& swing, long first_step,
                         std::size_t width) {
  std::ostringstream out;
  for (std::size_t begin = 0; begin < swing.size(); begin += width) {
    const std::size_t end = std::min(swing.size(), begin + width);
    out << "step " << first_step + static_cast<long>(begin) << "\n";
    for (std::size_t leg = 0; leg < legs.size(); ++leg) {
      out << legs[leg] << " ";
      for (std::size_t t = begin; t < end; ++t) out << (swing[t][leg] ? '.' : '#');
      out << "\n";
    }
  }
  return out.str();
}

std::string strip_chart(const std::string& label, const std::vector<double>& values, int rows) {
  std::ostringstream out;
  out << label << "\n";
  for (int r = rows - 1; r >= 0; --r) {
    const double lo = static_cast<double>(r) / rows;
    out << (r == rows - 1 ? "1 |" : (r == 0 ? "0 |" : "  |"));
    for (double v : values) out << (v >= lo && (v < lo + 1.0 / rows || r == rows - 1) ? '*' : ' ');
    out << "\n";
  }
  return out.str();
}

}  // namespace multicpg::apps
