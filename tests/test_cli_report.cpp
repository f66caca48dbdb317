// The real multicpg binary: render, tunnel, figure and reproduce (issue 5), the report opened
// in headless Chromium.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

// Frames of a video, counted by decoding it (ffprobe).
int video_frames(const fs::path& mp4) {
  const auto r = run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames -of csv=p=0 " +
      mp4.string());
  return r.exit_code == 0 ? std::stoi(r.out) : -1;
}

bool is_png(const fs::path& path) {
  const std::string bytes = read_file(path);
  return bytes.size() > 100 && bytes.compare(1, 3, "PNG") == 0;
}

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
  const auto learn = run_cli("render --learn --disable R1 --speed 50 --out " + dir + "/learn.mp4");
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

TEST(CliFigure, DrawsNamedFiguresAndRejectsUnknownNames) {
  const std::string dir = make_temp_dir("figure-");
  ASSERT_EQ(run_cli("figure gait cpg-sync --out " + dir).exit_code, 0);
  EXPECT_TRUE(is_png(fs::path(dir) / "figures/fig02-gaits.png"));
  EXPECT_TRUE(fs::exists(fs::path(dir) / "figures/fig06-cpg-sync.svg"));
  EXPECT_TRUE(fs::exists(fs::path(dir) / "figures/fig06-cpg-sync.csv"));
  expect_bad_input("figure fig99 --out " + dir, "known: gait");
  expect_bad_input("figure gait --out /proc/multicpg-out", "/proc/multicpg-out");
  fs::remove_all(dir);
}

// Runs headless Chromium on a page; returns its DOM and puts the browser's log in `log`.
std::string open_in_chromium(const fs::path& page, std::string& log) {
  const std::string profile = make_temp_dir("chromium-");
  const auto r = run_shell(
      "chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
      profile +
      " --enable-logging=stderr --v=0 "
      "--virtual-time-budget=20000 --dump-dom file://" +
      fs::absolute(page).string());
  log = r.err;
  fs::remove_all(profile);
  return r.out;
}

TEST(CliReproduce, QuickReportOpensInChromiumWithEveryImageAndVideo) {
  const std::string dir = make_temp_dir("reproduce-");
  const auto r = run_cli("reproduce --quick --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path root(dir);
  ASSERT_TRUE(fs::exists(root / "index.html"));

  // Every figure of the paper, as PNG and SVG with its CSV; not blank (gnuplot draws > 5 kB).
  for (const char* stem :
       {"fig02-gaits", "fig06-cpg-sync", "fig08-learning-trace", "fig09-motor", "fig10-contacts",
        "fig11-hexapod", "fig13-quadruped", "fig14-beta", "trunk-path-r1", "tunnel-path-R1"}) {
    const fs::path png = root / "figures" / (std::string(stem) + ".png");
    EXPECT_TRUE(is_png(png)) << png;
    EXPECT_GT(fs::file_size(png), 5000u) << png;
    EXPECT_NE(read_file(root / "figures" / (std::string(stem) + ".svg")).find("</svg>"),
              std::string::npos)
        << stem;
    EXPECT_TRUE(fs::exists(root / "figures" / (std::string(stem) + ".csv"))) << stem;
  }
  // The tripod video plays the quick run's 160 steps in real time: one frame per step.
  EXPECT_EQ(video_frames(root / "videos/walk-tripod.mp4"), 160);
  EXPECT_TRUE(fs::exists(root / "results.md"));

  std::string log;
  const std::string dom = open_in_chromium(root / "index.html", log);
  EXPECT_NE(dom.find("data-media=\"ok\""), std::string::npos)
      << dom.substr(0, dom.find("<h1>")) << "\n"
      << log;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(":CONSOLE") != std::string::npos) ADD_FAILURE() << "console: " << line;
  }

  // Started again with the same options: nothing is redone.
  const auto again = run_cli("reproduce --quick --out " + dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("already done"), std::string::npos);
  EXPECT_EQ(run_cli("reproduce --out " + dir).exit_code, 2) << "other options, same folder";
  fs::remove_all(dir);
}

TEST(CliReproduce, BadInput) {
  expect_bad_input("reproduce --out /proc/multicpg-out", "/proc/multicpg-out");
  expect_bad_input("reproduce --out /tmp/x --jobs 0", "--jobs");
}

}  // namespace
