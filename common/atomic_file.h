// Output files that appear whole or not at all: written to a temporary sibling and renamed on
// commit(), so a failed or interrupted run never leaves a half-written file.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace multicpg {

class AtomicFile {
 public:
  // Opens the temporary file now, so an unwritable path fails before any work
  // (throws BadInput naming the path).
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return out_; }
  // Flushes and renames into place; throws RuntimeFailure if writing failed.
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

// Writes `text` to `path` atomically.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

// Checks that `path` can be created: its folder exists and is writable and it is no folder
// itself. Throws BadInput naming the path; lets a long run fail before it starts.
void require_writable_file(const std::filesystem::path& path);

// Makes `dir` (and parents) and checks a file can be created in it; throws BadInput otherwise.
void ensure_writable_dir(const std::filesystem::path& dir);

}  // namespace multicpg
