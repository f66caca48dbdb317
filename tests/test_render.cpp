// Headless rendering and video: frames are drawn without a display, the red-prefix
// bodies come out red, the tracking camera follows the trunk, videos have every frame, and both
// GL platforms (EGL, OSMesa) work, each in a process of its own.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "common/errors.h"
#include "report/image.h"
#include "report/render.h"
#include "report/subprocess.h"
#include "report/video.h"
#include "tests/cli_runner.h"
#include "tests/render_test_model.h"

namespace {

namespace fs = std::filesystem;
using namespace multicpg::report;
using multicpg::testing::DataPtr;
using multicpg::testing::load_render_test_model;
using multicpg::testing::ModelPtr;

constexpr int kVideoFrames = 12;
constexpr int kVideoFps = 27;  // the controller's rate (paper §4)
// Share of the frame the trunk or the red leg must cover to count as seen.
constexpr double kMinShare = 0.002;
// How far (share of the frame width) the trunk may sit from the centre with a tracking camera.
constexpr double kCentreTolerance = 0.08;
constexpr int kSettleFrames = 40;  // MuJoCo's tracking camera closes 20 % of the gap per frame
// Set in a child process to run the tests meant for it alone.
constexpr const char* kChildEnv = "MULTICPG_RENDER_CHILD";
constexpr const char* kUnknownBackend = "no-such-gl";

// Channel levels (0-255) that tell the red leg and the blue trunk from the grey floor under
// MuJoCo's lighting.
constexpr int kStrongChannel = 150;
constexpr int kWeakChannel = 90;
bool is_red(const std::uint8_t* p) {
  return p[0] > kStrongChannel && p[1] < kWeakChannel && p[2] < kWeakChannel;
}
bool is_trunk_blue(const std::uint8_t* p) {
  return p[2] > kStrongChannel && p[0] < kWeakChannel && p[1] < kStrongChannel;
}

template <class Pred>
long count(const Image& image, Pred pred) {
  long n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) n += pred(image.pixel(x, y)) ? 1 : 0;
  }
  return n;
}

double share(const Image& image, long pixels) {
  return static_cast<double>(pixels) / (static_cast<double>(image.width) * image.height);
}

// Mean x of the pixels matching pred, as a share of the width.
template <class Pred>
double centroid_x(const Image& image, Pred pred) {
  double sum = 0;
  long n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (pred(image.pixel(x, y))) {
        sum += x;
        ++n;
      }
    }
  }
  return n == 0 ? -1.0 : sum / static_cast<double>(n) / image.width;
}

class RenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = load_render_test_model();
    ASSERT_NE(model_, nullptr);
    data_.reset(mj_makeData(model_.get()));
    mj_forward(model_.get(), data_.get());
    dir_ = multicpg::testing::make_temp_dir("multicpg-render-");
  }
  // Failed tests, or MULTICPG_KEEP_TEST_OUTPUT set, keep the frames for a person to look at.
  void TearDown() override {
    if (HasFailure() || std::getenv("MULTICPG_KEEP_TEST_OUTPUT") != nullptr) {
      std::cout << "frames kept in " << dir_ << "\n";
    } else {
      fs::remove_all(dir_);
    }
  }
  ModelPtr model_;
  DataPtr data_;
  fs::path dir_;
};

TEST_F(RenderTest, FrameShowsTheRobotWithTheRedLegRed) {
  Renderer renderer(model_.get());
  const char* env = std::getenv("MUJOCO_GL");
  if (env != nullptr && *env != '\0') {
    EXPECT_EQ(to_string(renderer.backend()), env);
  }
  const CameraSpec camera;
  const Image plain = render_frame(renderer, model_.get(), data_.get(), camera, {});
  const Image red = render_frame(renderer, model_.get(), data_.get(), camera,
                                 multicpg::testing::red_leg(model_.get()));
  ASSERT_EQ(plain.width, kDefaultFrameWidth);
  ASSERT_EQ(plain.height, kDefaultFrameHeight);
  ASSERT_EQ(red.rgb.size(), 3U * kDefaultFrameWidth * kDefaultFrameHeight);

  EXPECT_GT(share(plain, count(plain, is_trunk_blue)), kMinShare) << "trunk not visible";
  EXPECT_EQ(count(plain, is_red), 0) << "red before any prefix";
  const long red_pixels = count(red, is_red);
  EXPECT_GT(share(red, red_pixels), kMinShare) << "the R1_ leg is not red";
  // Red appears only where the leg is: pixels that the recolouring changed.
  long red_where_unchanged = 0;
  for (int y = 0; y < red.height; ++y) {
    for (int x = 0; x < red.width; ++x) {
      if (is_red(red.pixel(x, y)) && std::memcmp(red.pixel(x, y), plain.pixel(x, y), 3) == 0) {
        ++red_where_unchanged;
      }
    }
  }
  EXPECT_EQ(red_where_unchanged, 0);
  // The trunk keeps its colour.
  EXPECT_EQ(count(red, is_trunk_blue), count(plain, is_trunk_blue));

  const fs::path png = dir_ / "frame.png";
  write_png(red, png);
  const Image back = read_png(png);
  EXPECT_EQ(back.width, red.width);
  EXPECT_EQ(back.rgb, red.rgb);
}

TEST_F(RenderTest, TrackingCameraFollowsTheTrunk) {
  Renderer renderer(model_.get());
  CameraSpec tracking;
  tracking.azimuth = 90;  // looking along +y: x motion moves the trunk sideways in the picture
  CameraSpec fixed = tracking;
  fixed.track_robot = false;
  fixed.lookat = {0.0, 0.0, 0.3};
  render_frame(renderer, model_.get(), data_.get(), tracking, {});
  data_->qpos[0] += 0.6;  // free joint x: the trunk walks 0.6 m
  mj_forward(model_.get(), data_.get());
  Image followed;
  for (int i = 0; i < kSettleFrames; ++i) {
    followed = render_frame(renderer, model_.get(), data_.get(), tracking, {});
  }
  EXPECT_NEAR(centroid_x(followed, is_trunk_blue), 0.5, kCentreTolerance);
  const Image still = render_frame(renderer, model_.get(), data_.get(), fixed, {});
  const double off_centre = centroid_x(still, is_trunk_blue);
  EXPECT_TRUE(off_centre < 0 || std::abs(off_centre - 0.5) > kCentreTolerance)
      << "a fixed camera should not follow";
}

TEST_F(RenderTest, OtherSizesAndBadInput) {
  constexpr int kWide = 800;
  constexpr int kTall = 600;  // larger than the model's offscreen buffer (640x480)
  Renderer renderer(model_.get(), kWide, kTall);
  const Image image = render_frame(renderer, model_.get(), data_.get(), CameraSpec{}, {});
  EXPECT_EQ(image.width, kWide);
  EXPECT_EQ(image.height, kTall);
  EXPECT_GT(share(image, count(image, is_trunk_blue)), kMinShare);

  CameraSpec nowhere;
  nowhere.track_robot = false;
  nowhere.track_body = "no_such_body";
  EXPECT_THROW(render_frame(renderer, model_.get(), data_.get(), nowhere, {}), multicpg::BadInput);
  // A model of other parts (a reshaped copy of the renderer's own is drawn, sim/fault_effects.h).
  auto other = load_render_test_model(
      R"(<mujoco><worldbody><geom type="sphere" size="0.1"/></worldbody></mujoco>)");
  EXPECT_THROW(render_frame(renderer, other.get(), data_.get(), CameraSpec{}, {}),
               multicpg::BadInput);
  EXPECT_THROW(Renderer(nullptr), multicpg::BadInput);
  EXPECT_THROW(Renderer(model_.get(), 0, kTall), multicpg::BadInput);
}

std::string run_stdout(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  char buf[256];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  ::pclose(pipe);
  return out;
}

TEST_F(RenderTest, VideoHasEveryFrame) {
  Renderer renderer(model_.get());
  const fs::path mp4 = dir_ / "walk.mp4";
  VideoWriter video(mp4, renderer.width(), renderer.height(), kVideoFps);
  for (int i = 0; i < kVideoFrames; ++i) {
    data_->qpos[0] += 0.02;
    mj_forward(model_.get(), data_.get());
    video.add_frame(render_frame(renderer, model_.get(), data_.get(), CameraSpec{},
                                 multicpg::testing::red_leg(model_.get())));
  }
  EXPECT_FALSE(fs::exists(mp4)) << "the video must appear only when finished";
  video.finish();
  ASSERT_TRUE(fs::exists(mp4));
  EXPECT_EQ(multicpg::testing::video_frames(mp4), kVideoFrames);
  const std::string codec = run_stdout(
      "ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,width,height "
      "-of csv=p=0 '" +
      mp4.string() + "'");
  EXPECT_EQ(codec.substr(0, codec.find_last_not_of('\n') + 1), "h264,640,480");
  // Only the video is left: no temporary file.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

TEST_F(RenderTest, VideoBadInputAndAbandonedVideo) {
  const fs::path blocker = dir_ / "file";
  std::ofstream(blocker) << "x";
  try {
    VideoWriter(blocker / "sub" / "v.mp4", kDefaultFrameWidth, kDefaultFrameHeight, kVideoFps);
    FAIL() << "no exception";
  } catch (const multicpg::BadInput& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  EXPECT_THROW(VideoWriter(dir_ / "v.avi", kDefaultFrameWidth, kDefaultFrameHeight, kVideoFps),
               multicpg::BadInput);
  EXPECT_THROW(VideoWriter(dir_ / "v.mp4", 641, kDefaultFrameHeight, kVideoFps),
               multicpg::BadInput);
  EXPECT_THROW(VideoWriter(dir_ / "v.mp4", kDefaultFrameWidth, kDefaultFrameHeight, 0),
               multicpg::BadInput);
  {
    VideoWriter video(dir_ / "v.mp4", kDefaultFrameWidth, kDefaultFrameHeight, kVideoFps);
    EXPECT_THROW(video.add_frame(Image{2, 2, std::vector<std::uint8_t>(12)}), multicpg::BadInput);
    video.add_frame(Image{kDefaultFrameWidth, kDefaultFrameHeight,
                          std::vector<std::uint8_t>(3 * kDefaultFrameWidth * kDefaultFrameHeight)});
  }  // abandoned without finish(): nothing may be left behind
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
  VideoWriter empty(dir_ / "empty.mp4", kDefaultFrameWidth, kDefaultFrameHeight, kVideoFps);
  EXPECT_THROW(empty.finish(), multicpg::RuntimeFailure);
  EXPECT_FALSE(fs::exists(dir_ / "empty.mp4"));
}

// Runs this test program again with MUJOCO_GL set, so each platform gets a process of its own.
ProcessResult run_child(const std::string& backend, const std::string& filter,
                        const std::string& mode = "") {
  std::vector<std::string> argv{"env", "MUJOCO_GL=" + backend};
  if (!mode.empty()) argv.push_back(std::string(kChildEnv) + "=" + mode);
  argv.push_back(fs::read_symlink("/proc/self/exe").string());
  argv.push_back("--gtest_filter=" + filter);
  return run_process(argv);
}

TEST(RenderBackends, EglAndOsmesaEachRenderInTheirOwnProcess) {
  if (std::getenv(kChildEnv) != nullptr) GTEST_SKIP() << "child process";
  for (const std::string backend : {"egl", "osmesa"}) {
    const ProcessResult result =
        run_child(backend, "RenderTest.FrameShowsTheRobotWithTheRedLegRed", "render");
    EXPECT_EQ(result.exit_code, 0) << backend << ": " << result.output;
  }
}

TEST(RenderBackends, UnknownPlatformIsBadInput) {
  const char* mode = std::getenv(kChildEnv);
  if (mode == nullptr) {
    const ProcessResult result =
        run_child(kUnknownBackend, "RenderBackends.UnknownPlatformIsBadInput", "bad-backend");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return;
  }
  if (std::string(mode) != "bad-backend") GTEST_SKIP() << "child for another test";
  auto model = load_render_test_model();
  try {
    Renderer renderer(model.get());
    FAIL() << "no exception";
  } catch (const multicpg::BadInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(kUnknownBackend), std::string::npos);
    EXPECT_NE(what.find("egl"), std::string::npos);
    EXPECT_NE(what.find("osmesa"), std::string::npos);
  }
}

}  // namespace
