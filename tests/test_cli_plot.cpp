// The real multicpg binary: `walk`, `learn` and `tunnel --plot FILE.png` draw a picture of the run
// (report/figures.h RunPicture) on short, cheap runs, and refuse a bad path before the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <tuple>

#include "report/image.h"
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

TEST(CliPlot, TunnelDrawsTheWallsAndCourse) {
  const std::string dir = make_temp_dir("plot-");
  const auto r = run_cli("tunnel --disable R1 --max-steps 300 --plot " + dir + "/tunnel.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_picture(fs::path(dir) / "tunnel.png", 850);
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
