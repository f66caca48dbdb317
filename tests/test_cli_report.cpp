// The real multicpg binary: render, tunnel, figure and reproduce's bad input; the
// quick report itself is test_reproduce.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

TEST(CliRender, VideoHasOneFramePerStep) {
  const std::string dir = make_temp_dir("render-");
  const auto r = run_cli("render --disable R1 --steps 24 --out " + dir + "/walk.mp4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(video_frames(fs::path(dir) / "walk.mp4"), 24);
  const auto fast = run_cli("render --steps 40 --speed 4 --out " + dir + "/fast.mp4");
  ASSERT_EQ(fast.exit_code, 0) << fast.err;
  EXPECT_EQ(video_frames(fs::path(dir) / "fast.mp4"), 10);
  fs::remove_all(dir);
}

TEST(CliRender, PictureOfTheLastStepAndOfALearningRun) {
  const std::string dir = make_temp_dir("render-");
  ASSERT_EQ(run_cli("render --robot quadruped --steps 30 --out " + dir + "/q.png").exit_code, 0);
  EXPECT_TRUE(is_png(fs::path(dir) / "q.png"));
  const auto learn =
      run_cli("render --learn --mode paper --disable R1 --speed 50 --out " + dir + "/learn.mp4");
  ASSERT_EQ(learn.exit_code, 0) << learn.err;
  EXPECT_NE(learn.out.find("converged"), std::string::npos) << learn.out;
  EXPECT_GT(video_frames(fs::path(dir) / "learn.mp4"), 10);
  fs::remove_all(dir);
}

TEST(CliRender, BadInput) {
  const std::string dir = make_temp_dir("render-");
  expect_bad_input("render --out " + dir + "/x.gif", ".mp4");
  expect_bad_input("render --out " + dir + "/x", ".mp4");
  expect_bad_input("render --out /nonexistent-dir/x.mp4", "/nonexistent-dir/x.mp4");
  expect_bad_input("render --out /nonexistent-dir/x.png", "/nonexistent-dir/x.png");
  expect_bad_input("render --speed 0 --out " + dir + "/x.mp4", "--speed");
  expect_bad_input("render --learn --out " + dir + "/x.mp4", "--disable");
  expect_bad_input("render --disable R7 --out " + dir + "/x.mp4", "R7");
  EXPECT_FALSE(fs::exists(fs::path(dir) / "x.mp4"));
  fs::remove_all(dir);
}

TEST(CliTunnel, AllFourHitsTheWallAndThePapersR1CombinationPasses) {
  const auto before = run_cli("tunnel --disable R1 --json");
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_NE(before.out.find("\"touched_wall\": true"), std::string::npos) << before.out;
  const auto after = run_cli("tunnel --disable R1 --periods R2=5,R3=4,L1=5,L2=6,L3=5");
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_NE(after.out.find("passed"), std::string::npos) << after.out;
  expect_bad_input("tunnel --disable R1,R2,R3,L1,L2,L3", "every leg");
  expect_bad_input("tunnel --video /tmp/x.avi", ".mp4");
}

// tunnel --learn prints learn's table (streamed, apps/learning_output.h) before the tunnel walk.
TEST(CliTunnel, LearnPrintsTheLearningTableFirst) {
  const auto r = run_cli("tunnel --disable R1 --learn --mode paper --max-trials 2 --max-steps 400");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t header = r.out.find("trial  R1  R2  R3  L1  L2  L3");
  const std::size_t trial = r.out.find("\n    1  4x");
  const std::size_t learned = r.out.find("learned in the open field");
  ASSERT_NE(header, std::string::npos) << r.out;
  ASSERT_NE(trial, std::string::npos) << r.out;
  ASSERT_NE(learned, std::string::npos) << r.out;
  EXPECT_LT(header, trial);
  EXPECT_LT(trial, learned);
  EXPECT_NE(r.out.find("terrain flat, body model paper-sim"), std::string::npos) << r.out;
}

TEST(CliFigure, DrawsNamedFiguresAndRejectsUnknownNames) {
  const std::string dir = make_temp_dir("figure-");
  ASSERT_EQ(run_cli("figure gait cpg-sync --out " + dir).exit_code, 0);
  EXPECT_TRUE(is_png(fs::path(dir) / "figures/fig02-gaits.png"));
  EXPECT_TRUE(fs::exists(fs::path(dir) / "figures/fig06-cpg-sync.svg"));
  EXPECT_TRUE(fs::exists(fs::path(dir) / "figures/fig06-cpg-sync.csv"));
  expect_bad_input("figure fig99 --out " + dir, "unknown figure 'fig99' (gait, cpg-sync");
  expect_bad_input("figure gait --out /proc/multicpg-out", "/proc/multicpg-out");
  fs::remove_all(dir);
}

// The report's calibration section says what `model --list` says: models.txt is its output, the
// section's text quotes its line on real, the table's values and sources are its lines, and the
// candidate it names as real is the one docs/fidelity.md names. It says it reuses committed data.
TEST(CliReproduce, CalibrationTextIsModelList) {
  const auto list = run_cli("model --list");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  const std::string dir = make_temp_dir("calibration-");
  const auto r = run_cli("figure calibration --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir + "/calibration/models.txt"), list.out);

  const nlohmann::json section =
      nlohmann::json::parse(read_file(dir + "/sections/calibration.json"));
  const std::string measured = section.at("measured").get<std::string>();
  // model --list: "real: <what it is>", then one line per parameter; a blank line ends the block.
  const std::size_t real_at = list.out.find("\nreal: ");
  ASSERT_NE(real_at, std::string::npos) << list.out;
  const std::size_t line_end = list.out.find('\n', real_at + 1);
  const std::string describe = list.out.substr(real_at + 7, line_end - real_at - 7);
  EXPECT_NE(measured.find("\"" + describe + "\""), std::string::npos) << measured;
  const std::string real_block =
      list.out.substr(line_end, list.out.find("\n\n", line_end) - line_end);
  const auto& rows = section.at("tables").at(0).at("rows");
  ASSERT_FALSE(rows.empty());
  for (const auto& row : rows) {
    const std::string key = row.at(0).get<std::string>();
    const std::size_t at = real_block.find("\n  " + key + " ");
    ASSERT_NE(at, std::string::npos) << key;
    const std::string line = real_block.substr(at + 1, real_block.find('\n', at + 1) - at - 1);
    EXPECT_NE(line.find(row.at(3).get<std::string>()), std::string::npos) << line;
    EXPECT_NE(line.find(row.at(4).get<std::string>()), std::string::npos) << line;
  }
  const std::string named = "The model real is candidate ";
  const std::size_t id_at = measured.find(named);
  ASSERT_NE(id_at, std::string::npos) << measured;
  const std::size_t id_begin = id_at + named.size();
  const std::string id = measured.substr(id_begin, measured.find(' ', id_begin) - id_begin);
  EXPECT_NE(read_file(std::string(MULTICPG_SOURCE_DIR) + "/docs/fidelity.md").find("(" + id + ","),
            std::string::npos)
      << id;
  EXPECT_NE(section.at("reused").get<std::string>().find("docs/calibration"), std::string::npos);
  const std::string index = read_file(dir + "/index.html");
  EXPECT_NE(index.find("Reuses committed data"), std::string::npos);
  EXPECT_NE(index.find("What reproduced"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReproduce, BadInput) {
  expect_bad_input("reproduce --out /proc/multicpg-out", "/proc/multicpg-out");
  expect_bad_input("reproduce --out /tmp/x --jobs 0", "--jobs");
}

}  // namespace
