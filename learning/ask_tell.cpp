#include "learning/ask_tell.h"

#include <stdexcept>
#include <string>

#include "common/errors.h"
#include "common/limits.h"

namespace multicpg::learning {

namespace {

LearnerSetup learner_setup(const AskTellSetup& s) {
  const robot::Morphology& morph = robot::morphology(s.robot);
  LearnerSetup out;
  out.robot = s.robot;
  out.start = s.start.empty() ? Periods(morph.size(), kStartPeriod) : s.start;
  if (out.start.size() != morph.size()) {
    throw OptionError("start", "the " + morph.name + " takes " + std::to_string(morph.size()) +
                                   " periods, got " + std::to_string(out.start.size()));
  }
  for (std::size_t leg : s.told.failed()) {
    if (leg >= morph.size()) throw OptionError("told", "names a leg the " + morph.name + " lacks");
  }
  out.told = s.told;
  if (!s.start_windows.empty()) {
    out.start_deviation_deg = s.criterion.error(s.start_windows);
  } else if (s.start_deviation_deg) {
    out.start_deviation_deg = *s.start_deviation_deg;
  } else {
    throw OptionError("start_windows", "C0 needs what it measured: its windows or its E");
  }
  out.start_windows = s.start_windows;
  out.criterion = s.criterion;
  out.search = s.search;
  out.seed = s.seed;
  return out;
}

}  // namespace

AskTell::AskTell(const AskTellSetup& setup) : asked_setup_(setup), setup_(learner_setup(setup)) {
  within("learner", [&] { choice_ = resolve_learner(setup.learner); });
  within("search", [&] { validate(setup_.search); });
  within("learner", [&] {
    data_ = check_learner(choice_, setup_.robot, setup_.told, setup_.criterion,
                          setup_.search.period_set);
  });
  learner_ = make_learner(choice_, setup_, data_);
}

std::optional<Periods> AskTell::ask() {
  if (asked_) throw std::logic_error("ask(): the asked periods were not told yet (call tell)");
  if (done()) return std::nullopt;
  std::optional<Periods> next = learner_->propose();
  asked_ = next.has_value();
  return next;
}

void AskTell::next_episode(const Periods& start, const std::vector<body::WindowMeasure>& windows) {
  AskTellSetup next = asked_setup_;
  next.start = start;
  next.start_windows = windows;
  next.start_deviation_deg.reset();
  start_episode(std::move(next));
}

void AskTell::next_episode(const Periods& start, double deviation_deg) {
  AskTellSetup next = asked_setup_;
  next.start = start;
  next.start_windows.clear();
  next.start_deviation_deg = deviation_deg;
  start_episode(std::move(next));
}

void AskTell::start_episode(AskTellSetup next) {
  if (asked_) {
    throw std::logic_error("next_episode(): the asked periods were not told yet (call tell)");
  }
  // Episode k + 1 draws from its own stream, as a run's (learning/compensation.cpp).
  next.seed = asked_setup_.seed + static_cast<std::uint64_t>(episode_);
  LearnerSetup s = learner_setup(next);
  s.earlier = memory_;
  learner_ = make_learner(choice_, s, data_);
  setup_ = std::move(s);
  ++episode_;
}

TrialRecord AskTell::tell(const std::vector<body::WindowMeasure>& windows) {
  return record({setup_.criterion.error(windows), windows});
}

TrialRecord AskTell::tell(double deviation_deg) {
  return record({deviation_deg, {}});
}

TrialRecord AskTell::record(const Measurement& m) {
  if (!asked_) throw std::logic_error("tell(): no periods were asked (call ask first)");
  asked_ = false;
  trace_.push_back(learner_->observe(m));
  memory_.push_back({trace_.back().periods, m.windows});
  return trace_.back();
}

}  // namespace multicpg::learning
