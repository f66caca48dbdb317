// MP4 videos of rendered frames, encoded by ffmpeg (H.264, yuv420p so browsers play them).
// The file appears whole at finish() or not at all.
#pragma once

#include <filesystem>
#include <memory>

#include "report/image.h"
#include "report/subprocess.h"

namespace multicpg::report {

class VideoWriter {
 public:
  // Starts ffmpeg writing to a temporary sibling of `path` (.mp4). Throws BadInput for a path
  // that is not .mp4 or not writable, odd or non-positive sizes (yuv420p needs even sizes), or
  // fps <= 0; RuntimeFailure when ffmpeg cannot be started.
  VideoWriter(std::filesystem::path path, int width, int height, int fps);
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;
  // Without finish(): kills ffmpeg and removes the temporary file.
  ~VideoWriter();

  // Throws BadInput for a frame of another size, RuntimeFailure when ffmpeg has stopped.
  void add_frame(const Image& frame);
  // Waits for ffmpeg, checks the file with ffprobe (frame count and duration) and moves it into
  // place (synced; a symlink at the path is followed, not replaced). Throws RuntimeFailure
  // (ffmpeg's last error line, or what ffprobe found) when encoding failed, the file is not every
  // frame, or no frame was added.
  void finish();

  int frames() const { return frames_; }

 private:
  std::filesystem::path path_;
  std::filesystem::path tmp_;
  int width_;
  int height_;
  int fps_;
  int frames_ = 0;
  std::unique_ptr<ChildWithInput> ffmpeg_;
};

}  // namespace multicpg::report
