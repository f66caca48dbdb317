// Walking the alternatives of a std::variant of kinds (fault kinds, body/faults.h; terrain kinds,
// robot/terrain.h), each kind's traits being static members of its type.
#pragma once

#include <cstddef>
#include <utility>
#include <variant>

namespace multicpg {

namespace detail {
template <class Variant, class F, std::size_t... I>
void each_alternative(F& f, std::index_sequence<I...>) {
  (f(std::variant_alternative_t<I, Variant>{}), ...);
}
}  // namespace detail

// Calls `f` with a default-made value of each alternative of `Variant`, in order.
template <class Variant, class F>
void each_alternative(F&& f) {
  detail::each_alternative<Variant>(f, std::make_index_sequence<std::variant_size_v<Variant>>{});
}

}  // namespace multicpg
