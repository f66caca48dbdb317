#include "apps/options.h"

#include <charconv>

#include "common/errors.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

std::string allowed_periods() {
  std::string out;
  for (int p : kGaitPeriods) out += (out.empty() ? "" : ", ") + std::to_string(p);
  return out;
}

int parse_int(const std::string& text, const std::string& what) {
  int value = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty()) {
    throw BadInput(what + ": '" + text + "' is not a whole number");
  }
  return value;
}

}  // namespace

void require_positive(long value, const std::string& flag) {
  if (value <= 0) throw BadInput(flag + " must be positive, got " + std::to_string(value));
}

void require_positive(double value, const std::string& flag) {
  if (!(value > 0.0)) throw BadInput(flag + " must be positive, got " + std::to_string(value));
}

void require_cpg_period(int period, const std::string& flag) {
  if (period < 1 || period > 9) {
    throw BadInput(flag + ": period " + std::to_string(period) + " is outside 1-9");
  }
}

void require_gait_period(int period, const std::string& flag) {
  if (!kGaitPeriods.contains(period)) {
    throw BadInput(flag + ": period " + std::to_string(period) +
                   " gives no gait (allowed: " + allowed_periods() + ")");
  }
}

std::vector<int> parse_periods(const robot::Morphology& morph, const std::string& spec,
                               int fallback) {
  std::vector<int> periods(morph.size(), fallback);
  if (spec.find('=') == std::string::npos) {
    const int p = parse_int(spec, "--periods");
    require_gait_period(p, "--periods");
    periods.assign(morph.size(), p);
    return periods;
  }
  std::size_t start = 0;
  while (start < spec.size()) {
    std::size_t comma = spec.find(',', start);
    if (comma == std::string::npos) comma = spec.size();
    const std::string item = spec.substr(start, comma - start);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) {
      throw BadInput("--periods: '" + item + "' is not LEG=PERIOD");
    }
    const std::size_t leg = robot::leg_index(morph, item.substr(0, eq));
    const int p = parse_int(item.substr(eq + 1), "--periods " + item.substr(0, eq));
    require_gait_period(p, "--periods " + item.substr(0, eq));
    periods[leg] = p;
    start = comma + 1;
  }
  return periods;
}

long parse_step(const std::string& text, const std::string& flag) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < 0 || value > sim::kMaxSteps) {
    throw BadInput(flag + ": '" + text + "' is not a step in 0.." + std::to_string(sim::kMaxSteps));
  }
  return value;
}

}  // namespace multicpg::apps
