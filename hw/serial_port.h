// A serial line with termios: raw 8N1 at a baud rate, reads with a deadline (poll), and the
// pseudo-terminal the emulator speaks on. termios rather than a library: the bus code needs
// deadlines per read and a pty like any port, which a few system calls give (Debian's LibSerial
// would add a dependency and no deadline semantics we lack).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "hw/bytes.h"

namespace multicpg::hw {

using Clock = std::chrono::steady_clock;  // CLOCK_MONOTONIC: one clock for every process

// Seconds of `Clock` since its epoch (boot): what logs of two processes are compared by.
double monotonic_s(Clock::time_point t = Clock::now());

// The baud rates termios names (B50..B4000000); throws BadInput listing them for another.
void require_baud(int baud);
std::string baud_rates_text();

class SerialPort {
 public:
  // Opens `path` raw 8N1 at `baud`, without becoming its controlling terminal, and drops what was
  // waiting in it. The port is ours alone (flock and TIOCEXCL, before anything is written or
  // set): another program holding it is refused with RuntimeFailure naming its pid where
  // /proc/locks tells it. Throws RuntimeFailure naming the path when it cannot (no such port, no
  // permission, not a serial line, in use). `emulator`: the pid of the emulator a rehearsal file
  // names; a pseudo-terminal it no longer serves is refused as gone, whatever holds the number now.
  SerialPort(const std::string& path, int baud, std::optional<int> emulator = std::nullopt);
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;
  ~SerialPort();

  const std::string& path() const { return path_; }
  // Writes every byte; throws RuntimeFailure naming the port when the line fails.
  void write(std::span<const std::uint8_t> bytes);
  // Appends to `into` what arrives until `deadline`, returning as soon as anything came (the
  // count; 0: nothing by the deadline). Throws RuntimeFailure naming the port when the line fails.
  std::size_t read_some(Bytes& into, Clock::time_point deadline);
  // Drops every byte received and not read yet (after a malformed answer: the rest of it).
  void drop_input();
  // Reads and drops bytes until none came for `quiet`, or until `give_up`: after an answer that
  // did not come in time, so that its late bytes are not taken for the next answer (the
  // protocols number no answers).
  void wait_quiet(Clock::duration quiet, Clock::time_point give_up);

 private:
  std::string path_;
  int fd_ = -1;
};

// A pseudo-terminal (openpty): the emulator holds the master, a host opens `path` as its port.
struct Pty {
  int master = -1;
  int slave = -1;  // kept open until the host has opened the port, so its bytes wait for it
  std::string path;
};
// Opens one in raw mode; throws RuntimeFailure if the system has none to give.
Pty open_pty();
void close_pty(Pty& pty);

}  // namespace multicpg::hw
