#include "python/keywords.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace multicpg::python {
namespace {

// Edits (insertions, deletions, substitutions) between two names.
std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// A name this many edits away, or one third of its length, is a typing slip.
constexpr std::size_t kNearEdits = 2;
constexpr std::size_t kNearFraction = 3;

}  // namespace

std::string suggestion(std::string_view name, const std::vector<std::string>& known) {
  const std::string* best = nullptr;
  std::size_t best_distance = 0;
  for (const std::string& k : known) {
    const std::size_t d = distance(name, k);
    if (best == nullptr || d < best_distance) {
      best = &k;
      best_distance = d;
    }
  }
  const std::size_t near = std::max(kNearEdits, name.size() / kNearFraction);
  // A prefix ("max_trial" for "max_trials") is near too.
  const bool prefix = best != nullptr && best->starts_with(name) && name.size() >= 3;
  if (best == nullptr || (best_distance > near && !prefix)) return "";
  return "did you mean '" + *best + "'?";
}

py::object Keywords::operator[](std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return values_[i];
  }
  throw std::logic_error("no parameter " + std::string(name));  // a bug of this module
}

bool Keywords::given(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return given_[i];
  }
  throw std::logic_error("no parameter " + std::string(name));
}

std::vector<std::string> Keywords::given_of(const Params& params) const {
  std::vector<std::string> out;
  for (const Param& p : params) {
    if (given(p.name)) out.push_back(p.name);
  }
  return out;
}

Signature::Signature(std::string function, Params positional, Params keyword_only)
    : function_(std::move(function)), params_(std::move(positional)), positional_(params_.size()) {
  params_.insert(params_.end(), keyword_only.begin(), keyword_only.end());
}

Keywords Signature::read(const py::args& args, const py::kwargs& kwargs) const {
  Keywords k;
  for (const Param& p : params_) {
    k.names_.push_back(p.name);
    k.values_.push_back(p.fallback);
    k.given_.push_back(false);
  }
  if (args.size() > positional_) {
    throw py::type_error(function_ + "() takes " + std::to_string(positional_) +
                         " positional argument" + (positional_ == 1 ? "" : "s") + " but " +
                         std::to_string(args.size()) + " were given (the others are keywords)");
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    k.values_[i] = py::reinterpret_borrow<py::object>(args[i]);
    k.given_[i] = true;
  }
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    const auto at = std::find(k.names_.begin(), k.names_.end(), name);
    if (at == k.names_.end()) {
      const std::string hint = suggestion(name, k.names_);
      throw py::type_error(
          function_ + "(): no keyword '" + name + "'" +
          (hint.empty() ? " (help(" + function_ + ") lists them)" : " (" + hint + ")"));
    }
    const auto i = static_cast<std::size_t>(at - k.names_.begin());
    if (k.given_[i]) {
      throw py::type_error(function_ + "(): '" + name + "' is given twice");
    }
    k.values_[i] = py::reinterpret_borrow<py::object>(value);
    k.given_[i] = true;
  }
  return k;
}

std::string Signature::text(std::string_view name, std::string_view returns) const {
  const bool method = name == "__init__";
  std::string out = std::string(name) + (method ? "(self" : "(");
  for (std::size_t i = 0; i < params_.size(); ++i) {
    if (i > 0 || method) out += ", ";
    if (i == positional_) out += "*, ";
    out += params_[i].name + ": object = " + py::repr(params_[i].fallback).cast<std::string>();
  }
  out += ")";
  if (!returns.empty()) out += " -> " + std::string(returns);
  return out;
}

Params join(std::initializer_list<Params> parts) {
  Params out;
  for (const Params& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace multicpg::python
