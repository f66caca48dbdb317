// Walking the alternatives of a std::variant of kinds (fault kinds, body/faults.h; terrain kinds,
// robot/terrain.h), each kind's traits being static members of its type; visiting one by kind.
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

// One visitor made of lambdas, one per alternative: std::visit(Overloaded{[](const A&) {...},
// [](const B&) {...}}, v).
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Spelled out: clang 14 (the sanitizer job's) does not deduce an aggregate's template arguments.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// Calls `f` with a default-made value of each alternative of `Variant`, in order.
template <class Variant, class F>
void each_alternative(F&& f) {
  detail::each_alternative<Variant>(f, std::make_index_sequence<std::variant_size_v<Variant>>{});
}

}  // namespace multicpg
