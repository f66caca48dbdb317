#include "common/dir_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <string>

#include "common/errors.h"

namespace multicpg {

DirLock::DirLock(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / ".multicpg.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw BadInput("cannot lock '" + dir.string() + "': " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    std::array<char, 32> holder{};
    const ssize_t n = ::pread(fd_, holder.data(), holder.size() - 1, 0);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw BadInput("'" + dir.string() + "' is in use by another multicpg process" +
                     (n > 0 ? " (pid " + std::string(holder.data()) + ")" : std::string()));
    }
    throw BadInput("cannot lock '" + dir.string() + "': " + std::strerror(error));
  }
  // The holder's pid, only for the message a refused process prints; without it the lock still
  // holds, so a failed write is not an error.
  const std::string pid = std::to_string(::getpid());
  const bool noted = ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) > 0;
  static_cast<void>(noted);
}

DirLock::~DirLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace multicpg
