// The names of an enum's values: the one table an enum's to_string and parser go through, so a
// value gains its name in one place. Written by hand: nlohmann's NLOHMANN_JSON_SERIALIZE_ENUM
// covers JSON only (and reads an unknown name as the first value), and {fmt} does not read names
// back.
//
//   inline constexpr auto kJointNames =
//       enum_names<Joint>({{Joint::TC, "TC"}, {Joint::CTr, "CTr"}, {Joint::FTi, "FTi"}});
//   kJointNames.name(Joint::CTr)  -> "CTr"
//   kJointNames.find("FTi")       -> Joint::FTi (none for an unknown name)
//   kJointNames.list(" or ")      -> "TC, CTr or FTi"
//   kJointNames.names()           -> {"TC", "CTr", "FTi"}
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace multicpg {

template <class Enum, std::size_t N>
class EnumNames {
 public:
  using Entry = std::pair<Enum, std::string_view>;

  constexpr explicit EnumNames(const std::array<Entry, N>& entries) : entries_(entries) {}

  // The name of `value`; empty for a value the table lacks (every value of an enum is in its
  // table).
  constexpr std::string_view name(Enum value) const {
    for (const Entry& e : entries_) {
      if (e.first == value) return e.second;
    }
    return {};
  }

  // The value named `name`; none for an unknown name.
  constexpr std::optional<Enum> find(std::string_view name) const {
    for (const Entry& e : entries_) {
      if (e.second == name) return e.first;
    }
    return std::nullopt;
  }

  // Every name in the table's order, joined by ", " and `last` before the last one.
  std::string list(std::string_view last = ", ") const {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
      if (i > 0) out += i + 1 == N ? last : ", ";
      out += entries_[i].second;
    }
    return out;
  }

  // Every name in the table's order (for closest_name and unknown_name, common/user_text.h:
  // the "did you mean" of a mistyped name, case slips included).
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.emplace_back(e.second);
    return out;
  }

  // Every value in the table's order.
  constexpr std::array<Enum, N> values() const {
    std::array<Enum, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = entries_[i].first;
    return out;
  }

 private:
  std::array<Entry, N> entries_;
};

// The table of `entries` (value, name), N deduced from the list.
template <class Enum, std::size_t N>
constexpr EnumNames<Enum, N> enum_names(const std::pair<Enum, std::string_view> (&entries)[N]) {
  std::array<std::pair<Enum, std::string_view>, N> all{};
  for (std::size_t i = 0; i < N; ++i) all[i] = entries[i];
  return EnumNames<Enum, N>(all);
}

}  // namespace multicpg
