// libFuzzer target for the bytes a serial line brings (docs/hardware.md): Dynamixel packets, the
// AMOSII board's frames and the yaw line's lines, parsed as the robot's side and the emulator
// parse them. Every parser must take any bytes without a crash, and every answer but "more bytes
// needed" must consume some, or a reading loop would spin. A Dynamixel packet read back from its
// own encoding is the same packet.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>

#include "hw/amosii.h"
#include "hw/dynamixel.h"
#include "hw/yaw_line.h"

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace multicpg::hw;
  const std::span<const std::uint8_t> bytes(data, size);

  const dxl::ParseResult p = dxl::parse(bytes);
  require(p.consumed <= size && p.skipped <= p.consumed);
  require(p.status == dxl::ParseStatus::incomplete || p.consumed > 0);
  if (p.packet) {
    const Bytes again = dxl::encode(*p.packet);
    const dxl::ParseResult q = dxl::parse(again);
    require(q.status == dxl::ParseStatus::packet && q.packet == p.packet);
  }

  const amosii::Command c = amosii::parse_command(bytes);
  require(c.consumed <= size);
  require(c.status == amosii::CommandStatus::incomplete || c.consumed > 0);
  amosii::parse_sensor_frame(bytes);

  const yaw_line::Split s = yaw_line::next_line(bytes);
  require(s.consumed <= size && (!s.complete || s.consumed > 0));
  yaw_line::parse_line(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
