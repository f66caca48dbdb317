// Output files that appear whole or not at all: written to a temporary sibling, flushed to disk
// (fsync) and renamed on commit(), so a failed, interrupted or power-cut run never leaves a
// half-written file. A symlink is followed (the file it names is replaced, the link stays); a
// FIFO or character device (/dev/null, /dev/stdout) is written in place as the text comes (so a
// streamed record keeps no copy in memory), never replaced.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace multicpg {

// A stream buffer writing to a file descriptor that remembers why a write first failed (errno),
// which std::filebuf does not: a failure found long after it happened (at commit) still names
// its cause, e.g. "No space left on device".
class FdStreamBuf : public std::streambuf {
 public:
  FdStreamBuf();
  FdStreamBuf(const FdStreamBuf&) = delete;
  FdStreamBuf& operator=(const FdStreamBuf&) = delete;
  ~FdStreamBuf() override;

  // Takes ownership of `fd`.
  void attach(int fd);
  // Writes what is buffered and closes the descriptor; false when any write or the close failed.
  bool close();
  // errno of the first failed write or close; 0 while none failed.
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  bool write_buffer();

  static constexpr std::size_t kBufferBytes = 64 * 1024;
  int fd_ = -1;
  int error_ = 0;
  std::array<char, kBufferBytes> buffer_{};
};

class AtomicFile {
 public:
  // Opens the temporary file (or the FIFO or device) now, so an unwritable path fails before any
  // work: throws BadInput naming the path (also for a FIFO nobody reads, instead of blocking).
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return out_; }
  // Checks the finished temporary file before it takes the place of the target (e.g. that a PNG
  // decodes); throws to refuse it. Not called for a FIFO or device.
  using Verify = std::function<void(const std::filesystem::path& tmp)>;
  // Flushes, syncs and renames into place; throws RuntimeFailure naming the path and the cause
  // (strerror) if writing failed.
  void commit(const Verify& verify = {});

 private:
  std::filesystem::path path_;    // as given, for messages
  std::filesystem::path target_;  // path_ with symlinks followed: the file replaced
  std::filesystem::path tmp_;
  int special_fd_ = -1;  // a FIFO or character device, held open while buf_ writes it in place
  FdStreamBuf buf_;      // the temporary file, or the FIFO or device
  std::ostream out_{&buf_};
  bool committed_ = false;

  // Closes buf_; throws RuntimeFailure naming the cause when a write failed.
  void close_written();
};

// Why writing `out` failed, as strerror says it: the first failed write's when `out` writes
// through an FdStreamBuf (an AtomicFile's stream), else errno's.
std::string write_failure(const std::ostream& out);

// Writes `text` to `path` atomically.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

// `path` with every symlink in its last component followed (also a dangling one), so that writing
// replaces the file the link names, never the link. Throws BadInput for a symlink loop.
std::filesystem::path follow_symlinks(const std::filesystem::path& path);

// The temporary sibling this process writes before renaming: "<path>.tmp<pid>".
inline constexpr std::string_view kTempMarker = ".tmp";
// Digits of the largest pid (pid_max is at most 2^22 on Linux, proc(5)), with room to spare.
inline constexpr std::size_t kMaxPidDigits = 9;
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
