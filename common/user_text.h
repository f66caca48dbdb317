// Text the user typed (flag values, file keys, names), as error messages show it, and the
// "did you mean" of a mistyped name.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace multicpg {

// `text` with every control character escaped (NUL as \0, newline \n, tab \t, ESC \x1b, ...), so
// a message stays one line that a terminal shows as written and a NUL cannot cut it short.
// Printable text, a backslash included, is kept as it is: escaping twice changes nothing.
std::string printable(std::string_view text);

// The name of `known` closest to `typed` by edit distance, if it is close enough to be what the
// user meant (at most a third of its length, and at least `min_edits`, apart); ties go to the
// first. Case does not count: "Paper" is "paper" mistyped.
std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& known,
                                        std::size_t min_edits = 1);

// "unknown WHAT 'TYPED' (did you mean NAME?)" for the name of `known` nearest `typed`
// (closest_name), else "unknown WHAT 'TYPED' (NAMES)", the names joined by ", " and " or ".
std::string unknown_name(std::string_view what, std::string_view typed,
                         const std::vector<std::string>& known);

}  // namespace multicpg
