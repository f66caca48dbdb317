// One process at a time in an output directory: a second `multicpg experiment` on the same OUT
// would otherwise mix runs of different arguments into one directory.
#pragma once

#include <filesystem>

namespace multicpg {

class DirLock {
 public:
  // Claims `dir` (which must exist) with an exclusive flock(2) on dir/.multicpg.lock. The kernel
  // drops the lock when the process ends, even when it is killed, so no stale lock survives.
  // Throws BadInput naming `dir` (and the holder's pid) when another process holds it.
  explicit DirLock(const std::filesystem::path& dir);
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;
  ~DirLock();

 private:
  int fd_ = -1;
};

}  // namespace multicpg
