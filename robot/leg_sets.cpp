
#include "robot/leg_sets.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

#include "common/errors.h"

namespace multicpg::robot {
namespace {

// The items of `text` split at any of `separators`; an empty item is kept (and refused).
std::vector<std::string_view> split(std::string_view text, std::string_view separators) {
  std::vector<std::string_view> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find_first_of(separators, start);
    items.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) return items;
    start = end + 1;
  }
}

// The period `text` of `leg` (every leg when empty).
int parse_gait_period(std::string_view text, std::string_view leg) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) {
    throw BadInput("period '" + std::string(text) + "'" +
                   (leg.empty() ? "" : " of " + std::string(leg)) + " is not a whole number");
  }
  require_gait_period(value, leg);
  return value;
}

// Places along the body a leg's two-letter name gives.
constexpr int kNoPlace = -1;
constexpr int kFront = 0;
constexpr int kMiddle = 1;
constexpr int kHind = 2;
constexpr int kNoSide = -1;

// A letter of a leg's usual two-letter name ("RF", "LH", "FR"): its side (robot::Side's order),
// or its place along the body (front, middle, hind, back, rear); R is right or rear.
struct LegLetter {
  char letter;
  int side;
  int place;
};
constexpr std::array<LegLetter, 6> kLegLetters{{{'r', static_cast<int>(Side::right), kHind},
                                                {'l', static_cast<int>(Side::left), kNoPlace},
                                                {'f', kNoSide, kFront},
                                                {'m', kNoSide, kMiddle},
                                                {'h', kNoSide, kHind},
                                                {'b', kNoSide, kHind}}};

const LegLetter* leg_letter(char c) {
  const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const LegLetter& l : kLegLetters) {
    if (l.letter == lower) return &l;
  }
  return nullptr;
}

// "the right front leg": where `leg` is on the body (paper Fig. 1: R1 is the right front leg).
std::string leg_place(const Morphology& morph, std::size_t leg) {
  const Leg& l = morph.legs[leg];
  const int last = morph.legs_per_side - 1;
  const std::string side(kSideNames.name(l.side));
  if (l.position == 0) return "the " + side + " front leg";
  if (l.position == last) return "the " + side + " hind leg";
  if (morph.legs_per_side == 3) return "the " + side + " middle leg";
  return "the " + side + " leg number " + std::to_string(l.position + 1) + " from the front";
}

// The leg a name in another convention means: a case slip ("r1") or two letters for side and
// place ("RF", "FR", "LH", "RR" for right rear); none when it names none.
std::optional<std::size_t> meant_leg(const Morphology& morph, std::string_view name) {
  for (std::size_t i = 0; i < morph.size(); ++i) {
    const std::string& known = morph.legs[i].name;
    if (known.size() == name.size() &&
        std::equal(known.begin(), known.end(), name.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) ==
                 std::tolower(static_cast<unsigned char>(b));
        })) {
      return i;
    }
  }
  if (name.size() != 2) return std::nullopt;
  // The side is the letter that can only be a side (L), or the first of two that both can (R).
  const LegLetter* a = leg_letter(name[0]);
  const LegLetter* b = leg_letter(name[1]);
  if (a == nullptr || b == nullptr || (a->side == kNoSide && b->side == kNoSide)) {
    return std::nullopt;
  }
  const bool side_first = a->side != kNoSide && (b->side == kNoSide || b->place != kNoPlace);
  const int side = side_first ? a->side : b->side;
  const int place = side_first ? b->place : a->place;
  int position = kNoPlace;
  if (place == kFront) position = 0;
  if (place == kHind) position = morph.legs_per_side - 1;
  if (place == kMiddle && morph.legs_per_side == 3) position = 1;
  if (position == kNoPlace) return std::nullopt;
  for (std::size_t i = 0; i < morph.size(); ++i) {
    const Leg& l = morph.legs[i];
    if (static_cast<int>(l.side) == side && l.position == position) return i;
  }
  return std::nullopt;
}

}  // namespace

std::string gait_periods_text() {
  std::string out;
  for (int p : kGaitPeriods) out += (out.empty() ? "" : ", ") + std::to_string(p);
  return out;
}

bool is_gait_period(int period) {
  return std::find(kGaitPeriods.begin(), kGaitPeriods.end(), period) != kGaitPeriods.end();
}

std::string no_gait_message(int period, std::string_view leg) {
  return "period " + std::to_string(period) + (leg.empty() ? "" : " of " + std::string(leg)) +
         " gives no gait (allowed: " + gait_periods_text() + ")";
}

void require_gait_period(int period, std::string_view leg) {
  if (!is_gait_period(period)) throw BadInput(no_gait_message(period, leg));
}

std::size_t parse_leg(const Morphology& morph, std::string_view name) {
  for (std::size_t i = 0; i < morph.size(); ++i) {
    if (morph.legs[i].name == name) return i;
  }
  std::string names;
  for (const Leg& leg : morph.legs) names += (names.empty() ? "" : " ") + leg.name;
  const std::optional<std::size_t> meant = meant_leg(morph, name);
  throw BadInput(
      "the " + morph.name + " has no leg '" + std::string(name) + "'" +
      (meant ? " (did you mean " + morph.legs[*meant].name + ", " + leg_place(morph, *meant) + "?)"
             : "") +
      "; legs: " + names + " (R right, L left, numbered from the front)");
}

LegSet parse_leg_set(const Morphology& morph, std::string_view text) {
  LegSet out;
  if (text.empty()) return out;
  for (std::string_view item : split(text, ",+")) {
    if (item.empty()) throw BadInput("empty leg name in '" + std::string(text) + "'");
    const std::size_t leg = parse_leg(morph, item);
    if (std::find(out.begin(), out.end(), leg) != out.end()) {
      throw BadInput("leg " + std::string(item) + " is named twice in '" + std::string(text) + "'");
    }
    out.push_back(leg);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string leg_set_name(const Morphology& morph, const LegSet& legs) {
  std::string out;
  for (std::size_t leg : legs) out += (out.empty() ? "" : "+") + morph.legs.at(leg).name;
  return out;
}

std::vector<int> parse_period_map(const Morphology& morph, std::string_view text, int fallback) {
  if (text.find('=') == std::string_view::npos) {
    return std::vector<int>(morph.size(), parse_gait_period(text, {}));
  }
  std::vector<int> periods(morph.size(), fallback);
  std::vector<bool> named(morph.size(), false);
  for (std::string_view item : split(text, ", ")) {
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos) {
      throw BadInput("'" + std::string(item) + "' in '" + std::string(text) +
                     "' is not LEG=PERIOD");
    }
    const std::size_t leg = parse_leg(morph, item.substr(0, eq));
    if (named[leg]) {
      throw BadInput("leg " + morph.legs[leg].name + " is named twice in '" + std::string(text) +
                     "'");
    }
    named[leg] = true;
    periods[leg] = parse_gait_period(item.substr(eq + 1), morph.legs[leg].name);
  }
  return periods;
}

std::string period_map_text(const Morphology& morph, const std::vector<int>& periods,
                            const LegSet& skip) {
  std::string out;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    if (std::find(skip.begin(), skip.end(), i) != skip.end()) continue;
    out += (out.empty() ? "" : " ") + morph.legs.at(i).name + "=" + std::to_string(periods[i]);
  }
  return out;
}

nlohmann::json leg_set_json(const Morphology& morph, const LegSet& legs) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t leg : legs) out.push_back(morph.legs.at(leg).name);
  return out;
}

LegSet leg_set_from_json(const Morphology& morph, const nlohmann::json& j) {
  if (!j.is_array()) throw BadInput("a leg set must be an array of leg names");
  std::string text;
  for (const nlohmann::json& name : j) {
    if (!name.is_string()) throw BadInput("a leg set must be an array of leg names");
    if (!text.empty()) text += '+';
    text += name.get<std::string>();
  }
  return parse_leg_set(morph, text);
}

nlohmann::json period_map_json(const Morphology& morph, const std::vector<int>& periods) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < periods.size(); ++i) out[morph.legs.at(i).name] = periods[i];
  return out;
}

std::vector<int> period_map_from_json(const Morphology& morph, const nlohmann::json& j) {
  if (!j.is_object()) throw BadInput("a period map must be an object {\"R1\": 4, ...}");
  std::vector<int> periods(morph.size(), 0);
  for (std::size_t i = 0; i < morph.size(); ++i) {
    const auto it = j.find(morph.legs[i].name);
    if (it == j.end() || !it->is_number_integer()) {
      throw BadInput("the period map has no whole-number period for leg " + morph.legs[i].name);
    }
    periods[i] = it->get<int>();
  }
  if (j.size() != morph.size()) throw BadInput("the period map names legs the robot lacks");
  return periods;
}

namespace {

// The leg at the same place on the other side (itself for a leg on the body's axis).
std::size_t mirror_leg(const Morphology& morph, std::size_t leg) {
  const Leg& l = morph.legs[leg];
  for (std::size_t j = 0; j < morph.size(); ++j) {
    if (morph.legs[j].position == l.position && morph.legs[j].side != l.side) return j;
  }
  return leg;
}

}  // namespace

LegSet mirror(const Morphology& morph, const LegSet& legs) {
  LegSet out;
  for (std::size_t leg : legs) out.push_back(mirror_leg(morph, leg));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> mirror_periods(const Morphology& morph, const std::vector<int>& periods) {
  std::vector<int> out(periods.size());
  for (std::size_t leg = 0; leg < periods.size(); ++leg) out[mirror_leg(morph, leg)] = periods[leg];
  return out;
}

}  // namespace multicpg::robot
