// SIGTERM and SIGINT during `render` (docs/cli.md "Exit codes and signals"): the video stops with
// 143 or 130 and one line, no MP4 appears under its name, its temporary file is gone and no ffmpeg
// is left running. Needs rendering (EGL or OSMesa), so outside the sanitizer job's fast tests.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli_process.h"
#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;

constexpr std::chrono::seconds kStartGuard{60};
constexpr std::chrono::seconds kStopGuard{20};

// Processes whose command line mentions `text` (ffmpeg names its output file).
int processes_mentioning(const std::string& text) {
  int found = 0;
  for (const auto& e : fs::directory_iterator("/proc")) {
    std::ifstream in(e.path() / "cmdline", std::ios::binary);
    std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (cmdline.find(text) != std::string::npos) ++found;
  }
  return found;
}

TEST(SignalsRender, RenderStopsKillsFfmpegAndLeavesNoVideo) {
  for (const auto& [sig, code, name] : std::vector<std::tuple<int, int, std::string>>{
           {SIGTERM, 143, "SIGTERM"}, {SIGINT, 130, "SIGINT"}}) {
    SCOPED_TRACE(name);
    const std::string dir = make_temp_dir("multicpg-sig-render-");
    const fs::path video = fs::path(dir) / "walk.mp4";
    CliProcess cli({"render", "--out", video.string(), "--steps", "100000", "--width", "160",
                    "--height", "120"});
    const std::string tmp = video.string() + ".tmp" + std::to_string(cli.pid());
    // ffmpeg runs once the film has opened (its command line names the temporary file).
    ASSERT_TRUE(wait_until([&] { return processes_mentioning(tmp) > 0; }, kStartGuard))
        << cli.err();
    cli.signal(sig);
    ASSERT_TRUE(cli.wait(kStopGuard));
    EXPECT_EQ(cli.exit_code(), code) << cli.err();
    EXPECT_EQ(cli.err(), "multicpg: interrupted by " + name + "\n");
    EXPECT_FALSE(fs::exists(video));
    EXPECT_FALSE(fs::exists(tmp));
    EXPECT_EQ(processes_mentioning(tmp), 0) << "ffmpeg left running";
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace multicpg::testing
