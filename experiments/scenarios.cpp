#include "experiments/scenarios.h"

#include <algorithm>
#include <charconv>

#include "common/errors.h"
#include "robot/leg_sets.h"

namespace multicpg::experiments {
namespace {

using robot::Morphology;
using robot::Side;
using Legs = std::vector<std::size_t>;

std::size_t mirror_leg(const Morphology& morph, std::size_t leg) {
  const robot::Leg& l = morph.legs[leg];
  for (std::size_t j = 0; j < morph.size(); ++j) {
    if (morph.legs[j].position == l.position && morph.legs[j].side != l.side) return j;
  }
  return leg;
}

std::size_t right_legs(const Morphology& morph, const Legs& legs) {
  return static_cast<std::size_t>(std::count_if(
      legs.begin(), legs.end(), [&](std::size_t l) { return morph.legs[l].side == Side::right; }));
}

bool holds_whole_side(const Morphology& morph, const Legs& legs) {
  const std::size_t right = right_legs(morph, legs);
  const auto per_side = static_cast<std::size_t>(morph.legs_per_side);
  return right == per_side || legs.size() - right == per_side;
}

// The representative of {legs, mirror(legs)}: more right legs, then smaller indices.
bool is_representative(const Morphology& morph, const Legs& legs) {
  const Legs other = mirror(morph, legs);
  const std::size_t mine = right_legs(morph, legs);
  const std::size_t theirs = right_legs(morph, other);
  return mine > theirs || (mine == theirs && legs <= other);
}

}  // namespace

std::vector<std::size_t> mirror(const Morphology& morph, const std::vector<std::size_t>& legs) {
  Legs out;
  for (std::size_t leg : legs) out.push_back(mirror_leg(morph, leg));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> mirror_periods(const Morphology& morph, const std::vector<int>& periods) {
  std::vector<int> out(periods.size());
  for (std::size_t leg = 0; leg < periods.size(); ++leg) out[mirror_leg(morph, leg)] = periods[leg];
  return out;
}

std::vector<Scenario> leg_loss_scenarios(const Morphology& morph, std::size_t max_disabled) {
  std::vector<Legs> sets;
  const std::size_t n = morph.size();
  for (unsigned mask = 1; mask < (1U << n); ++mask) {
    Legs legs;
    for (std::size_t i = 0; i < n; ++i) {
      if (mask & (1U << i)) legs.push_back(i);
    }
    if (legs.size() <= max_disabled && !holds_whole_side(morph, legs)) sets.push_back(legs);
  }
  std::sort(sets.begin(), sets.end(), [](const Legs& a, const Legs& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  std::vector<Scenario> out;
  for (const Legs& legs : sets) out.push_back({robot::leg_set_name(morph, legs), legs});
  return out;
}

std::vector<Scenario> mirror_scenarios(const Morphology& morph, std::size_t max_disabled) {
  std::vector<Scenario> out = leg_loss_scenarios(morph, max_disabled);
  std::erase_if(out, [&](const Scenario& s) {
    return s.disabled.size() > 1 && !is_representative(morph, s.disabled);
  });
  return out;
}

std::vector<Scenario> paper_scenarios(robot::RobotKind kind) {
  const Morphology& morph = robot::morphology(kind);
  switch (kind) {
    case robot::RobotKind::hexapod: {
      constexpr std::size_t kMaxDisabled = 3;  // 1-3 disabled legs (paper Fig. 11)
      return mirror_scenarios(morph, kMaxDisabled);
    }
    case robot::RobotKind::quadruped: {
      std::vector<Scenario> out;
      for (std::size_t leg = 0; leg < morph.size(); ++leg)
        out.push_back({morph.legs[leg].name, {leg}});
      return out;
    }
    case robot::RobotKind::octopod:
      break;
  }
  throw BadInput("the paper reports no malfunction scenarios for the " + morph.name +
                 " (hexapod and quadruped only)");
}

Scenario beta_study_scenario() {
  const Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  const Legs legs{robot::leg_index(morph, "R1"), robot::leg_index(morph, "R2")};
  return {robot::leg_set_name(morph, legs), legs};
}

std::string format_number(double value) {
  char buf[32];  // the shortest form of any double needs at most 24
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}

}  // namespace multicpg::experiments
