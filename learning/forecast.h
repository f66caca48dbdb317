// What a model-based learner's model expects of a combination (docs/learning.md "Inside the
// model"): each window output's mean and sd, the probability that a window holds and a window's
// E as the run's criterion makes it (learning/criterion.h). Each trial of such a learner records
// its combination's forecast, made before the trial's windows are told (TrialRecord::details).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "learning/search_bounds.h"

namespace multicpg::learning {

// Prediction of one output for one combination: mean and sd of its mean (without the noise).
struct Prediction {
  double mean = 0.0;
  double sd = 0.0;
};

// The share of a normal within one sd of its mean lies between these quantiles (Phi(-1) and
// Phi(1)): a window's E band, as "E ± sd" reads for a normal.
inline constexpr double kBandLowQuantile = 0.15865525393145707;
inline constexpr double kBandHighQuantile = 1.0 - kBandLowQuantile;
// A combination the model gives at least this chance of holding (Forecast::hold) is one it still
// believes may hold; under it the model has all but ruled it out (5 %, the conventional level of
// a test).
inline constexpr double kMayHoldLevel = 0.05;

// The combinations of a model's map a run keeps after its last trial (LearningResult::forecasts):
// the rows of its picture (report/figures.h, model_map_figure).
inline constexpr std::size_t kBestForecasts = 20;

struct Forecast {
  Periods periods;
  bool tried = false;  // walked already in this episode (the start counts)
  Prediction yaw;      // a window's signed yaw change, degrees
  Prediction path;     // its path angle, degrees
  Prediction effort;   // the reflex's effort in degrees of E (0 without the reflex)
  // The chance that it holds: every window of its trial under the threshold (each part of E), as
  // independent windows around its mean, then holding on after the trial (keep).
  double hold = 0.0;
  // The chance, from data beside the trials (the prior's), that it keeps holding once its trial
  // has held; 1 for a model without such data.
  double keep = 1.0;
  // One window's E with the window noise: its median and the band between kBandLowQuantile and
  // kBandHighQuantile.
  double e_deg = 0.0;
  double e_low_deg = 0.0;
  double e_high_deg = 0.0;
};

// The keys of a trial's forecast in its details (TrialRecord::details): the chosen combination's
// Forecast, the effort's only while the reflex steers; `may_hold` counts the untried
// combinations (the chosen one among them) of hold >= kMayHoldLevel, `untried` all of them.
inline constexpr std::string_view kPredictedYawKey = "predicted_yaw_deg";
inline constexpr std::string_view kPredictedYawSdKey = "predicted_yaw_sd_deg";
inline constexpr std::string_view kPredictedPathKey = "predicted_path_deg";
inline constexpr std::string_view kPredictedPathSdKey = "predicted_path_sd_deg";
inline constexpr std::string_view kPredictedEffortKey = "predicted_effort_deg";
inline constexpr std::string_view kPredictedEffortSdKey = "predicted_effort_sd_deg";
inline constexpr std::string_view kPredictedHoldKey = "predicted_hold";
inline constexpr std::string_view kPredictedKeepKey = "predicted_keep";
inline constexpr std::string_view kPredictedEKey = "predicted_e_deg";
inline constexpr std::string_view kPredictedELowKey = "predicted_e_low_deg";
inline constexpr std::string_view kPredictedEHighKey = "predicted_e_high_deg";
inline constexpr std::string_view kMayHoldKey = "may_hold";
inline constexpr std::string_view kUntriedKey = "untried";
inline constexpr std::array<std::string_view, 13> kForecastKeys{
    kPredictedYawKey,    kPredictedYawSdKey,    kPredictedPathKey,  kPredictedPathSdKey,
    kPredictedEffortKey, kPredictedEffortSdKey, kPredictedHoldKey,  kPredictedKeepKey,
    kPredictedEKey,      kPredictedELowKey,     kPredictedEHighKey, kMayHoldKey,
    kUntriedKey};

}  // namespace multicpg::learning
