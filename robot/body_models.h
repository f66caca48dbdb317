// Named sets of body parameters (robot/body_params.h): the paper's simulator and the real AMOSII.
// One home for every model; `multicpg model --list` prints them with each value's source.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "robot/body_params.h"

namespace multicpg::robot {

enum class BodyModel {
  // The paper's simulator, lpzrobots AMOSII v2 (docs/robots.md): the default everywhere.
  paper_sim,
  // The real AMOSII of paper §5. For now its documented values (mass, trunk, the authors'
  // real-robot body lift,
  // lpzrobots' slip) over paper-sim: the starting point a calibration against Table 1 replaces.
  real,
};
inline constexpr std::array<BodyModel, 2> kBodyModels{BodyModel::paper_sim, BodyModel::real};
inline constexpr BodyModel kDefaultBodyModel = BodyModel::paper_sim;

std::string_view to_string(BodyModel model);  // "paper-sim", "real"
// Throws BadInput naming the known models.
BodyModel parse_body_model(std::string_view name);

// The model's parameters.
BodyParams body_params(BodyModel model);
// One line: what the model is.
std::string_view describe(BodyModel model);
// Where the model's value of a BodyParams key ("total_mass", "disabled_posture") comes from:
// a paper or docs/ section, or a measurement in docs/.
std::string_view value_source(BodyModel model, std::string_view key);
// The unit of a BodyParams key ("kg"; "" for none).
std::string_view value_unit(std::string_view key);
// Every BodyParams key, in the struct's order.
std::vector<std::string_view> parameter_keys();

}  // namespace multicpg::robot
