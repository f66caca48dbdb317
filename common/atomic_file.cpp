#include "common/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "common/errors.h"

namespace multicpg {
namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)) {
  if (path_.empty()) throw BadInput("empty output path");
  if (fs::is_directory(path_))
    throw BadInput("cannot write '" + path_.string() + "': is a directory");
  tmp_ = path_;
  tmp_ += ".tmp" + std::to_string(::getpid());
  out_.open(tmp_, std::ios::out | std::ios::trunc);
  if (!out_) {
    throw BadInput("cannot write '" + path_.string() + "': " + std::strerror(errno));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    fs::remove(tmp_, ec);
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw RuntimeFailure("writing '" + path_.string() + "' failed");
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec) throw RuntimeFailure("cannot move '" + tmp_.string() + "' into place: " + ec.message());
  committed_ = true;
}

void write_file_atomic(const fs::path& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

void require_writable_file(const fs::path& path) {
  if (path.empty()) throw BadInput("empty output path");
  if (fs::is_directory(path))
    throw BadInput("cannot write '" + path.string() + "': is a directory");
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent) || ::access(parent.c_str(), W_OK) != 0) {
    throw BadInput("cannot write '" + path.string() + "': folder '" + parent.string() +
                   "' does not exist or is not writable");
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
