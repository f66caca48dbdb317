// The real multicpg binary: `walk`, `learn` and `tunnel --plot FILE.png` draw a picture of the run
// (report/figures.h RunPicture) on short, cheap runs, and refuse a bad path before the run; the
// picture's data as --plot records a real run (apps/plot_output.h): its marks and the body's reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string_view>
#include <tuple>
#include <vector>

#include "apps/plot_output.h"
#include "common/table.h"
#include "experiments/learning_run.h"
#include "experiments/run_spec.h"
#include "experiments/tunnel.h"
#include "learning/learners.h"
#include "report/image.h"
#include "sim/sim.h"
#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

// The picture decodes to the expected size and is no blank page: it has many colours, the
// paths' and the gait strip's blue among them.
void expect_picture(const fs::path& png, int height) {
  ASSERT_TRUE(fs::exists(png)) << png;
  const multicpg::report::Image image = multicpg::report::read_png(png);
  EXPECT_EQ(image.width, 1100);
  EXPECT_EQ(image.height, height);
  std::set<std::tuple<int, int, int>> colours;
  long blue = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      colours.insert({p[0], p[1], p[2]});
      // common.gp's blue, #1f5fbf.
      blue += (p[0] == 0x1f && p[1] == 0x5f && p[2] == 0xbf) ? 1 : 0;
    }
  }
  EXPECT_GT(colours.size(), 10u) << png;
  EXPECT_GT(blue, 1000) << png;
}

TEST(CliPlot, WalkDrawsPathAndGaitStrip) {
  const std::string dir = make_temp_dir("plot-");
  const auto r = run_cli("walk --disable R1 --steps 200 --plot " + dir + "/walk.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + dir + "/walk.png"), std::string::npos) << r.out;
  expect_picture(fs::path(dir) / "walk.png", 850);
  // Only the picture: gnuplot's data lived elsewhere and is gone.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(CliPlot, LearnDrawsTheLearningTrace) {
  const std::string dir = make_temp_dir("plot-");
  const auto r =
      run_cli("learn --mode paper --disable R1 --max-trials 3 --json --plot " + dir + "/learn.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_picture(fs::path(dir) / "learn.png", 1250);
  fs::remove_all(dir);
}

// "12.34° [10.21, 15.67]": how learn prints a forecast E (docs/learning.md "Inside the model").
std::string forecast_cell(const nlohmann::json& trial) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << trial.at("predicted_e_deg").get<double>() << "° ["
    << trial.at("predicted_e_low_deg").get<double>() << ", "
    << trial.at("predicted_e_high_deg").get<double>() << "]";
  return s.str();
}

// A model-based learner's run prints each trial's forecast as a column, as its record has it,
// and --plot draws the model's map beside the run's picture.
TEST(CliPlot, AModelLearnersForecastsArePrintedAndItsMapDrawn) {
  const std::string dir = make_temp_dir("plot-model-");
  const auto r = run_cli("learn --mode paper --disable R1 --max-trials 3 --learner bayes --out " +
                         dir + "/run --plot " + dir + "/learn.png");
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.err;
  EXPECT_NE(r.out.find("deviation      predicted E [band]  decision"), std::string::npos) << r.out;
  const nlohmann::json record = nlohmann::json::parse(read_file(dir + "/run/learning.json"));
  const nlohmann::json& trace = record.at("trace");
  ASSERT_FALSE(trace.empty());
  for (const nlohmann::json& t : trace) {
    EXPECT_NE(r.out.find(forecast_cell(t)), std::string::npos) << forecast_cell(t) << "\n" << r.out;
  }
  // trace.csv has the forecast's columns.
  const std::string csv = read_file(dir + "/run/trace.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* key :
       {"predicted_e_deg", "predicted_hold", "predicted_yaw_sd_deg", "may_hold"}) {
    EXPECT_NE(header.find(key), std::string::npos) << header;
  }
  expect_picture(fs::path(dir) / "learn.png", 1250);
  const fs::path map = fs::path(dir) / "learn-model.png";
  EXPECT_NE(r.out.find("wrote " + map.string()), std::string::npos) << r.out;
  ASSERT_TRUE(fs::exists(map));
  const multicpg::report::Image image = multicpg::report::read_png(map);
  EXPECT_EQ(image.width, 1100);
  EXPECT_EQ(image.height, 160 + 28 * 20);  // a header and the 20 best combinations
  fs::remove_all(dir);
  // The annealing has no model: no column, no map.
  const std::string plain = make_temp_dir("plot-model-");
  const auto a =
      run_cli("learn --mode paper --disable R1 --max-trials 2 --plot " + plain + "/learn.png");
  EXPECT_EQ(a.out.find("predicted"), std::string::npos) << a.out;
  EXPECT_FALSE(fs::exists(fs::path(plain) / "learn-model.png"));
  fs::remove_all(plain);
}

TEST(CliPlot, TunnelDrawsTheWallsAndCourse) {
  const std::string dir = make_temp_dir("plot-");
  const auto r = run_cli("tunnel --disable R1 --max-steps 300 --plot " + dir + "/tunnel.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_picture(fs::path(dir) / "tunnel.png", 850);
  fs::remove_all(dir);
}

namespace mc = multicpg;

const mc::sim::SimModel& hexapod() {
  static const mc::sim::SimModel model = mc::sim::make_sim_model(mc::robot::RobotKind::hexapod);
  return model;
}

std::size_t leg(std::string_view name) {
  return mc::robot::leg_index(hexapod().controller.morphology, name);
}

// The marks of one kind, in order.
std::vector<mc::report::RunMark> marks_of(const mc::report::RunPicture& picture,
                                          mc::report::RunMarkKind kind) {
  std::vector<mc::report::RunMark> out;
  for (const mc::report::RunMark& m : picture.marks) {
    if (m.kind == kind) out.push_back(m);
  }
  return out;
}

// Paper mode: the fault at the start, the detection, then the learned gait where its trial
// started, in that order along the path; the run ends with that trial, and the subtitle says so.
TEST(CliPlot, LearnMarksFaultDetectionAndLearnedGait) {
  const std::string dir = make_temp_dir("plot-marks-");
  mc::experiments::RunSpec spec;
  mc::learning::CompensationOptions& o = spec.learning.emplace();
  o.mode = mc::learning::Mode::paper;
  o.seed = 1;
  o.search.max_trials = 3;
  spec.start = mc::experiments::learning_start(o.mode);
  spec.faults = mc::body::fail_at({leg("R1")}, 0);
  mc::experiments::validate(spec);
  mc::apps::PlotOutput plot(dir + "/learn.png");
  const auto run = mc::experiments::run_learning(hexapod(), spec, 0, plot.observer());
  plot.learning(run.result, o.search.threshold_deg, mc::body::failing_legs(spec.faults));
  const mc::report::RunPicture picture = plot.picture();
  using mc::report::RunMarkKind;
  const auto faults = marks_of(picture, RunMarkKind::fault);
  const auto detections = marks_of(picture, RunMarkKind::detection);
  const auto learned = marks_of(picture, RunMarkKind::learned);
  ASSERT_EQ(faults.size(), 1u);
  ASSERT_EQ(detections.size(), 1u);
  ASSERT_EQ(learned.size(), 1u);
  EXPECT_EQ(faults[0].label, "R1 fails");
  EXPECT_EQ(faults[0].at, 0u);
  EXPECT_GT(detections[0].at, 0u);
  EXPECT_GE(learned[0].at, detections[0].at);
  EXPECT_LT(learned[0].at, picture.path.size() - 1) << "the learned gait's trial is walked";
  EXPECT_NE(picture.subtitle.find("ends with its last trial"), std::string::npos);
  // The CSV gnuplot reads holds them, one row each.
  const mc::report::RunPictureData data = mc::report::run_picture_data(picture);
  EXPECT_EQ(data.marks.rfind("kind,label,x_m,y_m,step\nfault,R1 fails,", 0), 0u) << data.marks;
  EXPECT_NE(data.marks.find("\ndetection,detected "), std::string::npos) << data.marks;
  EXPECT_NE(data.marks.find("\nlearned,"), std::string::npos) << data.marks;
  EXPECT_TRUE(picture.span.empty()) << "no tunnel, no band";
  fs::remove_all(dir);
}

// The picture's data as --plot records a model-based learner's run: each trial's forecast
// beside its measured E (trial 0 has none), and the model's map after the last trial.
TEST(CliPlot, AModelLearnersPictureCarriesItsForecasts) {
  const std::string dir = make_temp_dir("plot-forecast-");
  mc::experiments::RunSpec spec;
  mc::learning::CompensationOptions& o = spec.learning.emplace();
  o.mode = mc::learning::Mode::paper;
  o.learner = mc::learning::resolve_learner({"prior", nlohmann::json::object()});
  o.seed = 2;
  o.search.max_trials = 2;
  spec.start = mc::experiments::learning_start(o.mode);
  spec.faults = mc::body::fail_at({leg("R1"), leg("R3")}, 0);
  mc::experiments::validate(spec);
  mc::apps::PlotOutput plot(dir + "/learn.png");
  const auto run = mc::experiments::run_learning(hexapod(), spec, 0, plot.observer());
  ASSERT_FALSE(run.result.trace.empty());
  plot.learning(run.result, o.search.threshold_deg, mc::body::failing_legs(spec.faults));
  const mc::report::RunPictureData data = mc::report::run_picture_data(plot.picture());
  std::istringstream lines(data.trace);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "trial,deviation_deg,accepted,reference_deg,predicted_deg,predicted_low_deg,"
            "predicted_high_deg");
  std::getline(lines, line);
  EXPECT_EQ(line.substr(line.size() - 12), ",NaN,NaN,NaN") << "trial 0 has no forecast";
  for (const mc::learning::TrialRecord& t : run.result.trace) {
    ASSERT_TRUE(std::getline(lines, line));
    const std::string predicted =
        mc::shortest(t.details.at("predicted_e_deg").get<double>()) + "," +
        mc::shortest(t.details.at("predicted_e_low_deg").get<double>()) + "," +
        mc::shortest(t.details.at("predicted_e_high_deg").get<double>());
    EXPECT_EQ(line.substr(line.size() - predicted.size()), predicted) << line;
  }
  // The map: the run's best forecasts, labelled without the failed legs.
  ASSERT_TRUE(plot.model_map());
  const mc::report::ModelMapPicture& map = *plot.model_map();
  ASSERT_EQ(map.rows.size(), run.result.forecasts.size());
  ASSERT_EQ(map.rows.size(), 20u);
  EXPECT_EQ(map.rows[0].hold, run.result.forecasts[0].hold);
  EXPECT_EQ(map.rows[0].label.find("R1"), std::string::npos) << map.rows[0].label;
  EXPECT_NE(map.rows[0].label.find("R2="), std::string::npos) << map.rows[0].label;
  for (std::size_t i = 1; i < map.rows.size(); ++i) {
    EXPECT_GE(map.rows[i - 1].hold, map.rows[i].hold);
  }
  EXPECT_EQ(mc::report::model_map_data(map).rfind(
                "rank,label,hold,e_deg,e_low_deg,e_high_deg,tried\n1,", 0),
            0u);
  fs::remove_all(dir);
}

// Robust mode walks monitored windows after its last episode: the path goes on past the learned
// gait, and no subtitle says it ends with the trial.
TEST(CliPlot, RobustLearnPathWalksOnAfterLearning) {
  const std::string dir = make_temp_dir("plot-robust-");
  mc::experiments::RunSpec spec;
  mc::learning::CompensationOptions& o = spec.learning.emplace();  // robust, reflex: the default
  o.learner = mc::learning::resolve_learner({"random", nlohmann::json::object()});
  o.seed = 4;
  o.search.max_trials = 2;
  o.max_episodes = 1;
  o.monitor_windows = 1;
  spec.start = mc::experiments::learning_start(o.mode);
  spec.faults = mc::body::fail_at({leg("R1"), leg("R3")}, 0);
  mc::experiments::validate(spec);
  mc::apps::PlotOutput plot(dir + "/learn.png");
  const auto run = mc::experiments::run_learning(hexapod(), spec, 0, plot.observer());
  ASSERT_EQ(run.result.episodes.size(), 1u) << "R1+R3 deviates with the reflex alone";
  plot.learning(run.result, o.search.threshold_deg, mc::body::failing_legs(spec.faults));
  const mc::report::RunPicture picture = plot.picture();
  const auto learned = marks_of(picture, mc::report::RunMarkKind::learned);
  ASSERT_EQ(learned.size(), 1u);
  // At least the monitored window (400 steps, docs/learning.md) after the learned gait started.
  EXPECT_GT(picture.path.size(), learned[0].at + 400);
  EXPECT_EQ(picture.subtitle, "");
  EXPECT_EQ(marks_of(picture, mc::report::RunMarkKind::fault)[0].label, "R1+R3 fails");
  fs::remove_all(dir);
}

// A tunnel run that touches a wall: the trunk's path ends well short of it, the body's reach
// (y_low_m, y_high_m) gets to it.
TEST(CliPlot, TunnelBandReachesTheWallTheBodyTouched) {
  const std::string dir = make_temp_dir("plot-tunnel-");
  mc::experiments::RunSpec spec;
  spec.faults = mc::body::fail_at({leg("R1")}, 0);
  mc::experiments::validate(spec);
  const mc::sim::SimModel corridor = mc::experiments::tunnel_model(spec);
  mc::apps::PlotOutput plot(dir + "/tunnel.png");
  const auto out = mc::experiments::run_tunnel(spec, corridor, 1000, plot.observer());
  ASSERT_TRUE(out.run.touched_wall) << "R1 disabled turns right into the wall";
  const double half = corridor.scene.tunnel_width / 2.0;
  plot.tunnel(corridor.scene.tunnel_length, half * 2.0);
  const mc::report::RunPicture picture = plot.picture();
  ASSERT_EQ(picture.span.size(), picture.path.size());
  double trunk = 0.0;
  double reach = 0.0;
  for (std::size_t i = 0; i < picture.path.size(); ++i) {
    trunk = std::max(trunk, std::abs(picture.path[i].y));
    reach = std::max({reach, std::abs(picture.span[i].low), std::abs(picture.span[i].high)});
  }
  EXPECT_LT(trunk, half - 0.1) << "the trunk stays clear of the wall";
  EXPECT_GT(reach, half - 0.02) << "the body reaches the wall it touched";
  const mc::report::RunPictureData data = mc::report::run_picture_data(picture);
  EXPECT_NE(data.path.find("series,x_m,y_m,y_low_m,y_high_m\npath,"), std::string::npos);
  EXPECT_EQ(data.path.find("\npath,0,0,NaN,NaN"), std::string::npos) << "the band has numbers";
  fs::remove_all(dir);
}

TEST(CliPlot, BadPathIsRefusedBeforeTheRun) {
  const std::string dir = make_temp_dir("plot-");
  expect_bad_input("walk --plot " + dir + "/walk.jpg", ".png");
  expect_bad_input("learn --disable R1 --plot " + dir + "/learn", ".png");
  expect_bad_input("tunnel --disable R1 --plot /nonexistent-dir/t.png", "/nonexistent-dir/t.png");
  expect_bad_input("walk --plot " + dir, "--plot");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
  fs::remove_all(dir);
}

// An output path that is a symbolic link is written through: the file it names is replaced,
// the link stays (docs/cli.md "Exit codes and signals").
TEST(CliPlot, OutputsThroughASymbolicLinkReplaceTheFileItNames) {
  const std::string dir = make_temp_dir("plot-link-");
  fs::create_directory(dir + "/real");
  for (const char* name : {"walk.png", "walk.html", "walk.csv"}) {
    fs::create_symlink(dir + "/real/" + name, dir + "/" + name);  // dangling until written
  }
  const auto r = run_cli("walk --disable R1 --steps 100 --plot " + dir + "/walk.png --replay " +
                         dir + "/walk.html --csv " + dir + "/walk.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"walk.png", "walk.html", "walk.csv"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/" + name)));
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir + "/real/" + name)));
  }
  expect_picture(fs::path(dir) / "real" / "walk.png", 850);
  fs::remove_all(dir);
}

// docs/replay.md: a replay's name ends in .html (not .htm), and its page's title is the command
// with the file's name, not the folders it was typed with.
TEST(CliPlot, ReplayNameAndTitle) {
  const std::string dir = make_temp_dir("replay-title-");
  expect_bad_input("walk --steps 10 --replay " + dir + "/r.htm", "--replay");
  const auto r = run_cli("walk --disable R1 --steps 20 --replay " + dir + "/walk.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_file(dir + "/walk.html");
  const std::size_t open = page.find("<title>");
  ASSERT_NE(open, std::string::npos);
  const std::string title = page.substr(open, page.find("</title>") - open);
  EXPECT_NE(title.find("--replay walk.html"), std::string::npos) << title;
  EXPECT_EQ(title.find(dir), std::string::npos) << title;
  fs::remove_all(dir);
}

}  // namespace
