// The calibration of the body against the real robot (docs/fidelity.md "Calibration"): which
// body parameter moves which Table 1 number, drawn from the calibration committed under
// docs/calibration (`multicpg calibrate` takes hours, so the report draws its data rather than
// run it again), and every value of the body models with its source.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/table.h"
#include "experiments/calibration.h"
#include "report/stages/stage.h"
#include "robot/body_json.h"
#include "robot/body_models.h"

namespace multicpg::report {
namespace {

namespace fs = std::filesystem;

// Installed layout: <prefix>/bin/multicpg and <prefix>/share/multicpg/calibration.
constexpr const char* kInstalledData = "../share/multicpg/calibration";

fs::path calibration_dir() {
  const fs::path source(MULTICPG_CALIBRATION_SOURCE_DIR);
  if (fs::is_directory(source)) return source;
  std::error_code ec;
  const fs::path installed = fs::read_symlink("/proc/self/exe", ec).parent_path() / kInstalledData;
  if (!ec && fs::is_directory(installed)) return installed.lexically_normal();
  throw RuntimeFailure("calibration data not found in " + source.string() +
                       " nor next to the program");
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RuntimeFailure("cannot read '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
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

}  // namespace

Section calibration_stage(const StageContext& ctx) {
  const fs::path dir = calibration_dir();
  const std::string csv = read_text(dir / "candidates.csv");
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "summary.json"));
  const experiments::Sensitivity s = experiments::sensitivity(parse_csv(csv));
  const CalibrationMap map{
      s.params, s.numbers, s.rho, "Which body parameter moves which number",
      std::to_string(s.candidates) + " design candidates of the calibration against Table 1 "
                                     "(docs/calibration)"};
  const FigureFiles figure = plot_calibration(map, ctx.dir("figures"));
  // The data beside the figure.
  const fs::path data = ctx.dir("calibration");
  write_file_atomic(data / "candidates.csv", csv);
  write_file_atomic(data / "summary.json", summary.dump(2) + "\n");
  const nlohmann::json& best = summary.at("best");
  return {"calibration",
          "Calibrating the body against the real robot",
          "The paper gives the real AMOSII's tunnel runs (Table 1, §5): before learning 42°, 21° "
          "and 23° to the right, R1 the worst; its mass (5.758 kg, 2.2 kg trunk) and its "
          "controller's body lift (5°) come from the authors' code. Nothing else of the body is "
          "stated.",
          "`multicpg calibrate --budget " + std::to_string(summary.at("budget").get<int>()) +
              "` walked " + std::to_string(summary.at("candidates").get<int>()) +
              " candidate bodies (a maximin Latin hypercube, then a compass search), each "
              "through Table 1's scenarios from " +
              counted(static_cast<long>(summary.at("warmups").size()), "start") +
              ", scored by the RMS distance of its "
              "before-learning angles to the real robot's with the intact robot straight "
              "(under 3° per window) and at a plausible speed. The best (" +
              best.at("id").get<std::string>() + ", RMS " +
              fixed(best.at("score_deg").get<double>(), 1) +
              "°), rounded, is the model real; the figure shows the rank correlation of each searched "
              "parameter with each number over the design, the table every value of both "
              "models with its source. docs/fidelity.md has the numbers it predicts on what it "
              "never saw (the paper's periods, the mirrored scenarios).",
          {ctx.image(figure)},
          {},
          {ctx.rel(data / "candidates.csv"), ctx.rel(data / "summary.json")},
          {models_table()}};
}

}  // namespace multicpg::report
