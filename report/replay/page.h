// The replay page: one self-contained HTML file that shows a recorded run (report/replay/
// recording.h) in 3D in any browser, offline, from disk (docs/replay.md). It inlines three.js
// (Debian's libjs-three) with its orbit controls, the page's own script and style
// (report/replay/replay.js, replay.css, embedded at build time) and the recording, its poses
// quantised, delta-coded per step and base64-coded, decoded by the page.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "common/limits.h"
#include "report/replay/recording.h"

namespace multicpg::report {

// The recording's format, written into every page and checked by the page's script.
inline constexpr const char* kReplayFormat = "multicpg replay";
inline constexpr int kReplayVersion = 1;
// The most steps a replay holds (docs/replay.md): 10 hours at 27 Hz, some 560 MB of the hexapod's
// poses in memory; a page any longer would not open in a browser.
inline constexpr long kMaxReplaySteps = 1'000'000;
inline constexpr Limits<long> kReplayStepLimits{1, kMaxReplaySteps};

// Throws BadInput naming `out` unless it is an .html file that can be created, so a bad path
// fails before any run.
void check_replay_path(const std::filesystem::path& out);

// The recording as the page reads it (a JSON object; poses and contacts base64-coded).
nlohmann::json replay_document(const Recording& recording, const std::string& title);

// The whole page.
std::string replay_html(const Recording& recording, const std::string& title);

// Writes the page to `out` atomically (common/atomic_file.h). Throws BadInput for a bad path,
// RuntimeFailure for an empty recording or a failed write.
void write_replay(const Recording& recording, const std::string& title,
                  const std::filesystem::path& out);

}  // namespace multicpg::report
