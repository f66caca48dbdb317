// Output files that appear whole or not at all: written to a temporary sibling, flushed to disk
// (fsync) and renamed on commit(), so a failed, interrupted or power-cut run never leaves a
// half-written file. A symlink is followed (the file it names is replaced, the link stays); a
// FIFO or character device (/dev/null, /dev/stdout) is written in place as the text comes (so a
// streamed record keeps no copy in memory), never replaced.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace multicpg {

class AtomicFile {
 public:
  // Opens the temporary file (or the FIFO or device) now, so an unwritable path fails before any
  // work: throws BadInput naming the path (also for a FIFO nobody reads, instead of blocking).
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return *out_; }
  // Checks the finished temporary file before it takes the place of the target (e.g. that a PNG
  // decodes); throws to refuse it. Not called for a FIFO or device.
  using Verify = std::function<void(const std::filesystem::path& tmp)>;
  // Flushes, syncs and renames into place; throws RuntimeFailure if writing failed.
  void commit(const Verify& verify = {});

 private:
  std::filesystem::path path_;    // as given, for messages
  std::filesystem::path target_;  // path_ with symlinks followed: the file replaced
  std::filesystem::path tmp_;
  int special_fd_ = -1;  // a FIFO or character device, held open while file_ writes it in place
  std::ofstream file_;   // the temporary file, or the FIFO or device
  std::ostream* out_ = nullptr;
  bool committed_ = false;
};

// Writes `text` to `path` atomically.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

// `path` with every symlink in its last component followed (also a dangling one), so that writing
// replaces the file the link names, never the link. Throws BadInput for a symlink loop.
std::filesystem::path follow_symlinks(const std::filesystem::path& path);

// The temporary sibling this process writes before renaming: "<path>.tmp<pid>".
std::filesystem::path temp_sibling(const std::filesystem::path& path);

// fsync(2)s the finished `tmp`, renames it to `path` and syncs the folder, so after a crash
// `path` is either the old or the new file, whole. Throws RuntimeFailure naming `path`.
void sync_and_rename(const std::filesystem::path& tmp, const std::filesystem::path& path);

// Removes, anywhere under `dir`, temporary siblings ("*.tmp<pid>") left by processes that no
// longer run (killed runs). Returns how many it removed.
int remove_stray_temps(const std::filesystem::path& dir);

// Checks that `path` can be created: its folder exists and is writable and it is no folder
// itself (or it is a writable FIFO or device). Throws BadInput naming the path; lets a long run
// fail before it starts.
void require_writable_file(const std::filesystem::path& path);

// Makes `dir` (and parents) and checks a file can be created in it; throws BadInput otherwise.
void ensure_writable_dir(const std::filesystem::path& dir);

}  // namespace multicpg
