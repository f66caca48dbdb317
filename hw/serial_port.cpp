#include "hw/serial_port.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

#include "common/errors.h"

namespace multicpg::hw {
namespace {

struct Baud {
  int rate;
  speed_t constant;
};
constexpr std::array<Baud, 30> kBauds{
    {{50, B50},           {75, B75},           {110, B110},         {134, B134},
     {150, B150},         {200, B200},         {300, B300},         {600, B600},
     {1200, B1200},       {1800, B1800},       {2400, B2400},       {4800, B4800},
     {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
     {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
     {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
     {1500000, B1500000}, {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000},
     {3500000, B3500000}, {4000000, B4000000}}};

speed_t baud_constant(int baud) {
  for (const Baud& b : kBauds) {
    if (b.rate == baud) return b.constant;
  }
  require_baud(baud);
  return B0;
}

std::string system_error(const std::string& what) {
  return what + ": " + std::strerror(errno);
}

// The program holding a flock on `path`, from /proc/locks ("1: FLOCK ADVISORY WRITE PID
// MAJ:MIN:INODE 0 EOF"): "pid N (NAME)", or "another program" when no lock names one.
std::string lock_holder(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "another program";
  std::ifstream locks("/proc/locks");
  for (std::string line; std::getline(locks, line);) {
    std::istringstream fields(line);
    std::string number, type, advisory, mode, pid, where;
    if (!(fields >> number >> type)) continue;
    if (type == "->") fields >> type;  // a waiter's line
    if (!(fields >> advisory >> mode >> pid >> where) || type != "FLOCK") continue;
    unsigned major = 0, minor = 0;
    unsigned long inode = 0;
    if (std::sscanf(where.c_str(), "%x:%x:%lu", &major, &minor, &inode) != 3) continue;
    if (major != ::major(st.st_dev) || minor != ::minor(st.st_dev) || inode != st.st_ino) continue;
    if (pid == std::to_string(::getpid())) continue;
    std::string name;
    std::getline(std::ifstream("/proc/" + pid + "/comm"), name);
    return "pid " + pid + (name.empty() ? "" : " (" + name + ")");
  }
  return "another program";
}

// Where Linux puts pseudo-terminals (devpts): the emulator's ports.
constexpr std::string_view kPtyDir = "/dev/pts/";

// Whether process `pid` holds the master of pseudo-terminal `path` ("/dev/pts/N"): one of its
// descriptors' /proc fdinfo reads "tty-index: N" (what Linux's pty driver shows of a master).
// Where its descriptors cannot be read (another user's process) only that it runs is known, and
// it is taken as serving: refusing there would stop rehearsals that work.
bool serves_pty(int pid, const std::string& path) {
  const std::string proc = "/proc/" + std::to_string(pid);
  if (::access(proc.c_str(), F_OK) != 0) return false;
  const std::string index = path.substr(kPtyDir.size());
  std::error_code error;
  std::filesystem::directory_iterator fd(proc + "/fdinfo", error);
  if (error) return true;
  // Its descriptors may come and go meanwhile: the error codes' increment does not throw.
  for (; !error && fd != std::filesystem::directory_iterator(); fd.increment(error)) {
    std::ifstream info(fd->path());
    for (std::string line; std::getline(info, line);) {
      std::istringstream fields(line);
      std::string key, value;
      if (fields >> key >> value && key == "tty-index:" && value == index) return true;
    }
  }
  return false;
}

std::string emulator_gone(const std::string& path) {
  return "cannot open port " + path +
         ": the emulator that served it has ended; start it again (multicpg emulate --hardware "
         "FILE --rehearsal OUT.toml) and use the rehearsal file it writes";
}

std::string in_use(const std::string& path) {
  return "port " + path + " is in use by " + lock_holder(path) +
         ": one program drives a robot at a time (docs/hardware.md \"Safety\")";
}

}  // namespace

double monotonic_s(Clock::time_point t) {
  return std::chrono::duration<double>(t.time_since_epoch()).count();
}

std::string baud_rates_text() {
  std::string text;
  for (const Baud& b : kBauds) text += (text.empty() ? "" : ", ") + std::to_string(b.rate);
  return text;
}

void require_baud(int baud) {
  for (const Baud& b : kBauds) {
    if (b.rate == baud) return;
  }
  throw BadInput("baud " + std::to_string(baud) + " is not a termios rate (" + baud_rates_text() +
                 ")");
}

SerialPort::SerialPort(const std::string& path, int baud, std::optional<int> emulator)
    : path_(path) {
  const speed_t speed = baud_constant(baud);
  const bool pty = path.starts_with(kPtyDir);
  // A rehearsal file's port whose emulator has ended (it serves until interrupted): the kernel
  // may have given its number to another program since, a terminal even.
  if (pty && emulator && !serves_pty(*emulator, path)) throw RuntimeFailure(emulator_gone(path));
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd_ < 0 && errno == EBUSY) throw RuntimeFailure(in_use(path));  // another's TIOCEXCL
  if (fd_ < 0 && errno == ENOENT && pty) throw RuntimeFailure(emulator_gone(path));
  if (fd_ < 0) throw RuntimeFailure(system_error("cannot open port " + path));
  // Exclusive before a byte is written or a setting changed: a lock every multicpg takes, and
  // TIOCEXCL against other programs (a terminal program opening the port is refused, EBUSY).
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const std::string message =
        errno == EWOULDBLOCK ? in_use(path) : system_error("cannot lock port " + path);
    ::close(fd_);
    throw RuntimeFailure(message);
  }
  termios t{};
  if (::tcgetattr(fd_, &t) != 0) {
    const std::string message = system_error("port " + path + " is not a serial line");
    ::close(fd_);
    throw RuntimeFailure(message);
  }
  ::ioctl(fd_, TIOCEXCL);
  ::cfmakeraw(&t);  // 8 data bits, no parity, no echo, no translation
  t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);  // one stop bit, no flow control
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cc[VMIN] = 0;  // reads return what has come; poll() waits
  t.c_cc[VTIME] = 0;
  if (::cfsetispeed(&t, speed) != 0 || ::cfsetospeed(&t, speed) != 0 ||
      ::tcsetattr(fd_, TCSANOW, &t) != 0) {
    const std::string message = system_error("cannot set up port " + path);
    ::close(fd_);
    throw RuntimeFailure(message);
  }
  drop_input();
}

SerialPort::~SerialPort() {
  if (fd_ < 0) return;
  ::ioctl(fd_, TIOCNXCL);  // a pty's flag outlives our descriptor while its master is open
  ::close(fd_);
}

void SerialPort::write(std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw RuntimeFailure(system_error("cannot write to port " + path_));
    done += static_cast<std::size_t>(n);
  }
}

std::size_t SerialPort::read_some(Bytes& into, Clock::time_point deadline) {
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::max<long>(0, left.count())));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw RuntimeFailure(system_error("cannot read port " + path_));
    if (ready == 0) return 0;
    std::array<std::uint8_t, 512> buffer{};
    const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) throw RuntimeFailure(system_error("cannot read port " + path_));
    if (n == 0) {
      // POLLHUP with nothing to read: the other end is gone (a pty whose emulator ended).
      if ((p.revents & (POLLHUP | POLLERR)) != 0) {
        throw RuntimeFailure("port " + path_ + " hung up");
      }
      if (Clock::now() >= deadline) return 0;
      continue;
    }
    into.insert(into.end(), buffer.begin(), buffer.begin() + n);
    return static_cast<std::size_t>(n);
  }
}

void SerialPort::drop_input() {
  ::tcflush(fd_, TCIFLUSH);
}

void SerialPort::wait_quiet(Clock::duration quiet, Clock::time_point give_up) {
  Bytes late;
  for (;;) {
    const Clock::time_point now = Clock::now();
    if (now >= give_up || read_some(late, std::min(now + quiet, give_up)) == 0) return;
    late.clear();
  }
}

Pty open_pty() {
  Pty pty;
  termios t{};
  ::cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  std::array<char, 256> name{};
  if (::openpty(&pty.master, &pty.slave, name.data(), &t, nullptr) != 0) {
    throw RuntimeFailure(system_error("cannot open a pseudo-terminal"));
  }
  ::fcntl(pty.master, F_SETFD, FD_CLOEXEC);
  ::fcntl(pty.slave, F_SETFD, FD_CLOEXEC);
  pty.path = name.data();
  return pty;
}

void close_pty(Pty& pty) {
  if (pty.slave >= 0) ::close(std::exchange(pty.slave, -1));
  if (pty.master >= 0) ::close(std::exchange(pty.master, -1));
}

}  // namespace multicpg::hw
