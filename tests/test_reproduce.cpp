// `multicpg reproduce --quick` end to end: every figure and video, the report
// opened in headless Chromium, and a second start that redoes nothing. It runs experiments on
// every core; ctest gives it one slot (tests/CMakeLists.txt says why).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::testing;

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
  for (const char* stem : {"fig02-gaits", "fig06-cpg-sync", "fig08-learning-trace", "fig09-motor",
                           "fig10-contacts", "fig11-hexapod", "fig13-quadruped", "fig14-beta",
                           "trunk-path-r1", "tunnel-path-R1", "landscape-map"}) {
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
  // Fig. 8's learning run and each Table 1 tunnel film have their 3D replay beside them
  // (tests/test_replay.cpp opens replays in Chromium).
  const std::string index = read_file((root / "index.html").string());
  for (const char* stem : {"learning-r1", "tunnel-R1-before", "tunnel-R1-after"}) {
    const fs::path page = root / "replays" / (std::string(stem) + ".html");
    EXPECT_GT(fs::exists(page) ? fs::file_size(page) : 0, 500'000u) << page;
    EXPECT_NE(index.find("3D replay: <a href=\"replays/" + std::string(stem) + ".html\">"),
              std::string::npos)
        << stem;
  }

  // The verdict table opens the report, each row linked to its section; Table 1's angles are
  // signed on both sides (the paper's before-learning ones to the right, negative).
  const std::size_t verdicts = index.find("What reproduced");
  ASSERT_NE(verdicts, std::string::npos);
  EXPECT_LT(verdicts, index.find("<section"));
  const std::string table = index.substr(verdicts, index.find("</table>", verdicts) - verdicts);
  for (const char* section :
       {"learning-r1", "hexapod-table", "quadruped-table", "beta", "tunnel"}) {
    EXPECT_NE(table.find("<a href=\"#" + std::string(section) + "\">"), std::string::npos)
        << section;
  }
  EXPECT_NE(index.find("hit the right wall, ≈-42°"), std::string::npos);
  // Fig. 14's claim, β = 0 (random search) needs the most trials, holds in the quick study (fewer
  // β values, one run each, seed 1): the suite's one test of it (report/stages/beta.cpp).
  const nlohmann::json beta =
      nlohmann::json::parse(read_file((root / "sections" / "beta.json").string()));
  EXPECT_EQ(beta.at("verdicts").at(0).at("reproduced"), "yes") << beta.at("measured");
  EXPECT_EQ(index.find("° right"), std::string::npos);

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

}  // namespace
