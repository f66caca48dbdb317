// Calibration of the body against the real robot (docs/fidelity.md): a search over the body
// parameters (robot/body_params.h), inside their documented ranges, for the body whose tunnel
// runs come closest to paper §5 Table 1's before-learning column (42°, 21°, 23° to the right).
// Every candidate is one task of the runner (experiments/runner.h: parallel, resumable,
// checksummed); the search is a seeded space-filling design (a maximin Latin hypercube) and
// then a compass search on the normalised box around the best candidate. The paper's own
// periods and the mirrored scenarios are walked for every candidate too, as checks the score
// never sees.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/limits.h"
#include "common/table.h"
#include "experiments/run_robot.h"
#include "robot/body_params.h"
#include "robot/morphology.h"
#include "sim/sim.h"

namespace multicpg::experiments {

// One body parameter searched (a key of robot::number_params) and the interval searched, inside
// the parameter's documented range; log_scale: searched evenly in log(value).
struct SearchedParam {
  std::string key;
  double lo = 0.0;
  double hi = 0.0;
  bool log_scale = false;
};

// What the candidates are scored against. table1: paper §5 Table 1, before learning (paper.h).
enum class CalibrationTarget { table1 };
std::string_view to_string(CalibrationTarget target);
CalibrationTarget parse_calibration_target(std::string_view text);  // BadInput naming choices

// Candidates a calibration may walk: at least a design of two, at most a few days of CPU.
inline constexpr Limits<int> kCalibrationBudgetLimits{2, 100'000};
inline constexpr int kDefaultCalibrationBudget = 600;
// Share of the budget the space-filling design takes; the compass search has the rest.
inline constexpr double kDesignShare = 0.6;
// Compass search on the normalised box: first step, and the step below which it stops.
inline constexpr double kCompassFirstStep = 0.25;
inline constexpr double kCompassLastStep = 1.0 / 64.0;
// Maximin Latin hypercube: designs drawn, the one whose closest pair is farthest apart kept.
inline constexpr int kDesignDraws = 20;

// The intact robot must walk straight: every 400-step window after settling turns under 3°
// (the probe's measure, docs/fidelity.md: 800 settling steps, then 3 windows).
inline constexpr double kIntactStraightDeg = 3.0;
inline constexpr long kIntactSettleSteps = 800;
inline constexpr long kIntactSteps = 1200;
// The intact tripod's speed must be one a position-servo hexapod walks (docs/fidelity.md
// "Calibration"): at least half the paper's simulator's 7.85 cm/s, at most the fastest the
// tripod walks at any setting of the probe (9.97 cm/s at foot friction 0.4), rounded up.
inline constexpr Limits<double> kPlausibleSpeedMS{0.04, 0.10};
// Perturbed starts: the tunnel runs and the intact walk are scored as the mean over these
// controller warm-ups (body::kControllerWarmup and half a tripod cycle of 36 steps later, so the
// other tripod leads), so that a
// candidate is not chosen for the ~2° a single deterministic run varies with irrelevant changes.
inline const std::vector<long> kDefaultCalibrationWarmups{1000, 1018};
inline constexpr Limits<long> kCalibrationWarmupLimits{0, 100'000};
// Steps a candidate's tunnel walk may take before it is stopped where it is (neither passed nor
// at a wall; its angle is that of its displacement so far). The real robot's before-learning
// runs ended at a wall after a path of 0.7-1.3 m: 3,000 steps cover that at 1.2 cm/s, a third of
// the slowest plausible tripod, so no candidate near the target is cut. The paper's periods must
// cross the whole 3 m: 6,000 steps are 3 m at 1.35 cm/s, about the slow wave gait's pace. Beyond
// these a body stalls or circles (turns of 90° and more), and would cost up to 12,000 steps.
inline constexpr long kCalibrationFitSteps = 3000;
// A fitted run that reaches no wall within kCalibrationFitSteps counts this much against the
// candidate's constraints (as 1° of intact yaw over its bound): the real robot's runs all ended at
// the wall, so a body that stalls short of it does not fail like the real one, whatever its
// angle so far (docs/fidelity.md "Calibration").
inline constexpr double kStalledRunViolation = 1.0;
inline constexpr long kCalibrationCheckSteps = 6000;

struct CalibrationSpec {
  CalibrationTarget target = CalibrationTarget::table1;
  // The hexapod, built in (Table 1 is its). Its options hold the body's unsearched values (and
  // the time steps): every candidate is this body with the searched parameters set.
  RobotSpec robot;
  std::vector<SearchedParam> params;
  int budget = kDefaultCalibrationBudget;
  std::uint64_t seed = 1;
  std::vector<long> warmups = kDefaultCalibrationWarmups;
};

// The parameters the probe (docs/fidelity.md) showed to move Table 1, over the intervals a real
// AMOSII could have: the dead-leg posture (each joint), slip (log scale), foot friction, joint
// compliance and servo torque. The masses and the body lift are measured (the `real` model).
std::vector<SearchedParam> default_searched_params();

// Throws OptionError naming the key ("params[2].hi", "budget", "warmups[1]", "sim.body.slip")
// for a parameter that is not a number of the body, named twice, or an interval outside its
// documented range or empty; a robot other than the built-in hexapod (Table 1 is its).
void validate(const CalibrationSpec& spec);

// The body of a point of the normalised box (u in [0, 1] per searched parameter).
robot::BodyParams body_at(const CalibrationSpec& spec, const std::vector<double>& u);

// One tunnel walk of a candidate.
struct TunnelNumbers {
  double deviation_deg = 0.0;  // + = left (Table 1's angle)
  bool passed = false;
  bool touched_wall = false;
  long steps = 0;
  double forward_m = 0.0;
  double lateral_m = 0.0;
};

// One scenario of a candidate, walked from every start.
struct ScenarioNumbers {
  std::string name;     // "R1+R3"
  std::string periods;  // "all 4" or "R2=4 L1=6 L2=4 L3=9"
  std::vector<TunnelNumbers> starts;
  double mean_deg() const;
  int passed() const;
};

struct CandidateNumbers {
  // Empty when the body could not be walked (a physics blow-up): the candidate ranks last.
  std::string failure;
  std::vector<ScenarioNumbers> fit;            // Table 1's scenarios, all periods 4 (scored)
  std::vector<ScenarioNumbers> paper_periods;  // with the paper's periods (unseen check)
  std::vector<ScenarioNumbers> mirrors;        // the fit's mirror images, all 4 (unseen check)
  std::vector<double> intact_yaw_deg;          // every window of every start
  std::vector<double> intact_speed_m_s;        // per start
  double intact_max_yaw_deg() const;
  double intact_mean_speed_m_s() const;
  // RMS over the scenarios of (mean deviation - the real robot's), degrees.
  double score_deg = 0.0;
  // How far the constraints are missed: degrees of intact yaw over kIntactStraightDeg, cm/s of
  // speed outside kPlausibleSpeedMS and kStalledRunViolation per fitted run short of a wall;
  // 0 = feasible.
  double violation = 0.0;
  bool feasible() const { return failure.empty() && violation == 0.0; }
};

// Walks every scenario of a candidate body from every start and scores it.
CandidateNumbers measure_candidate(const CalibrationSpec& spec, const robot::BodyParams& body);

// a ranks before b: walked before failed, feasible before not, less violation, then less score.
bool better(const CandidateNumbers& a, const CandidateNumbers& b);

struct Candidate {
  std::string id;     // "d0007" (design) or "r03-05" (compass round 3, point 5)
  std::string stage;  // "design" or "refine-03"
  std::vector<double> u;
  robot::BodyParams body;
  CandidateNumbers numbers;
};

struct Calibration {
  CalibrationSpec spec;
  std::vector<Candidate> candidates;  // in the order walked
  std::size_t best = 0;               // index of the best (better())
  int loaded = 0;                     // candidates found saved in OUT
  int ran = 0;                        // walked now
};

// Runs the search in OUT: OUT/design and one directory per compass round, each a runner
// experiment (resumable; a resume with another spec is refused naming the key), then writes
// OUT/candidates.csv, OUT/candidates.json (calibration_json) and OUT/summary.json.
Calibration run_calibration(const CalibrationSpec& spec, const std::filesystem::path& out, int jobs,
                            bool progress);

// What every stage's runner records (and a resume must match).
nlohmann::json calibration_arguments(const CalibrationSpec& spec);

// OUT/candidates.json: the spec, every candidate (id, stage, u, each searched value, the whole
// body and all its numbers) and the best's id. read_calibration reads it back (BadInput naming
// the file when it is not one).
nlohmann::json calibration_json(const Calibration& calibration);
Calibration read_calibration(const std::filesystem::path& candidates_json);
// candidates.csv: one row per candidate: id, stage, each searched parameter, then for each
// scenario ("fit R1", "paper's periods R1", "mirror L1") its mean deviation, each start's and
// how many starts passed; intact_max_yaw_deg, intact_speed_cm_s, score_deg, violation, feasible
// (1/0), failure.
Table candidates_table(const Calibration& calibration);

// Which parameter moves which number: Spearman's rank correlation, over the design's walked
// candidates (the space-filling part: the compass rounds cluster), of each searched parameter
// with each number ("R1", ..., "score", "intact yaw", "speed", "R1 paper's"). Read from a
// candidates table (candidates_table, or candidates.csv read back), so that saved calibration
// data draw the same figure.
struct Sensitivity {
  std::vector<std::string> params;
  std::vector<std::string> numbers;
  std::vector<std::vector<double>> rho;  // [param][number]
  std::size_t candidates = 0;
};
Sensitivity sensitivity(const Table& candidates);

}  // namespace multicpg::experiments
