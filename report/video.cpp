#include "report/video.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "common/atomic_file.h"
#include "common/errors.h"

namespace multicpg::report {
namespace {

constexpr const char* kFfmpeg = "ffmpeg";
constexpr const char* kFfprobe = "ffprobe";

// A value of ffprobe's "key=value" lines; empty when missing.
std::string probed(const std::string& output, const std::string& key) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key + "=", 0) == 0) return line.substr(key.size() + 1);
  }
  return {};
}

// Checks that ffmpeg's file holds `frames` frames lasting frames / fps seconds (to one frame), so
// a file cut short (a full disk, a killed encoder) is never published.
void verify_video(const std::filesystem::path& file, const std::filesystem::path& name, int frames,
                  int fps) {
  const ProcessResult probe = run_process(
      {kFfprobe, "-v", "error", "-select_streams", "v:0", "-count_packets", "-show_entries",
       "stream=nb_read_packets,duration", "-of", "default=noprint_wrappers=1", file.string()});
  const std::string packets = probed(probe.output, "nb_read_packets");
  const std::string duration = probed(probe.output, "duration");
  const double expected = static_cast<double>(frames) / fps;
  const bool ok = probe.exit_code == 0 && packets == std::to_string(frames) && !duration.empty() &&
                  std::abs(std::strtod(duration.c_str(), nullptr) - expected) <= 1.0 / fps;
  if (!ok) {
    throw RuntimeFailure("encoding '" + name.string() + "' failed: ffprobe finds " +
                         (packets.empty() ? std::string("no video") : packets + " frames") +
                         (duration.empty() ? "" : " lasting " + duration + " s") + ", expected " +
                         std::to_string(frames) + " frames");
  }
}

std::filesystem::path checked_path(std::filesystem::path path) {
  if (path.extension() != ".mp4") throw BadInput("video '" + path.string() + "' must end in .mp4");
  ensure_writable_dir(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."));
  return path;
}

}  // namespace

VideoWriter::VideoWriter(std::filesystem::path path, int width, int height, int fps)
    : path_(checked_path(std::move(path))), width_(width), height_(height), fps_(fps) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    throw BadInput("video size must be positive and even, got " + std::to_string(width) + "x" +
                   std::to_string(height));
  }
  if (fps <= 0) throw BadInput("video frame rate must be positive, got " + std::to_string(fps));
  tmp_ = temp_sibling(follow_symlinks(path_));
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  ffmpeg_ = std::make_unique<ChildWithInput>(std::vector<std::string>{
      kFfmpeg, "-nostdin", "-y", "-loglevel", "error",
      // input: raw RGB frames on standard input
      "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-r", std::to_string(fps), "-i", "pipe:0",
      // output: H.264 that browsers play, index at the front for streaming in the HTML report;
      // x264's veryfast preset: 40 % less CPU than its default for the same file size here
      "-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p", "-movflags", "+faststart",
      "-f", "mp4", tmp_.string()});
}

VideoWriter::~VideoWriter() {
  if (ffmpeg_) {
    ffmpeg_.reset();  // an unfinished video is abandoned: ffmpeg is killed (subprocess.h)
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void VideoWriter::add_frame(const Image& frame) {
  if (!ffmpeg_) throw BadInput("video '" + path_.string() + "' is already finished");
  if (frame.width != width_ || frame.height != height_ ||
      frame.rgb.size() !=
          3 * static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_)) {
    throw BadInput("video frame is " + std::to_string(frame.width) + "x" +
                   std::to_string(frame.height) + ", expected " + std::to_string(width_) + "x" +
                   std::to_string(height_));
  }
  if (!ffmpeg_->write(frame.rgb)) {
    const ProcessResult result = ffmpeg_->finish();
    ffmpeg_.reset();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    throw RuntimeFailure("ffmpeg stopped while encoding '" + path_.string() +
                         "': " + tool_error(result));
  }
  ++frames_;
}

void VideoWriter::finish() {
  if (!ffmpeg_) throw BadInput("video '" + path_.string() + "' is already finished");
  const ProcessResult result = ffmpeg_->finish();
  ffmpeg_.reset();
  std::error_code ec;
  if (result.exit_code != 0 || frames_ == 0) {
    std::filesystem::remove(tmp_, ec);
    throw RuntimeFailure("encoding '" + path_.string() + "' failed: " +
                         (frames_ == 0 ? std::string("no frames") : tool_error(result)));
  }
  try {
    verify_video(tmp_, path_, frames_, fps_);
    sync_and_rename(tmp_, follow_symlinks(path_));
  } catch (...) {
    std::filesystem::remove(tmp_, ec);
    throw;
  }
}

}  // namespace multicpg::report
