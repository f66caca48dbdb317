// The picture of one run (figures.h RunPicture): path, learning trace and gait strip in one PNG.
#include <algorithm>
#include <cstdlib>
#include <system_error>

#include "common/atomic_file.h"
#include "common/enum_names.h"
#include "common/errors.h"
#include "common/table.h"
#include "report/figure_drawing.h"
#include "report/figures.h"

namespace multicpg::report {

namespace fs = std::filesystem;

using namespace drawing;

namespace {

// Each mark's kind in marks.csv, as report/gnuplot/run_picture.gp reads it.
constexpr auto kRunMarkKindNames = enum_names<RunMarkKind>({{RunMarkKind::fault, "fault"},
                                                            {RunMarkKind::detection, "detection"},
                                                            {RunMarkKind::learned, "learned"}});

// The run picture's size: wide enough for the tunnel's 3 m beside its key; one panel taller
// with the learning trace.
constexpr int kPictureWidth = 1100;
constexpr int kPictureHeight = 850;
constexpr int kPictureTraceHeight = 400;
// Points of the trunk path drawn at most: a long run is thinned evenly (its last point kept),
// so gnuplot reads a small file whatever the run's length.
constexpr std::size_t kPicturePathPoints = 4000;
// The model's map: wide enough for a six-leg combination's label beside the chart; a row's
// height fits its label.
constexpr int kMapWidth = 1100;
constexpr int kMapHeaderHeight = 160;
constexpr int kMapRowHeight = 28;

// A folder of its own under the system's temporary folder, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "multicpg-plot-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw RuntimeFailure("cannot make a temporary folder for the plot's data under " +
                           fs::temp_directory_path().string());
    }
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

bool has_predictions(const RunPicture& picture) {
  return std::any_of(picture.trials.begin(), picture.trials.end(),
                     [](const TrialPoint& t) { return t.predicted.has_value(); });
}

}  // namespace

void check_run_picture_path(const fs::path& png) {
  if (png.extension() != ".png") {
    throw BadInput("cannot plot to '" + png.string() + "': the file type must be .png");
  }
  require_writable_file(png);
}

RunPictureData run_picture_data(const RunPicture& picture) {
  constexpr std::string_view name = "run picture";
  require(!picture.path.empty(), name, "no trunk path");
  require(picture.span.empty() || picture.span.size() == picture.path.size(), name,
          "need one lateral span per path point or none");
  require(picture.trials.empty() || picture.threshold_deg > 0.0, name,
          "threshold must be positive");
  require_rows(picture.contact, picture.legs, name);
  RunPictureData data;

  // y_low_m, y_high_m: the body's lateral reach around the path (NaN where not drawn).
  Csv path({"series", "x_m", "y_m", "y_low_m", "y_high_m"});
  const std::size_t stride = (picture.path.size() + kPicturePathPoints - 1) / kPicturePathPoints;
  for (std::size_t i = 0; i < picture.path.size(); ++i) {
    if (i % stride != 0 && i + 1 != picture.path.size()) continue;
    const bool spans = !picture.span.empty();
    path.row({"path", shortest(picture.path[i].x), shortest(picture.path[i].y),
              spans ? shortest(picture.span[i].low) : "NaN",
              spans ? shortest(picture.span[i].high) : "NaN"});
  }
  path.gap();
  const auto block = [&path](const std::string& series, const std::vector<Point2>& points) {
    for (const Point2& p : points) {
      path.row({series, shortest(p.x), shortest(p.y), "NaN", "NaN"});
    }
    path.gap();
  };
  for (const auto& wall : picture.walls) block("wall", wall);
  if (!picture.course.empty()) block("course", picture.course);
  data.path = path.text();

  Csv marks({"kind", "label", "x_m", "y_m", "step"});
  for (const RunMark& m : picture.marks) {
    require(m.at < picture.path.size(), name, "a mark lies past the path's end");
    marks.row({std::string(kRunMarkKindNames.name(m.kind)), m.label, shortest(picture.path[m.at].x),
               shortest(picture.path[m.at].y), std::to_string(m.at)});
  }
  data.marks = marks.text();

  const bool predicted = has_predictions(picture);
  std::vector<std::string> columns{"trial", "deviation_deg", "accepted", "reference_deg"};
  if (predicted)
    columns.insert(columns.end(), {"predicted_deg", "predicted_low_deg", "predicted_high_deg"});
  Csv trace(columns);
  const std::vector<double> references = reference_deviations(picture.trials);
  for (std::size_t i = 0; i < picture.trials.size(); ++i) {
    const TrialPoint& t = picture.trials[i];
    std::vector<std::string> row{std::to_string(t.trial), shortest(t.deviation_deg),
                                 t.accepted ? "1" : "0", shortest(references[i])};
    if (predicted) {
      // gnuplot skips a NaN: trial 0 (the detection window) has no forecast.
      const auto cell = [&](double PredictedE::*part) {
        return t.predicted ? shortest((*t.predicted).*part) : std::string("NaN");
      };
      row.insert(row.end(),
                 {cell(&PredictedE::deg), cell(&PredictedE::low_deg), cell(&PredictedE::high_deg)});
    }
    trace.row(row);
  }
  data.trace = trace.text();
  // Trial 0 alone is no trace: one lone point would read as a learning run of one trial.
  if (picture.trials.size() == 1) {
    data.trace_note =
        picture.no_trial_note.empty() ? "No trial: nothing was learned" : picture.no_trial_note;
  }

  Csv gait({"leg", "row", "stance_start_step", "stance_end_step"});
  const long first = picture.first_contact_step;
  for (std::size_t leg = 0; leg < picture.legs.size(); ++leg) {
    for (const auto& [start, end] : runs_of(picture.contact, leg, true)) {
      gait.row({picture.legs[leg], std::to_string(leg),
                std::to_string(first + static_cast<long>(start)),
                std::to_string(first + static_cast<long>(end))});
    }
  }
  data.gait = gait.text();
  data.subtitle = picture.subtitle;
  return data;
}

void plot_run_picture(const RunPicture& picture, const fs::path& png) {
  check_run_picture_path(png);
  const RunPictureData csv = run_picture_data(picture);
  const TempDir data;
  write_file_atomic(data.path() / "path.csv", csv.path);
  write_file_atomic(data.path() / "marks.csv", csv.marks);
  write_file_atomic(data.path() / "trace.csv", csv.trace);
  write_file_atomic(data.path() / "gait.csv", csv.gait);

  const fs::path dir = scripts_dir();
  const long first = picture.first_contact_step;
  const auto count = [&picture](RunMarkKind kind) {
    return static_cast<double>(std::count_if(picture.marks.begin(), picture.marks.end(),
                                             [kind](const RunMark& m) { return m.kind == kind; }));
  };
  Params params;
  params.text("dir", (dir / "").string())
      .text("path", (data.path() / "path.csv").string())
      .text("marks", (data.path() / "marks.csv").string())
      .text("trace", (data.path() / "trace.csv").string())
      .text("gait", (data.path() / "gait.csv").string())
      .text("title", picture.title)
      .text("subtitle", csv.subtitle)
      .num("has_walls", picture.walls.empty() ? 0 : 1)
      .num("has_course", picture.course.empty() ? 0 : 1)
      .num("has_span", picture.span.empty() ? 0 : 1)
      .num("has_marks", picture.marks.empty() ? 0 : 1)
      .num("n_fault", count(RunMarkKind::fault))
      .num("n_detection", count(RunMarkKind::detection))
      .num("n_learned", count(RunMarkKind::learned))
      .num("has_trace", picture.trials.empty() ? 0 : 1)
      .num("has_predicted", has_predictions(picture) ? 1 : 0)
      .text("trace_note", csv.trace_note)
      .num("threshold", picture.threshold_deg)
      .text("legs", join(picture.legs))
      .num("first_step", static_cast<double>(first))
      .num("last_step", static_cast<double>(first + static_cast<long>(picture.contact.size())));
  const int height = kPictureHeight + (picture.trials.empty() ? 0 : kPictureTraceHeight);
  run_gnuplot(dir / "run_picture.gp",
              "set terminal pngcairo size " + std::to_string(kPictureWidth) + "," +
                  std::to_string(height) + " enhanced font " + gp_string(kFont) +
                  " background rgb 'white'",
              params, png);
}

std::string model_map_data(const ModelMapPicture& picture) {
  const std::string name = "the model's map";
  require(!picture.rows.empty(), name, "no combination");
  require(picture.threshold_deg > 0.0, name, "the threshold must be positive");
  Csv csv({"rank", "label", "hold", "e_deg", "e_low_deg", "e_high_deg", "tried"});
  for (std::size_t i = 0; i < picture.rows.size(); ++i) {
    const ModelMapRow& r = picture.rows[i];
    csv.row({std::to_string(i + 1), r.label, shortest(r.hold), shortest(r.e.deg),
             shortest(r.e.low_deg), shortest(r.e.high_deg), r.tried ? "1" : "0"});
  }
  return csv.text();
}

void plot_model_map(const ModelMapPicture& picture, const fs::path& png) {
  check_run_picture_path(png);
  const std::string csv = model_map_data(picture);
  const TempDir data;
  write_file_atomic(data.path() / "map.csv", csv);
  const fs::path dir = scripts_dir();
  Params params;
  params.text("dir", (dir / "").string())
      .text("map", (data.path() / "map.csv").string())
      .text("title", picture.title)
      .text("subtitle", picture.subtitle)
      .num("threshold", picture.threshold_deg)
      .num("rows", static_cast<double>(picture.rows.size()));
  const int height = kMapHeaderHeight + kMapRowHeight * static_cast<int>(picture.rows.size());
  run_gnuplot(dir / "model_map.gp",
              "set terminal pngcairo size " + std::to_string(kMapWidth) + "," +
                  std::to_string(height) + " enhanced font " + gp_string(kFont) +
                  " background rgb 'white'",
              params, png);
}

}  // namespace multicpg::report
