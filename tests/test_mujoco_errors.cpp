// MuJoCo's fatal errors reach the user as one line on stderr and exit 1 (issue 9): never stdout,
// a MUJOCO_LOG.TXT file or a "Press Enter" prompt. Renders, so not in the sanitizer job.
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

}  // namespace
}  // namespace multicpg
