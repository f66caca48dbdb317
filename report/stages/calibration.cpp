// The calibration of the body against the real robot (docs/fidelity.md "Calibration"): which
// body parameter moves which Table 1 number, drawn from the calibration committed under
// docs/calibration (`multicpg calibrate` takes hours, so the report draws its data rather than
// run it again), and every value of the body models with its source.
#include "experiments/calibration.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <system_error>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/installed_data.h"
#include "common/table.h"
#include "experiments/paper.h"
#include "report/stages/stage.h"
#include "robot/body_json.h"
#include "robot/body_models.h"

namespace multicpg::report {
namespace {

namespace fs = std::filesystem;
namespace paper = experiments::paper;

// Installed in <prefix>/share/multicpg/calibration (common/installed_data.h).
constexpr const char* kInstalledData = "calibration";

fs::path calibration_dir() {
  const fs::path source(MULTICPG_CALIBRATION_SOURCE_DIR);
  if (fs::is_directory(source)) return source;
  const fs::path data = program_data_dir();
  if (!data.empty() && fs::is_directory(data / kInstalledData)) return data / kInstalledData;
  throw RuntimeFailure("calibration data not found in " + source.string() +
                       " nor next to the program");
}

std::string read_text(const fs::path& path) {
  return read_input_file(path, kMaxRecordBytes, kMaxRecordText, "a calibration record");
}

// Every body parameter: its value in each model and where real's comes from.
Table models_table() {
  Table t{{{"parameter", Align::left},
           {"unit", Align::left},
           {"paper-sim", Align::left},
           {"real", Align::left},
           {"source of real's value", Align::left}},
          {}};
  const robot::BodyParams sim = robot::body_params(robot::BodyModel::paper_sim);
  const robot::BodyParams real = robot::body_params(robot::BodyModel::real);
  for (std::string_view key : robot::parameter_keys()) {
    t.add_row({std::string(key), std::string(robot::value_unit(key)), robot::value_text(sim, key),
               robot::value_text(real, key),
               std::string(robot::value_source(robot::BodyModel::real, key))});
  }
  return t;
}

// The column of `table` titled `title`; RuntimeFailure when the committed data lack it.
std::size_t column_of(const Table& table, const std::string& title) {
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.columns[c].title == title) return c;
  }
  throw RuntimeFailure("docs/calibration/candidates.csv has no column '" + title + "'");
}

// The calibration's candidate the model real is: the row whose searched values are real's (the
// model keeps them at the search's full precision, robot/body_models.cpp). Empty if none is.
std::optional<std::size_t> real_candidate(const Table& candidates) {
  const robot::BodyParams real = robot::body_params(robot::BodyModel::real);
  const std::vector<std::pair<std::string, double>> searched{
      {"disabled_posture.tc", real.disabled_posture.tc},
      {"disabled_posture.ctr", real.disabled_posture.ctr},
      {"disabled_posture.fti", real.disabled_posture.fti},
      {"slip", real.slip},
      {"foot_friction", real.foot_friction},
      {"joint_compliance", real.joint_compliance},
      {"servo_torque", real.servo_torque}};
  for (std::size_t r = 0; r < candidates.rows.size(); ++r) {
    bool same = true;
    for (const auto& [title, value] : searched) {
      same = same && std::stod(candidates.rows[r][column_of(candidates, title)]) == value;
    }
    if (same) return r;
  }
  return std::nullopt;
}

}  // namespace

Section calibration_stage(const StageContext& ctx) {
  const fs::path dir = calibration_dir();
  const std::string csv = read_text(dir / "candidates.csv");
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "summary.json"));
  const experiments::Sensitivity s = experiments::sensitivity(parse_csv(csv));
  const CalibrationMap map{s.params, s.numbers, s.rho, "Which body parameter moves which number",
                           std::to_string(s.candidates) +
                               " design candidates of the calibration against Table 1 "
                               "(docs/calibration)"};
  const FigureFiles figure = plot_calibration(map, ctx.dir("figures"));
  // The data beside the figure.
  const fs::path data = ctx.dir("calibration");
  write_file_atomic(data / "candidates.csv", csv);
  write_file_atomic(data / "summary.json", summary.dump(2) + "\n");
  const nlohmann::json& best = summary.at("best");
  const Table candidates = parse_csv(csv);
  // The model real, as `model --list` lists it, and its candidate's fitted angles.
  write_file_atomic(data / "models.txt", robot::body_models_listing());
  const std::optional<std::size_t> row = real_candidate(candidates);
  std::string real_is = "No candidate of the committed calibration has real's values.";
  if (row) {
    const std::vector<std::string>& c = candidates.rows[*row];
    std::string fitted;
    for (const paper::TunnelResult& sc : paper::kTunnel) {
      fitted +=
          (fitted.empty() ? "" : ", ") + std::string(sc.disabled) + " " +
          fixed(
              std::stod(c[column_of(candidates, "fit " + std::string(sc.disabled) + " mean_deg")]),
              1) +
          "°";
    }
    real_is = "The model real is candidate " + c[column_of(candidates, "id")] +
              " (fitted before learning: " + fitted + "; score " +
              fixed(std::stod(c[column_of(candidates, "score_deg")]), 1) + "°)" +
              (c[column_of(candidates, "id")] == best.at("id").get<std::string>()
                   ? ", the search's best by score."
                   : ", not the search's best by score (" + best.at("id").get<std::string>() +
                         ", " + fixed(best.at("score_deg").get<double>(), 1) +
                         "°): docs/fidelity.md \"Calibration\" says why.");
  }
  std::string targets;
  for (const paper::TunnelResult& sc : paper::kTunnel) {
    targets += (targets.empty() ? "" : ", ") + fixed(paper::signed_before_deg(sc), 0) + "°";
  }
  const robot::BodyParams real = robot::body_params(robot::BodyModel::real);
  Section section{
      "calibration",
      "Calibrating the body against the real robot",
      "The paper gives the real AMOSII's tunnel runs (Table 1, §5): before learning it deviated "
      "to the right and hit the right board in all three scenarios (" +
          targets +
          ", signed + = left as ours). Its mass and trunk mass and its controller's body lift "
          "come from the authors' code (" +
          fixed(real.total_mass, 3) + " kg, " + fixed(real.trunk_mass, 1) + " kg, " +
          fixed(real.lift_body, 0) + "°). Nothing else of the body is stated.",
      "`multicpg calibrate --budget " + std::to_string(summary.at("budget").get<int>()) +
          "` walked " + std::to_string(summary.at("candidates").get<int>()) +
          " candidate bodies (a maximin Latin hypercube, then a compass search), each "
          "through Table 1's scenarios from " +
          counted(static_cast<long>(summary.at("warmups").size()), "start") +
          ", scored by the RMS distance of its before-learning angles to the real robot's with "
          "the intact robot straight and at a plausible speed. " +
          real_is + " `multicpg model --list` says of it: \"" +
          std::string(robot::describe(robot::BodyModel::real)) +
          "\". The figure shows the rank correlation of each searched parameter with each "
          "number over the design; the table and models.txt (the output of `multicpg model "
          "--list`) every value of both models with its source. docs/fidelity.md has the "
          "numbers it predicts on what it never saw (the paper's periods, the mirrored "
          "scenarios).",
      {ctx.image(figure)},
      {},
      {ctx.rel(data / "candidates.csv"), ctx.rel(data / "summary.json"),
       ctx.rel(data / "models.txt")},
      {models_table()}};
  section.reused =
      "docs/calibration/candidates.csv and summary.json, committed from `multicpg calibrate "
      "--budget " +
      std::to_string(summary.at("budget").get<int>()) +
      "`; this run draws them and does not walk the candidates again.";
  return section;
}

}  // namespace multicpg::report
