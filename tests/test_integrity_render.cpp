// Results you can trust, the cases that render (so not in the sanitizer job): MuJoCo's
// fatal errors reach the user as one line on stderr (never stdout, a MUJOCO_LOG.TXT file or a
// "Press Enter" prompt), and a video cut short is a failure, not a file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/cli_runner.h"

namespace multicpg {
namespace {

namespace fs = std::filesystem;
using testing::count_lines;
using testing::make_temp_dir;
using testing::run_shell;

TEST(MujocoErrors, OversizedFramebufferIsOneLineOnStderr) {
  const fs::path dir = make_temp_dir("mujoco-error-");
  // An offscreen buffer far beyond any OpenGL limit; stdin open, so a prompt would hang the test
  // until its timeout instead of passing.
  const auto r = run_shell("cd " + dir.string() + " && " + MULTICPG_EXE +
                           " render --steps 1 --width 100000 --height 100000 --out x.png");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("multicpg: "), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(dir / "MUJOCO_LOG.TXT"));
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

TEST(VerifiedOutputs, TruncatedVideoIsAFailure) {
  const fs::path dir = make_temp_dir("truncated-video-");
  // A file size limit stands in for a full disk: ffmpeg's writes fail (SIGXFSZ ignored), yet it
  // exits 0 with a file that holds no playable video.
  constexpr int kFileSizeLimitKiB = 40;
  const auto r = run_shell("cd " + dir.string() + " && trap '' XFSZ && ulimit -f " +
                           std::to_string(kFileSizeLimitKiB) + " && " + MULTICPG_EXE +
                           " render --steps 60 --width 320 --height 240 --out x.mp4");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("expected 60 frames"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.mp4"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace multicpg
