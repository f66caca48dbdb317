#include "common/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "common/errors.h"

namespace multicpg {
namespace {

std::string file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "no regular file";
}

}  // namespace

std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes,
                            std::string_view max_text, std::string_view what) {
  const std::string name = path.string();
  const auto too_large = [&](const std::string& size) {
    return BadInput(name + ": is " + size + ", more than the " + std::string(max_text) + " " +
                    std::string(what) + " may have");
  };
  // O_NONBLOCK: opening a FIFO never waits for a writer; the kind is checked on the open file,
  // so nothing can be swapped in between.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw BadInput(name + ": cannot read (" + std::strerror(errno) + ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw BadInput(name + ": cannot read (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw BadInput(name + ": is " + file_kind(st.st_mode) + ", not a file");
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    throw too_large(std::to_string(st.st_size) + " bytes");
  }
  // Read to the end, but never past the limit (a file may grow, /proc files say size 0): the
  // buffer starts at the size fstat gave and doubles, up to one byte past the limit.
  constexpr std::size_t kFirstBuffer = 64 * 1024;
  std::string text(
      std::min(max_bytes + 1,
               std::max<std::size_t>(static_cast<std::size_t>(st.st_size) + 1, kFirstBuffer)),
      '\0');
  std::size_t done = 0;
  for (;;) {
    if (done == text.size()) {
      if (text.size() > max_bytes) break;
      text.resize(std::min(max_bytes + 1, 2 * text.size()));
    }
    const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw BadInput(name + ": cannot read (" + std::strerror(errno) + ")");
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  if (done > max_bytes) throw too_large("larger");
  text.resize(done);
  return text;
}

}  // namespace multicpg
