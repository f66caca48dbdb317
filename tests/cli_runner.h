// Runs the real multicpg binary for end-to-end tests.
#pragma once

#include <filesystem>
#include <string>

namespace multicpg::testing {

struct CliResult {
  int exit_code = -1;
  std::string out;  // standard output
  std::string err;  // standard error
};

// Runs `multicpg <args>` through the shell (args are shell words) and captures both streams.
CliResult run_cli(const std::string& args);

// Runs a whole shell command line (e.g. one that changes the environment first, or wraps the
// binary, whose path is MULTICPG_EXE) and captures both streams.
CliResult run_shell(const std::string& command_line);

// A fresh empty directory under the system temp dir, removed by the caller if wanted.
std::string make_temp_dir(const std::string& prefix);

// Lines of `text` without the trailing empty line.
int count_lines(const std::string& text);

// A whole file (binary-safe); empty when it cannot be read.
std::string read_file(const std::string& path);
std::string first_line(const std::string& text);
// True when the file starts with PNG's signature and is not trivially short.
bool is_png(const std::filesystem::path& path);
// Frames of a video, counted by decoding it (ffprobe); -1 when ffprobe fails.
int video_frames(const std::filesystem::path& mp4);

// Bad input: `multicpg <args>` exits 2 with exactly one line on stderr that mentions
// `must_mention`, and prints nothing on stdout (GoogleTest expectations).
void expect_bad_input(const std::string& args, const std::string& must_mention);

}  // namespace multicpg::testing
