#include "common/user_text.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace multicpg {
namespace {

constexpr char kDelete = 0x7f;
constexpr unsigned char kFirstPrintable = 0x20;
// A name is taken for a typo of another when at most this fraction of it differs.
constexpr std::size_t kTypoFraction = 3;

// Edit distance counting an insertion, deletion, substitution or swap of two neighbours as one
// (optimal string alignment), so "wlak" is one edit from "walk". Neither the standard library nor
// a Debian library of ours offers one.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

// `text` with A-Z as a-z: a case slip ("Paper", "--Mode") costs no edit.
std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  });
  return out;
}

}  // namespace

std::string printable(std::string_view text) {
  static constexpr std::array<char, 16> kHex{'0', '1', '2', '3', '4', '5', '6', '7',
                                             '8', '9', 'a', 'b', 'c', 'd', 'e', 'f'};
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= kFirstPrintable && c != kDelete) {
      out += c;
    } else if (c == '\0') {
      out += "\\0";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 0xf];
    }
  }
  return out;
}

std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& known,
                                        std::size_t min_edits) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max(min_edits, typed.size() / kTypoFraction) + 1;
  const std::string lower_typed = lower(typed);
  for (const std::string& name : known) {
    const std::size_t d = edit_distance(lower_typed, lower(name));
    if (d < best_distance) {
      best = name;
      best_distance = d;
    }
  }
  return best;
}

std::string unknown_name(std::string_view what, std::string_view typed,
                         const std::vector<std::string>& known) {
  const std::string head = "unknown " + std::string(what) + " '" + std::string(typed) + "'";
  if (const std::optional<std::string> near = closest_name(typed, known)) {
    return head + " (did you mean " + *near + "?)";
  }
  std::string names;
  for (std::size_t i = 0; i < known.size(); ++i) {
    if (i > 0) names += i + 1 == known.size() ? " or " : ", ";
    names += known[i];
  }
  return head + " (" + names + ")";
}

}  // namespace multicpg
