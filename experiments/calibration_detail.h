// What calibration.cpp shares with calibration_json.cpp and calibration_statistics.cpp; not API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "experiments/calibration.h"

namespace multicpg::experiments::calibration_detail {

// Column titles of candidates.csv that sensitivity() reads back.
inline constexpr const char* kFitPrefix = "fit ";
inline constexpr const char* kPaperPrefix = "paper's periods ";
inline constexpr const char* kMirrorPrefix = "mirror ";
inline constexpr const char* kIntactYawColumn = "intact_max_yaw_deg";
inline constexpr const char* kSpeedColumn = "intact_speed_cm_s";
inline constexpr const char* kScoreColumn = "score_deg";

// The mean of v; 0 when v is empty.
double mean(const std::vector<double>& v);

// A point of the normalised box (calibration.h body_at).
using Point = std::vector<double>;
// n points in d dimensions: of kDesignDraws Latin hypercubes drawn from `seed`, the one whose
// closest pair is farthest apart.
std::vector<Point> maximin_design(std::size_t n, std::size_t d, std::uint64_t seed);

// The numbers as the runner records them and candidates.json holds them.
nlohmann::json to_json(const std::vector<ScenarioNumbers>& scenarios);
nlohmann::json to_json(const CandidateNumbers& n);
CandidateNumbers numbers_from_json(const nlohmann::json& j);
nlohmann::json to_json(const SearchedParam& p);

}  // namespace multicpg::experiments::calibration_detail
