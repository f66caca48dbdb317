#include "common/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include "common/errors.h"

namespace multicpg {
namespace fs = std::filesystem;
namespace {

// Linux's own limit on symlinks followed in one lookup (path_resolution(7)).
constexpr int kMaxSymlinks = 40;

bool written_in_place(const fs::file_status& s) {
  return fs::is_fifo(s) || fs::is_character_file(s);
}

std::string cannot_write(const fs::path& path, const std::string& why) {
  return "cannot write '" + path.string() + "': " + why;
}

// fsync(2) of the file or folder `path`; false (errno set) when it fails.
bool sync_path(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  const int error = errno;
  ::close(fd);
  errno = error;
  return ok;
}

// The pid in a temporary sibling's name "<file>.tmp<pid>", if it is one.
std::optional<pid_t> temp_owner(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::size_t at = name.rfind(kTempMarker);
  if (at == std::string::npos || at == 0) return std::nullopt;
  const std::string digits = name.substr(at + kTempMarker.size());
  if (digits.empty() || digits.size() > kMaxPidDigits ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return static_cast<pid_t>(std::stol(digits));
}

bool process_running(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno == EPERM;
}

// Mode of a new output file before the umask, as std::ofstream and shells create files.
constexpr mode_t kNewFileMode = 0666;

}  // namespace

FdStreamBuf::FdStreamBuf() {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

FdStreamBuf::~FdStreamBuf() {
  if (fd_ >= 0) ::close(fd_);
}

void FdStreamBuf::attach(int fd) {
  fd_ = fd;
  error_ = 0;
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

bool FdStreamBuf::write_buffer() {
  const char* data = pbase();
  std::size_t left = static_cast<std::size_t>(pptr() - pbase());
  while (left > 0 && error_ == 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = n < 0 ? errno : EIO;  // a write of 0 bytes cannot progress
      break;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return error_ == 0;
}

FdStreamBuf::int_type FdStreamBuf::overflow(int_type c) {
  if (fd_ < 0 || !write_buffer()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int FdStreamBuf::sync() {
  return fd_ >= 0 && write_buffer() ? 0 : -1;
}

bool FdStreamBuf::close() {
  if (fd_ < 0) return error_ == 0;
  write_buffer();
  if (::close(fd_) != 0 && error_ == 0) error_ = errno;
  fd_ = -1;
  return error_ == 0;
}

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)) {
  if (path_.empty()) throw BadInput("empty output path");
  target_ = follow_symlinks(path_);
  std::error_code ec;
  const fs::file_status status = fs::status(target_, ec);
  if (fs::is_directory(status)) throw BadInput(cannot_write(path_, "is a directory"));
  if (written_in_place(status)) {
    // O_NONBLOCK: opening a FIFO nobody reads fails (ENXIO) instead of waiting for a reader.
    special_fd_ = ::open(target_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (special_fd_ < 0) {
      throw BadInput(cannot_write(
          path_, errno == ENXIO ? "FIFO has no reader" : std::string(std::strerror(errno))));
    }
    // It has a reader now, so this open does not wait; writes block like any other.
    const int fd = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw BadInput(cannot_write(path_, std::strerror(errno)));
    buf_.attach(fd);
    return;
  }
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw BadInput(cannot_write(path_, "not a regular file, FIFO or character device"));
  }
  tmp_ = temp_sibling(target_);
  const int fd = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, kNewFileMode);
  if (fd < 0) throw BadInput(cannot_write(path_, std::strerror(errno)));
  buf_.attach(fd);
}

AtomicFile::~AtomicFile() {
  if (special_fd_ >= 0) ::close(special_fd_);
  if (!committed_ && !tmp_.empty()) {
    buf_.close();
    std::error_code ec;
    fs::remove(tmp_, ec);
  }
}

void AtomicFile::close_written() {
  out_.flush();
  if (!buf_.close() || !out_) {
    // A stream error with no failed write (a formatting failure) has no errno to name.
    const int error = buf_.error() != 0 ? buf_.error() : EIO;
    throw RuntimeFailure("writing '" + path_.string() + "' failed: " + std::strerror(error));
  }
}

void AtomicFile::commit(const Verify& verify) {
  if (special_fd_ >= 0) {
    const int fd = std::exchange(special_fd_, -1);
    try {
      close_written();
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
    committed_ = true;
    return;
  }
  close_written();
  if (verify) verify(tmp_);
  sync_and_rename(tmp_, target_);
  committed_ = true;
}

std::string write_failure(const std::ostream& out) {
  const int error = errno;
  const auto* buf = dynamic_cast<const FdStreamBuf*>(out.rdbuf());
  return std::strerror(buf != nullptr && buf->error() != 0 ? buf->error() : error);
}

void write_file_atomic(const fs::path& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

fs::path follow_symlinks(const fs::path& path) {
  fs::path p = path;
  for (int i = 0; i < kMaxSymlinks; ++i) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) throw BadInput(cannot_write(path, ec.message()));
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  throw BadInput(cannot_write(path, "too many levels of symbolic links"));
}

fs::path temp_sibling(const fs::path& path) {
  fs::path tmp = path;
  tmp += std::string(kTempMarker) + std::to_string(::getpid());
  return tmp;
}

void sync_and_rename(const fs::path& tmp, const fs::path& path) {
  if (!sync_path(tmp, O_RDONLY)) {
    throw RuntimeFailure("cannot flush '" + path.string() + "' to disk: " + std::strerror(errno));
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw RuntimeFailure("cannot move '" + tmp.string() + "' into place: " + ec.message());
  // Makes the rename itself durable. Some file systems cannot sync a folder; the file is already
  // whole on disk then, so that is no reason to fail the run.
  static_cast<void>(sync_path(path.has_parent_path() ? path.parent_path() : fs::path("."),
                              O_RDONLY | O_DIRECTORY));
}

int remove_stray_temps(const fs::path& dir) {
  std::vector<fs::path> stray;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const std::optional<pid_t> owner = temp_owner(it->path());
    if (owner && *owner != ::getpid() && !process_running(*owner) && it->is_regular_file(ec)) {
      stray.push_back(it->path());
    }
  }
  int removed = 0;
  for (const fs::path& p : stray) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

void require_writable_file(const fs::path& path) {
  if (path.empty()) throw BadInput("empty output path");
  const fs::path target = follow_symlinks(path);
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status)) throw BadInput(cannot_write(path, "is a directory"));
  if (written_in_place(status)) {
    if (::access(target.c_str(), W_OK) != 0) throw BadInput(cannot_write(path, "not writable"));
    return;
  }
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(parent) || ::access(parent.c_str(), W_OK) != 0) {
    throw BadInput(
        cannot_write(path, "folder '" + parent.string() + "' does not exist or is not writable"));
  }
}

void ensure_writable_dir(const fs::path& dir) {
  if (dir.empty()) throw BadInput("empty output directory");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw BadInput("cannot create output directory '" + dir.string() + "'" +
                   (ec ? ": " + ec.message() : ""));
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw BadInput("output directory '" + dir.string() + "' is not writable");
  }
}

}  // namespace multicpg
