// What a prior learns from its landscapes before any trial (learning/prior.cpp, docs/learning.md
// "Learners"): a ridge regression over the scenarios it may see of a window's mean yaw change,
// path angle and the reflex's effort on which legs are lost, each working leg's period, and each
// lost leg's effect on each working leg's period, mirrored scenarios included as data; from it
// the prior mean of every combination, the GP's scales (docs/learning.md "The prior's scales from
// its data") and each combination's chance of holding on after its trial ("Holding on after the
// trial").
#pragma once

#include <optional>
#include <vector>

#include "learning/additive_model.h"
#include "learning/landscapes.h"
#include "learning/learner.h"
#include "learning/search_space.h"

namespace multicpg::learning {

// How a prior learns from its scenarios, besides which they are.
struct PriorFit {
  double ridge = 1.0;  // weight decay of the regression, in windows
  // What a window of a loss of another number of legs than the one told counts for (told
  // nothing, every loss is another's: learning/prior.cpp fits it at 1 then).
  double other_size_weight = 1.0;
  bool scales = false;  // estimate the GP's scales from the data
  bool keeps = false;   // learn each combination's chance of holding on after its trial
};

// A prior's model before any trial, over the combinations of a search space.
struct PriorModel {
  std::vector<std::vector<double>> mean;      // [output][combination], AdditiveModel's prior mean
  std::optional<AdditiveModelParams> scales;  // with PriorFit::scales
  std::vector<double> keep;                   // [combination], with PriorFit::keeps
};

// What `scenarios` of `dataset` (those the prior may see) say of every combination of `space` for
// a run set up as `setup`: for the legs it is told failed, or, told nothing, for the features
// every scenario shares (each leg's period), no leg lost.
PriorModel fit_prior(const LandscapeDataset& dataset,
                     std::vector<const ScenarioLandscape*> scenarios, const LearnerSetup& setup,
                     const SearchSpace& space, const PriorFit& fit);

}  // namespace multicpg::learning
