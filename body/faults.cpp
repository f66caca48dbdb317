#include "body/faults.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/errors.h"
#include "common/variants.h"

namespace multicpg::body {
namespace {

template <class Kind>
concept HasValue = requires {
  Kind::kValue;
};

template <class Kind>
std::optional<double> value_of_kind(const Kind& k) {
  if constexpr (HasValue<Kind>) {
    return k.value;
  } else {
    return std::nullopt;
  }
}

}  // namespace

std::string_view kind_name(const Malfunction& kind) {
  return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::kName; }, kind);
}

Strikes strikes(const Malfunction& kind) {
  return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::kStrikes; }, kind);
}

std::optional<double> value_of(const Malfunction& kind) {
  return std::visit([](const auto& k) { return value_of_kind(k); }, kind);
}

std::string kind_names() {
  std::string names;
  each_alternative<Malfunction>([&](const auto& k) {
    if (!names.empty()) names += ", ";
    names += std::decay_t<decltype(k)>::kName;
  });
  return names;
}

Malfunction make_kind(std::string_view name, std::optional<double> value, bool value_optional) {
  std::optional<Malfunction> made;
  each_alternative<Malfunction>([&](const auto& k) {
    using Kind = std::decay_t<decltype(k)>;
    if (made || Kind::kName != name) return;
    if constexpr (HasValue<Kind>) {
      const ValueSpec& spec = Kind::kValue;
      if (!value) {
        if (spec.required && !value_optional) {
          throw BadInput(fmt::format("{} needs a value: {}={} (in {})", name, name, spec.name,
                                     spec.limits.text()));
        }
        made = Kind{};
        return;
      }
      if (!spec.limits.contains(*value)) {
        throw BadInput(fmt::format("{}: {} must be in {}{}{}, got {}", name, spec.name,
                                   spec.limits.text(), spec.unit.empty() ? "" : " ", spec.unit,
                                   *value));
      }
      Kind k;
      k.value = *value;
      made = k;
    } else {
      if (value) throw BadInput(fmt::format("{} takes no value, got {}={}", name, name, *value));
      made = Kind{};
    }
  });
  if (!made) {
    throw BadInput(fmt::format("unknown fault kind '{}' (known: {})", name, kind_names()));
  }
  return *made;
}

bool same_target(const Fault& a, const Fault& b) {
  if (a.kind.index() != b.kind.index()) return false;
  if (strikes(a.kind) == Strikes::sensor) return true;
  for (std::size_t leg : a.legs) {
    if (std::find(b.legs.begin(), b.legs.end(), leg) == b.legs.end()) continue;
    if (!a.joint || !b.joint || *a.joint == *b.joint) return true;
  }
  return false;
}

}  // namespace multicpg::body
