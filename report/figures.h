// The paper's figures, drawn by gnuplot from a CSV written next to each picture.
// Each plot_* call writes <out_dir>/<stem>.csv, .png (pngcairo) and .svg and returns the paths;
// the data come in as plain values so this layer depends on no simulation code.
// Errors: BadInput (one line) for unusable data or an unwritable out_dir, RuntimeFailure (one
// line, gnuplot's error) when gnuplot fails or leaves no output; the CSV, already whole, stays
// for inspection and no partial picture is left.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace multicpg::report {

struct FigureFiles {
  std::filesystem::path png;
  std::filesystem::path svg;
  std::filesystem::path csv;
};

// A figure this layer draws: its lookup name, default file stem, gnuplot script, pixel size and
// a caption for listings and the HTML report.
struct FigureInfo {
  std::string_view name;
  std::string_view stem;
  std::string_view script;
  int width;
  int height;
  std::string_view caption;
};

std::span<const FigureInfo> known_figures();
// Throws BadInput naming the known figures when `name` is not one of them.
const FigureInfo& figure_by_name(std::string_view name);

// Fig. 2: one gait diagram per period; swing[step][leg], true = swing (white), false = stance
// (blue, the paper's colours). Legs are drawn top to bottom in the order given.
struct GaitPanel {
  int period;
  std::vector<std::vector<bool>> swing;
};
FigureFiles plot_gait_diagrams(const std::vector<GaitPanel>& panels,
                               const std::vector<std::string>& legs, double step_seconds,
                               const std::filesystem::path& out_dir, std::string_view stem = {});

// Fig. 6: master and client CPG outputs with the client synchronised (alpha = 1) and free
// (alpha = 0), e.g. master p = 5, client p = 6.
struct CpgPairPoint {
  double master_x1;
  double master_x2;
  double client_x1;
  double client_x2;
};
FigureFiles plot_cpg_sync(const std::vector<CpgPairPoint>& synchronised,
                          const std::vector<CpgPairPoint>& independent, int master_period,
                          int client_period, const std::filesystem::path& out_dir,
                          std::string_view stem = {});

// Fig. 8: deviation of every trial of one learning run. Trial 0 is the detection window (the
// starting combination, accepted by definition); periods[leg] is the tried combination.
// What a model-based learner's model expected of a trial (learning/forecast.h): the median of a
// window's E and the band around it, degrees.
struct PredictedE {
  double deg;
  double low_deg;
  double high_deg;
};
struct TrialPoint {
  int trial;
  double deviation_deg;
  bool accepted;
  std::vector<int> periods;
  std::optional<PredictedE> predicted = {};  // none: a learner without a model, or trial 0
};
FigureFiles plot_learning_trace(const std::vector<TrialPoint>& trials,
                                const std::vector<std::string>& legs, double threshold_deg,
                                const std::filesystem::path& out_dir, std::string_view stem = {});

// Fig. 9: the motor outputs m of every leg, motor[step][leg] = {TC, CTr, FTi}; notes[leg] is a
// panel caption such as "disabled" or "p5".
using MotorTrace = std::vector<std::vector<std::array<double, 3>>>;
FigureFiles plot_motor_outputs(const MotorTrace& motor, const std::vector<std::string>& legs,
                               const std::vector<std::string>& notes, double step_seconds,
                               const std::filesystem::path& out_dir, std::string_view stem = {});

// Fig. 10: foot contact per leg, contact[step][leg] (true = touching the ground, stance).
FigureFiles plot_foot_contacts(const std::vector<std::vector<bool>>& contact,
                               const std::vector<std::string>& legs, double step_seconds,
                               const std::filesystem::path& out_dir, std::string_view stem = {});

// Figs. 11 (hexapod) and 13 (quadruped): per disabled-leg scenario, trials to converge and the
// final deviation over the runs (mean and SD), and the share of runs that converged (0..1).
struct ScenarioSummary {
  std::string scenario;  // disabled legs, e.g. "R1+R2"
  double mean_trials;
  double sd_trials;
  double mean_deviation_deg;
  double sd_deviation_deg;
  double share_converged;
  // Every run stayed under the threshold (e.g. a symmetric loss such as R1+L1): nothing was
  // learned, and the bar is labelled so instead of 0 % converged.
  bool no_deviation = false;
};
// robot: "hexapod" (Fig. 11) or "quadruped" (Fig. 13).
FigureFiles plot_learning_summary(const std::vector<ScenarioSummary>& scenarios,
                                  std::string_view robot, double threshold_deg,
                                  const std::filesystem::path& out_dir, std::string_view stem = {});

// Fig. 14: trials to converge per annealing factor beta (mean and SD over the runs).
struct BetaSummary {
  double beta;
  double mean_trials;
  double sd_trials;
  double share_converged;
};
// disabled_legs names the scenario in the title, e.g. "R1+R2" (the paper's).
FigureFiles plot_beta_study(const std::vector<BetaSummary>& betas, std::string_view disabled_legs,
                            const std::filesystem::path& out_dir, std::string_view stem = {});

// The learner benchmark (docs/learning.md "Learner benchmark"): each learner's share of runs
// held within the budget with its 95% interval, and the quartiles of its trials to a held
// combination (none where more than that share of runs never held).
struct LearnerScore {
  std::string name;
  double share_held = 0.0;
  double share_low = 0.0;
  double share_high = 0.0;
  std::optional<double> q1_trials, median_trials, q3_trials;
};
struct LearnerBenchmarkSetting {
  std::string robot;
  int budget = 0;
  int scenarios = 0;  // with a holding combination
  int seeds = 0;
};
FigureFiles plot_learner_benchmark(const std::vector<LearnerScore>& learners,
                                   const LearnerBenchmarkSetting& setting,
                                   const std::filesystem::path& out_dir,
                                   std::string_view stem = {});

// The trunk's path seen from above, before and after learning (paper §5 tunnel, Table 1);
// walls are optional polylines (e.g. the corridor's sides). Metres.
struct Point2 {
  double x;
  double y;
};
struct TrunkPaths {
  std::vector<Point2> before;
  std::vector<Point2> after;
  std::vector<std::vector<Point2>> walls;
  std::string before_label = "before learning";
  std::string after_label = "after learning";
};
FigureFiles plot_trunk_paths(const TrunkPaths& paths, const std::filesystem::path& out_dir,
                             std::string_view stem = {});

// The landscape of one scenario, every combination of working-leg periods sorted by
// its worst deviation (the largest of |yaw| and |path angle| over its windows), each window's
// own worst deviation behind it, the threshold, the best holding combination and where the
// learned combinations fall.
struct LandscapePoint {
  std::string label;  // e.g. "R2=5 R3=4 L1=5 L2=6 L3=5"
  // One per window walked, as the landscape judges it (with the reflex, its effort too); a
  // reflex landscape stops at the first window over the threshold, so counts may differ.
  std::vector<double> window_worst_deg;
  double worst_deg;          // the largest of them
  bool holds;                // every window under the threshold
  bool first_window_passes;  // the paper's yaw criterion on the first window
  bool best = false;         // the holding combination with the least worst_deg
  int learned = 0;           // how many learned answers are this combination
};
// title: the scenario, e.g. "hexapod, R1 disabled".
FigureFiles plot_landscape(const std::vector<LandscapePoint>& points, std::string_view title,
                           double threshold_deg, const std::filesystem::path& out_dir,
                           std::string_view stem = {});

// The calibration of the body against Table 1 (docs/fidelity.md): a heat map of the rank
// correlation (-1..1) of each searched body parameter (rows) with each number a candidate walked
// (columns: the tunnel angles, the score, the intact robot's yaw and speed, the paper's periods).
struct CalibrationMap {
  std::vector<std::string> params;
  std::vector<std::string> numbers;
  std::vector<std::vector<double>> rho;  // [param][number]
  std::string title;
  std::string subtitle;
};
FigureFiles plot_calibration(const CalibrationMap& map, const std::filesystem::path& out_dir,
                             std::string_view stem = {});

// `walk`, `learn` and `tunnel --plot FILE.png`: one picture of one run, drawn on the spot. The
// trunk's path seen from above (with the tunnel's walls and its axis, the course the robot should
// hold, where there is a tunnel), the learning trace when the run learned (Fig. 8's form), and a
// gait strip: the feet's contact over the run's last steps (blue = stance, Fig. 2's colours).
// What happened where on the path: a fault came, the deviation was detected (learning starts),
// the learned gait (the combination an episode ended with) starts.
enum class RunMarkKind { fault, detection, learned };
struct RunMark {
  RunMarkKind kind = RunMarkKind::fault;
  std::size_t at = 0;  // index into RunPicture::path
  std::string label;   // e.g. "R1 fails", "detected 37.9°"
};
// The body's lateral reach at one path point (world y, m): where the robot's outermost parts are,
// so that a path ending short of a wall still shows the body touching it.
struct LateralSpan {
  double low;
  double high;
};
struct RunPicture {
  std::string title;     // e.g. the command line
  std::string subtitle;  // a second line under the title; empty: none
  std::vector<Point2> path;
  std::vector<LateralSpan> span;  // empty, or one per path point: the band drawn around the path
  std::vector<RunMark> marks;
  std::vector<std::vector<Point2>> walls;
  std::vector<Point2> course;
  std::vector<TrialPoint> trials;  // empty: no learning panel; `trial` is the x position
  double threshold_deg = 0.0;      // the learning panel's threshold line
  // Written in the learning panel instead of a trace when no trial was made (trials holds only
  // trial 0, the detection window); empty: a generic sentence.
  std::string no_trial_note;
  std::vector<std::string> legs;
  std::vector<std::vector<bool>> contact;  // [step][leg], true = the foot touches the ground
  long first_contact_step = 0;             // the run's step of contact[0]
};
// Throws BadInput (one line, naming the path) unless `png` ends in .png and can be created.
void check_run_picture_path(const std::filesystem::path& png);
// The data gnuplot reads for a run picture: CSV texts and the script's variables that carry
// text. plot_run_picture writes these to a temporary folder; tests read them here.
struct RunPictureData {
  std::string path;   // series,x_m,y_m,y_low_m,y_high_m (series: path | wall | course)
  std::string marks;  // kind,label,x_m,y_m,step (kind: fault | detection | learned)
  // trial,deviation_deg,accepted,reference_deg; with a model's forecasts also predicted_deg,
  // predicted_low_deg, predicted_high_deg (NaN for trial 0)
  std::string trace;
  std::string gait;  // leg,row,stance_start_step,stance_end_step
  std::string subtitle;
  std::string trace_note;  // non-empty: the learning panel is this text alone
};
// Throws BadInput as plot_run_picture for unusable data.
RunPictureData run_picture_data(const RunPicture& picture);

// `--plot FILE.png` of a model-based learner's run, beside it as FILE-model.png: the model's map
// after the last trial (docs/learning.md "Inside the model"), its combinations with the best
// chance to hold, best on top, each with the median of a window's E and its band, and whether it
// was walked.
struct ModelMapRow {
  std::string label;  // the combination, e.g. "R1=4x R2=5 ..."
  double hold = 0.0;  // the chance that a window holds
  PredictedE e{};
  bool tried = false;
};
struct ModelMapPicture {
  std::string title;
  std::string subtitle;  // e.g. "the last episode's model after trial 12"
  double threshold_deg = 0.0;
  std::vector<ModelMapRow> rows;  // best first
};
// The data gnuplot reads: rank,label,hold,e_deg,e_low_deg,e_high_deg,tried (rank 1 = best).
// Throws BadInput naming the figure for no row or a threshold that is not positive.
std::string model_map_data(const ModelMapPicture& picture);
// Writes the picture to `png` alone (whole or not at all). Errors as plot_run_picture.
void plot_model_map(const ModelMapPicture& picture, const std::filesystem::path& png);
// Writes the picture to `png` alone (whole or not at all); the data gnuplot reads live in a
// temporary folder removed afterwards. Errors as the figures above.
void plot_run_picture(const RunPicture& picture, const std::filesystem::path& png);

}  // namespace multicpg::report
