// Leg sets ("R1+R3") and period maps ("R1=5 R2=4") as text and JSON: the one parser and
// formatter of each, used by the CLI, experiment files, records and the report alike.
#pragma once

#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::robot {

// Periods that give a gait (paper §2.1: 1 = stop, 4 tripod, 5 tetrapod, 6 transition, 8, 9 waves).
inline constexpr std::array<int, 6> kGaitPeriods{1, 4, 5, 6, 8, 9};
bool is_gait_period(int period);
// "period 7 gives no gait (allowed: 1, 4, 5, 6, 8, 9)", or "period 7 of R1 ..." with a leg: the
// one message for a period outside kGaitPeriods, wherever a period is given.
std::string no_gait_message(int period, std::string_view leg = {});
// Throws BadInput(no_gait_message(period, leg)) unless `period` gives a gait.
void require_gait_period(int period, std::string_view leg = {});
// The tripod (period 4): every leg's period unless told otherwise (paper Table 2 C0).
inline constexpr int kDefaultPeriod = 4;
std::string gait_periods_text();  // "1, 4, 5, 6, 8, 9"

// The index of the leg `name` ("R1"). Throws BadInput naming the legs otherwise, with the leg
// meant when the name is a case slip or another convention's: "the hexapod has no leg 'RF' (did
// you mean R1, the right front leg?); legs: R1 R2 R3 L1 L2 L3 (R right, L left, numbered from
// the front)".
std::size_t parse_leg(const Morphology& morph, std::string_view name);

// Legs as sorted indices into morphology(kind).legs.
using LegSet = std::vector<std::size_t>;

// "R1+R3" or "R1,R3" -> sorted indices; "" -> empty. Throws BadInput (one line) for an unknown
// leg, an empty item ("R1,", "R1++R3") or a leg named twice.
LegSet parse_leg_set(const Morphology& morph, std::string_view text);
// "R1+R3", in leg order; "" for no leg. parse_leg_set reads it back.
std::string leg_set_name(const Morphology& morph, const LegSet& legs);

// "4" (every leg) or "R1=5,R2=4" / "R1=5 R2=4" (legs not named keep `fallback`). Periods must
// give a gait (kGaitPeriods). Throws BadInput naming the item for an unknown leg, a leg named
// twice, an empty item, a period that is not a whole number or gives no gait.
std::vector<int> parse_period_map(const Morphology& morph, std::string_view text, int fallback);
// "R2=5 R3=4 L1=5": the periods of every leg not in `skip`, in leg order, as the paper lists a
// learned combination (Figs. 10, 11). parse_period_map reads it back.
std::string period_map_text(const Morphology& morph, const std::vector<int>& periods,
                            const LegSet& skip = {});

// The legs' left-right mirror images (R1 <-> L1, ...), sorted.
LegSet mirror(const Morphology& morph, const LegSet& legs);
// Periods per leg (morphology order) with each leg's period moved to its mirror image.
std::vector<int> mirror_periods(const Morphology& morph, const std::vector<int>& periods);

// JSON: a leg set is an array of names, a period map an object {"R1": 4, ...} of every leg.
nlohmann::json leg_set_json(const Morphology& morph, const LegSet& legs);
LegSet leg_set_from_json(const Morphology& morph, const nlohmann::json& j);  // throws BadInput
nlohmann::json period_map_json(const Morphology& morph, const std::vector<int>& periods);
// Every leg of `morph` must be named; throws BadInput otherwise.
std::vector<int> period_map_from_json(const Morphology& morph, const nlohmann::json& j);

}  // namespace multicpg::robot
