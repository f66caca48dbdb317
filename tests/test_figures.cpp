// The figure layer: every figure is written as PNG, SVG and CSV, the pictures are real
// and not blank, the CSV holds the data, and bad input fails with one line.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.h"
#include "experiments/paper.h"
#include "report/figures.h"
#include "report/image.h"
#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::report;
namespace paper = multicpg::experiments::paper;

const std::vector<std::string> kHexapod{"R1", "R2", "R3", "L1", "L2", "L3"};
// Share of pixels that must differ from the background for a picture to count as drawn.
constexpr double kMinInkShare = 0.01;
constexpr std::array<unsigned char, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr long kGaitSteps = 120;
constexpr double kPi = std::numbers::pi;
// docs/controller.md "Gaits": swing lasts 2p+1 steps of a p(2p+1)-step cycle; legs lag by tau,
// left by tau_L.
constexpr long kTau = 18;
constexpr long kTauLeft = 90;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

// Signature, IHDR first with the figure's size, and decodable with ink on it.
void expect_png(const fs::path& path, const FigureInfo& info) {
  ASSERT_TRUE(fs::exists(path)) << path;
  const std::string bytes = read_text(path);
  ASSERT_GT(bytes.size(), 24U);
  EXPECT_TRUE(std::equal(
      kPngSignature.begin(), kPngSignature.end(), bytes.begin(),
      [](unsigned char want, char got) { return want == static_cast<unsigned char>(got); }));
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(big_endian(bytes, 16), static_cast<std::uint32_t>(info.width));
  EXPECT_EQ(big_endian(bytes, 20), static_cast<std::uint32_t>(info.height));
  const Image image = read_png(path);
  std::map<std::array<std::uint8_t, 3>, long> counts;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      ++counts[{p[0], p[1], p[2]}];
    }
  }
  long background = 0;
  for (const auto& [colour, n] : counts) background = std::max(background, n);
  const double total = static_cast<double>(image.width) * image.height;
  EXPECT_GT((total - static_cast<double>(background)) / total, kMinInkShare) << path << " is blank";
}

void expect_svg(const fs::path& path) {
  ASSERT_TRUE(fs::exists(path)) << path;
  const std::string text = read_text(path);
  EXPECT_TRUE(text.starts_with("<?xml") || text.starts_with("<svg")) << path;
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("</svg>"), std::string::npos);
  // Drawn content, not just an empty canvas.
  EXPECT_NE(text.find("<path"), std::string::npos);
}

// The CSV starts with `header` and has `rows` data lines (blank separator lines not counted).
void expect_csv(const fs::path& path, const std::string& header, std::size_t rows) {
  ASSERT_TRUE(fs::exists(path)) << path;
  const auto all = lines(read_text(path));
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front(), header);
  const auto data = static_cast<std::size_t>(
      std::count_if(all.begin() + 1, all.end(), [](const std::string& l) { return !l.empty(); }));
  EXPECT_EQ(data, rows) << path;
}

void expect_figure(const FigureFiles& files, std::string_view name, const std::string& header,
                   std::size_t rows) {
  const FigureInfo& info = figure_by_name(name);
  expect_png(files.png, info);
  expect_svg(files.svg);
  expect_csv(files.csv, header, rows);
  EXPECT_EQ(files.png.parent_path(), files.csv.parent_path());
}

class FiguresTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = multicpg::testing::make_temp_dir("multicpg-fig-"); }
  // Failed tests, or MULTICPG_KEEP_TEST_OUTPUT set, keep the pictures for a person to look at.
  void TearDown() override {
    if (HasFailure() || std::getenv("MULTICPG_KEEP_TEST_OUTPUT") != nullptr) {
      std::cout << "figures kept in " << dir_ << "\n";
    } else {
      fs::remove_all(dir_);
    }
  }
  fs::path dir_;
};

// A gait as docs/controller.md "Gaits" describes it: leg i swings for 2p+1 steps of every p(2p+1).
std::vector<std::vector<bool>> synthetic_gait(int period) {
  const long cycle = static_cast<long>(period) * (2 * period + 1);
  const std::array<long, 6> delay{2 * kTau,        kTau,    0, 2 * kTau + kTauLeft,
                                  kTau + kTauLeft, kTauLeft};
  std::vector<std::vector<bool>> swing(kGaitSteps, std::vector<bool>(kHexapod.size()));
  for (long t = 0; t < kGaitSteps; ++t) {
    for (std::size_t leg = 0; leg < kHexapod.size(); ++leg) {
      swing[t][leg] = period > 1 && (t + delay[leg]) % cycle < 2 * period + 1;
    }
  }
  return swing;
}

TEST_F(FiguresTest, GaitDiagramsOfSixPeriods) {
  std::vector<GaitPanel> panels;
  std::size_t stance_runs = 0;
  for (int p : {1, 4, 5, 6, 8, 9}) {
    panels.push_back({p, synthetic_gait(p)});
    for (std::size_t leg = 0; leg < kHexapod.size(); ++leg) {
      bool previous_stance = false;
      for (const auto& row : panels.back().swing) {
        stance_runs += !row[leg] && !previous_stance ? 1 : 0;
        previous_stance = !row[leg];
      }
    }
  }
  const auto files = plot_gait_diagrams(panels, kHexapod, paper::kStepSeconds, dir_);
  EXPECT_EQ(files.png.filename(), "fig02-gaits.png");
  expect_figure(files, "gait", "period,leg,row,stance_start_step,stance_end_step", stance_runs);
  // p = 1 is "stop": every leg stands for the whole record (one run per leg).
  const auto rows = lines(read_text(files.csv));
  EXPECT_EQ(rows[1], "1,R1,0,0," + std::to_string(kGaitSteps));
}

TEST_F(FiguresTest, CpgSyncAndAsync) {
  constexpr int kSteps = 60;
  std::vector<CpgPairPoint> sync;
  std::vector<CpgPairPoint> free;
  for (int t = 0; t < kSteps; ++t) {
    const double m = 0.5 + 0.4 * std::sin(2 * kPi * t / 5);
    const double c = 0.5 + 0.4 * std::sin(2 * kPi * t / 6);
    sync.push_back({m, 1 - m, m, 1 - m});
    free.push_back({m, 1 - m, c, 1 - c});
  }
  const auto files = plot_cpg_sync(sync, free, 5, 6, dir_);
  expect_figure(files, "cpg-sync",
                "step,sync_master_x1,sync_master_x2,sync_client_x1,sync_client_x2,"
                "free_master_x1,free_master_x2,free_client_x1,free_client_x2",
                kSteps);
}

TEST_F(FiguresTest, LearningTraceMarksAcceptedAndReference) {
  // The paper's §4 example: 37.86° at detection, L1 -> 5 gives 21.46° (kept), R3 -> 9 gives
  // 64.12° (rejected), then one below the threshold.
  const std::vector<TrialPoint> trials{
      {0, 37.86, true, {4, 4, 4, 4, 4, 4}},
      {1, 21.46, true, {4, 4, 4, 5, 4, 4}},
      {2, 64.12, false, {4, 4, 9, 5, 4, 4}},
      {3, 5.2, true, {4, 5, 4, 5, 4, 4}},
  };
  const auto files = plot_learning_trace(trials, kHexapod, paper::kThresholdDeg, dir_);
  expect_figure(files, "learning-trace",
                "trial,deviation_deg,accepted,reference_deg,change,R1,R2,R3,L1,L2,L3",
                trials.size());
  const auto rows = lines(read_text(files.csv));
  EXPECT_EQ(rows[3], "2,64.12,0,21.46,R3=9,4,4,9,5,4,4");  // rejected: E_ref stays at 21.46
}

TEST_F(FiguresTest, MotorOutputsOfEighteenJoints) {
  constexpr int kSteps = 80;
  MotorTrace motor(kSteps, std::vector<std::array<double, 3>>(kHexapod.size()));
  for (int t = 0; t < kSteps; ++t) {
    for (std::size_t leg = 0; leg < kHexapod.size(); ++leg) {
      const double phase = 2 * kPi * t / (4 + static_cast<double>(leg));
      motor[t][leg] = leg == 0 ? std::array<double, 3>{0.0, 0.7, -0.7}
                               : std::array<double, 3>{std::sin(phase), std::cos(phase) * 0.8,
                                                       -0.5 * std::sin(phase)};
    }
  }
  const std::vector<std::string> notes{"disabled", "p5", "p4", "p5", "p6", "p5"};
  const auto files = plot_motor_outputs(motor, kHexapod, notes, paper::kStepSeconds, dir_);
  std::string header = "step,time_s";
  for (const auto& leg : kHexapod) header += "," + leg + "_TC," + leg + "_CTr," + leg + "_FTi";
  expect_figure(files, "motor", header, kSteps);
}

TEST_F(FiguresTest, FootContactsPerLeg) {
  const auto swing = synthetic_gait(5);
  std::vector<std::vector<bool>> contact;
  for (const auto& row : swing) {
    std::vector<bool> c;
    for (bool s : row) c.push_back(!s);
    contact.push_back(c);
  }
  const auto files = plot_foot_contacts(contact, kHexapod, paper::kStepSeconds, dir_);
  expect_figure(files, "contacts", "step,time_s,R1,R2,R3,L1,L2,L3", contact.size());
}

TEST_F(FiguresTest, LearningSummaryHexapodAndQuadruped) {
  const std::vector<ScenarioSummary> hexapod{
      {"R1", 6.2, 3.1, 5.1, 1.9, 1.0},         {"R2", 4.5, 2.0, 4.0, 2.2, 1.0},
      {"R1+R2", 18.3, 9.9, 6.4, 1.2, 0.9},     {"R1+R3", 12.0, 5.5, 5.9, 1.7, 1.0},
      {"R1+R2+L3", 44.0, 30.1, 9.5, 4.4, 0.6}, {"R1+L1", 0.0, 0.0, 0.1, 0.0, 0.0, true},
  };
  const auto hex = plot_learning_summary(hexapod, "hexapod", paper::kThresholdDeg, dir_);
  EXPECT_EQ(hex.png.filename(), "fig11-hexapod.png");
  const std::string header =
      "scenario,mean_trials,sd_trials,mean_deviation_deg,sd_deviation_deg,share_converged,label";
  expect_figure(hex, "learning-hexapod", header, hexapod.size());
  // A scenario that never deviated says so instead of "0%".
  const std::string data = read_text(hex.csv);
  EXPECT_NE(data.find("R1+L1,0,0,0.1,0,0,n/d"), std::string::npos) << data;
  EXPECT_NE(data.find(",0.6,60%"), std::string::npos) << data;

  const std::vector<ScenarioSummary> quadruped{{"R1", 8.0, 4.0, 4.8, 2.0, 1.0},
                                               {"R2", 5.5, 2.5, 3.9, 1.5, 1.0},
                                               {"L1", 7.1, 3.3, 5.0, 2.1, 1.0},
                                               {"L2", 6.0, 2.9, 4.2, 1.8, 1.0}};
  const auto quad = plot_learning_summary(quadruped, "quadruped", paper::kThresholdDeg, dir_);
  EXPECT_EQ(quad.png.filename(), "fig13-quadruped.png");
  expect_figure(quad, "learning-quadruped", header, quadruped.size());
}

TEST_F(FiguresTest, BetaStudy) {
  const std::vector<BetaSummary> betas{{0, 30.2, 20.1, 0.9},    {0.1, 25.0, 15.0, 0.94},
                                       {0.3, 20.0, 12.0, 0.96}, {0.5, 14.3, 10.0, 1.0},
                                       {1, 16.0, 11.0, 0.98},   {5, 22.0, 18.0, 0.9},
                                       {10, 35.0, 40.0, 0.7}};
  const auto files = plot_beta_study(betas, "R1+R2", dir_);
  expect_figure(files, "beta", "beta,mean_trials,sd_trials,share_converged", betas.size());
}

TEST_F(FiguresTest, LandscapeSortsCombinationsAndMarksBestAndLearned) {
  const std::vector<LandscapePoint> points{
      {"R1=4 R2=4 L1=4", {30.0, 45.0}, 45.0, false, false},
      {"R1=9 R2=9 L1=4", {7.0, 7.9}, 7.9, true, true, true, 2},
      {"R1=5 R2=4 L1=4", {12.0, 9.0}, 12.0, false, true, false, 1}};
  const auto files = plot_landscape(points, "quadruped, L2 disabled",
                                    multicpg::experiments::paper::kThresholdDeg, dir_);
  EXPECT_EQ(files.png.filename(), "landscape-map.png");
  expect_figure(files, "landscape",
                "rank,worst_deg,holds,first_window_passes,best,learned,label,w1_worst_deg,"
                "w2_worst_deg",
                points.size());
  const std::string data = read_text(files.csv);
  EXPECT_NE(data.find("1,7.9,1,1,1,2,R1=9 R2=9 L1=4,7,7.9"), std::string::npos) << data;
  EXPECT_NE(data.find("3,45,0,0,0,0,R1=4 R2=4 L1=4,30,45"), std::string::npos) << data;

  // A walked-order landscape stops a combination at its first window over the threshold: the
  // windows it did not walk are drawn as gaps.
  const std::vector<LandscapePoint> truncated{{"a", {9.0}, 9.0, false, false},
                                              {"b", {1.0, 2.0}, 2.0, true, true}};
  const auto cut = plot_landscape(truncated, "x", multicpg::experiments::paper::kThresholdDeg, dir_,
                                  "truncated");
  EXPECT_NE(read_text(cut.csv).find("2,9,0,0,0,0,a,9,NaN"), std::string::npos)
      << read_text(cut.csv);
  const std::vector<LandscapePoint> empty{{"a", {}, 1.0, true, true},
                                          {"b", {1.0, 2.0}, 2.0, true, true}};
  EXPECT_THROW(plot_landscape(empty, "x", multicpg::experiments::paper::kThresholdDeg, dir_),
               multicpg::BadInput);
}

TEST_F(FiguresTest, TrunkPathsWithTunnelWalls) {
  constexpr int kPoints = 50;
  constexpr double kLength = 3.0;     // m, the paper's tunnel (Table 1)
  constexpr double kHalfWidth = 0.6;  // m
  TrunkPaths paths;
  for (int i = 0; i < kPoints; ++i) {
    const double x = kLength * i / (kPoints - 1);
    paths.before.push_back({x, -0.15 * x * x});
    paths.after.push_back({x, 0.02 * std::sin(3 * x)});
  }
  paths.walls = {{{0, kHalfWidth}, {kLength, kHalfWidth}},
                 {{0, -kHalfWidth}, {kLength, -kHalfWidth}}};
  paths.before_label = "all periods 4";
  paths.after_label = "learned periods";
  const auto files = plot_trunk_paths(paths, dir_);
  expect_figure(files, "trunk-path", "series,x_m,y_m", 2 * kPoints + 4);
}

TEST_F(FiguresTest, CustomStemKeepsFiguresApart) {
  const auto files = plot_foot_contacts({{true, false}, {false, true}}, {"R1", "L1"},
                                        paper::kStepSeconds, dir_, "contacts_two_legs");
  EXPECT_EQ(files.svg, dir_ / "contacts_two_legs.svg");
  expect_csv(files.csv, "step,time_s,R1,L1", 2);
}

TEST_F(FiguresTest, UnknownFigureNameListsKnownOnes) {
  try {
    figure_by_name("fig99");
    FAIL() << "no exception";
  } catch (const multicpg::BadInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("fig99"), std::string::npos);
    for (const FigureInfo& f : known_figures()) EXPECT_NE(what.find(f.name), std::string::npos);
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  EXPECT_THROW(plot_learning_summary({{"R1", 1, 0, 1, 0, 1}}, "spider", 8, dir_),
               multicpg::BadInput);
}

TEST_F(FiguresTest, UnwritableDirectoryIsBadInput) {
  const fs::path blocker = dir_ / "file";
  std::ofstream(blocker) << "x";
  try {
    plot_foot_contacts({{true}}, {"R1"}, paper::kStepSeconds, blocker / "sub");
    FAIL() << "no exception";
  } catch (const multicpg::BadInput& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

TEST_F(FiguresTest, GnuplotFailureIsOneLineRuntimeFailure) {
  // Nothing to draw: gnuplot stops with "all points y value undefined".
  const double undefined = std::nan("");
  try {
    plot_beta_study({{0, undefined, undefined, 0}}, "R1+R2", dir_);
    FAIL() << "no exception";
  } catch (const multicpg::RuntimeFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("beta_study.gp"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  // No picture, and no temporary file, is left behind.
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().extension(), ".csv") << entry.path();
  }
}

TEST_F(FiguresTest, RaggedDataIsBadInput) {
  EXPECT_THROW(plot_foot_contacts({{true, false}, {true}}, {"R1", "L1"}, paper::kStepSeconds, dir_),
               multicpg::BadInput);
  EXPECT_THROW(plot_gait_diagrams({}, kHexapod, paper::kStepSeconds, dir_), multicpg::BadInput);
  EXPECT_THROW(plot_learning_trace({{0, 10, true, {4}}}, kHexapod, 8, dir_), multicpg::BadInput);
  // Nothing half-written was left behind.
  EXPECT_TRUE(fs::is_empty(dir_));
}

// A run picture's data: the marks where they happened, the body's reach around the path, and a
// learning panel with no trial says so instead of holding one lone point.
TEST_F(FiguresTest, RunPictureMarksEventsBandAndNoTrial) {
  RunPicture picture;
  picture.title = "walk";
  picture.path = {{0.0, 0.0}, {0.5, -0.1}, {1.0, -0.3}};
  picture.span = {{-0.2, 0.2}, {-0.3, 0.1}, {-0.6, -0.1}};
  picture.marks = {{RunMarkKind::fault, 0, "R1 fails"},
                   {RunMarkKind::detection, 1, "detected 38.8°"},
                   {RunMarkKind::learned, 2, "learned gait"}};
  picture.walls = {{{0.0, 0.6}, {3.0, 0.6}}, {{0.0, -0.6}, {3.0, -0.6}}};
  picture.legs = {"R1", "L1"};
  picture.contact = {{true, false}, {false, true}};
  picture.threshold_deg = 8.0;
  picture.trials = {{0, 3.0, true, {4, 4}}};
  picture.subtitle = "the run ends with its last trial";
  const RunPictureData data = run_picture_data(picture);
  EXPECT_NE(data.path.find("series,x_m,y_m,y_low_m,y_high_m\npath,0,0,-0.2,0.2\n"),
            std::string::npos)
      << data.path;
  EXPECT_NE(data.path.find("path,1,-0.3,-0.6,-0.1\n"), std::string::npos) << data.path;
  EXPECT_NE(data.path.find("wall,0,0.6,NaN,NaN\n"), std::string::npos) << data.path;
  EXPECT_EQ(data.marks,
            "kind,label,x_m,y_m,step\nfault,R1 fails,0,0,0\ndetection,detected 38.8°,0.5,-0.1,1\n"
            "learned,learned gait,1,-0.3,2\n");
  EXPECT_EQ(data.trace_note, "No trial: nothing was learned");
  EXPECT_EQ(data.subtitle, picture.subtitle);
  // Drawn: gnuplot takes the marks, the band and the note.
  plot_run_picture(picture, dir_ / "run.png");
  EXPECT_TRUE(fs::exists(dir_ / "run.png"));

  // With a trial there is a trace, and no note.
  picture.trials.push_back({1, 2.0, true, {4, 5}});
  EXPECT_EQ(run_picture_data(picture).trace_note, "");
  // Without walls or a run walked, no band: NaN in its columns.
  picture.span.clear();
  EXPECT_NE(run_picture_data(picture).path.find("path,0,0,NaN,NaN\n"), std::string::npos);
  // A mark past the path's end, or a band of another length, is refused.
  picture.marks.push_back({RunMarkKind::learned, 3, "x"});
  EXPECT_THROW(run_picture_data(picture), multicpg::BadInput);
  picture.marks.pop_back();
  picture.span = {{-0.2, 0.2}};
  EXPECT_THROW(run_picture_data(picture), multicpg::BadInput);
}

}  // namespace
