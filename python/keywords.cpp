#include "python/keywords.h"

#include <map>
#include <optional>
#include <stdexcept>

#include "common/user_text.h"
#include "python/typed.h"

namespace multicpg::python {
namespace {

// A keyword this many edits away (or a third of its length, if more) is a typing slip.
constexpr std::size_t kNearEdits = 2;
// A typed keyword at least this long that begins a known one ("max_trial") is near too.
constexpr std::size_t kPrefixLength = 3;

}  // namespace

std::string suggestion(std::string_view name, const std::vector<std::string>& known) {
  std::optional<std::string> near = closest_name(name, known, kNearEdits);
  if (!near && name.size() >= kPrefixLength) {
    for (const std::string& k : known) {
      if (k.starts_with(name) && (!near || k.size() < near->size())) near = k;
    }
  }
  return near ? "did you mean '" + *near + "'?" : "";
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

namespace {

// Each keyword's type as help() shows it (multicpg/_multicpg.pyi): one name means one thing in
// every call that takes it.
std::string param_type(std::string_view name) {
  static const std::map<std::string_view, std::string_view> types{
      {"robot", "Robot | str"},
      {"name", "str"},
      {"terrain", "Terrain | str | None"},
      {"periods", kPeriodsType},
      {"disable", kLegsType},
      {"disable_at", "int"},
      {"faults", kFaultsType},
      {"recoveries", kFaultsType},
      {"warmup", "int"},
      {"record", "bool"},
      {"seed", "int"},
      {"tunnel", "bool"},
      {"control_dt", "float"},
      {"physics_dt", "float | None"},
      {"servo_gain", "float | None"},
      {"model", "str"},
      {"body", "dict[str, Any] | None"},
      {"mode", "str"},
      {"learner", "str | None"},
      {"learner_options", "dict[str, Any] | None"},
      {"steering", "str"},
      {"hold_windows", "int"},
      {"monitor_windows", "int"},
      {"period_learning", "bool"},
      {"tell_fault", "bool"},
      {"beta", "float"},
      {"threshold", "float"},
      {"window", "int"},
      {"settle", "int | None"},
      {"max_trials", "int"},
      {"max_episodes", "int"},
      {"step_budget", "int"},
      {"observer", "Callable[[dict], Any] | None"},
      {"progress", kProgressType},
      {"hardware", "str | os.PathLike[str] | None"},
      {"lock_step", "bool"},
      {"learn", "bool"},
      {"max_steps", "int"},
      {"video", "str | os.PathLike[str] | None"},
      {"scale_tunnel", "bool"},
  };
  const auto it = types.find(name);
  return std::string(it == types.end() ? "Any" : it->second);
}

}  // namespace

std::string Signature::text(std::string_view name, std::string_view returns) const {
  const bool method = name == "__init__";
  std::string out = std::string(name) + (method ? "(self" : "(");
  for (std::size_t i = 0; i < params_.size(); ++i) {
    if (i > 0 || method) out += ", ";
    if (i == positional_) out += "*, ";
    out += params_[i].name + ": " + param_type(params_[i].name) + " = " +
           py::repr(params_[i].fallback).cast<std::string>();
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
