#include "tests/cli_runner.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace multicpg::testing {

std::string make_temp_dir(const std::string& prefix) {
  std::string tmpl = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
  if (::mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return tmpl;
}

CliResult run_cli(const std::string& args) {
  return run_shell(std::string(MULTICPG_EXE) + " " + args);
}

CliResult run_shell(const std::string& command_line) {
  const std::string dir = make_temp_dir("multicpg-cli-");
  const std::string err_path = dir + "/stderr";
  const std::string cmd = command_line + " 2>" + err_path;
  CliResult result;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("popen failed");
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) result.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_path);
  std::stringstream ss;
  ss << err.rdbuf();
  result.err = ss.str();
  std::filesystem::remove_all(dir);
  return result;
}

int count_lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n' ? 1 : 0;
  if (!text.empty() && text.back() != '\n') ++n;
  return n;
}

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

void expect_bad_input(const std::string& args, const std::string& must_mention) {
  const CliResult r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(must_mention), std::string::npos) << args << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
}

bool is_png(const std::filesystem::path& path) {
  const std::string bytes = read_file(path);
  return bytes.size() > 100 && bytes.compare(1, 3, "PNG") == 0;
}

int video_frames(const std::filesystem::path& mp4) {
  const CliResult r = run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
      "-of csv=p=0 '" +
      mp4.string() + "'");
  return r.exit_code == 0 ? std::stoi(r.out) : -1;
}

}  // namespace multicpg::testing
