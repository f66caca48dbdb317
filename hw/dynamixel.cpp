#include "hw/dynamixel.h"

#include <algorithm>
#include <stdexcept>

namespace multicpg::hw::dxl {
namespace {

constexpr std::uint16_t kCrcPolynomial = 0x8005;
constexpr std::uint8_t kStuffByte = 0xFD;  // the header's third byte, repeated
constexpr std::uint8_t kAlertBit = 0x80;
constexpr std::uint8_t kErrorNumberMask = 0x7F;

bool pattern_ends_at(std::span<const std::uint8_t> bytes, std::size_t i) {
  return i >= 2 && bytes[i - 2] == 0xFF && bytes[i - 1] == 0xFF && bytes[i] == kStuffByte;
}

void put16(Bytes& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value & 0xFF));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

std::uint16_t get16(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::uint16_t>(bytes[at] | (bytes[at + 1] << 8));
}

}  // namespace

std::uint16_t crc16(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
  // Bit by bit rather than the e-Manual's 256-entry table: the same CRC, and a control step
  // sends a few hundred bytes at most.
  for (std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (b << 8));
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x8000) != 0 ? static_cast<std::uint16_t>((crc << 1) ^ kCrcPolynomial)
                                : static_cast<std::uint16_t>(crc << 1);
    }
  }
  return crc;
}

Bytes stuff(std::span<const std::uint8_t> body) {
  Bytes out;
  out.reserve(body.size() + body.size() / 3);
  for (std::size_t i = 0; i < body.size(); ++i) {
    out.push_back(body[i]);
    if (pattern_ends_at(body, i)) out.push_back(kStuffByte);
  }
  return out;
}

Bytes unstuff(std::span<const std::uint8_t> body) {
  Bytes out;
  out.reserve(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    out.push_back(body[i]);
    if (pattern_ends_at(body, i) && i + 1 < body.size() && body[i + 1] == kStuffByte) ++i;
  }
  return out;
}

Bytes encode(const Packet& packet) {
  Bytes body{static_cast<std::uint8_t>(packet.instruction)};
  body.insert(body.end(), packet.params.begin(), packet.params.end());
  const Bytes stuffed = stuff(body);
  const std::size_t length = stuffed.size() + 2;  // and the CRC
  if (kPrefixBytes + length > kMaxPacketBytes) {
    throw std::invalid_argument("Dynamixel packet longer than " + std::to_string(kMaxPacketBytes) +
                                " bytes");
  }
  Bytes out(std::begin(kHeader), std::end(kHeader));
  out.push_back(packet.id);
  put16(out, static_cast<std::uint16_t>(length));
  out.insert(out.end(), stuffed.begin(), stuffed.end());
  put16(out, crc16(out));
  return out;
}

Bytes ping(std::uint8_t id) {
  return encode({id, Instruction::ping, {}});
}

Bytes write(std::uint8_t id, std::uint16_t address, std::span<const std::uint8_t> data) {
  Bytes params;
  put16(params, address);
  params.insert(params.end(), data.begin(), data.end());
  return encode({id, Instruction::write, params});
}

Bytes sync_write(std::uint16_t address, std::uint16_t size,
                 const std::vector<std::pair<std::uint8_t, Bytes>>& data) {
  Bytes params;
  put16(params, address);
  put16(params, size);
  for (const auto& [id, bytes] : data) {
    if (bytes.size() != size) throw std::invalid_argument("sync write: data of the wrong size");
    params.push_back(id);
    params.insert(params.end(), bytes.begin(), bytes.end());
  }
  return encode({kBroadcastId, Instruction::sync_write, params});
}

Bytes sync_read(std::uint16_t address, std::uint16_t size, std::span<const std::uint8_t> ids) {
  Bytes params;
  put16(params, address);
  put16(params, size);
  params.insert(params.end(), ids.begin(), ids.end());
  return encode({kBroadcastId, Instruction::sync_read, params});
}

Bytes status(std::uint8_t id, std::uint8_t error, std::span<const std::uint8_t> data) {
  Bytes params{error};
  params.insert(params.end(), data.begin(), data.end());
  return encode({id, Instruction::status, params});
}

Bytes position_bytes(std::int32_t position) {
  const auto u = static_cast<std::uint32_t>(position);
  return {static_cast<std::uint8_t>(u & 0xFF), static_cast<std::uint8_t>((u >> 8) & 0xFF),
          static_cast<std::uint8_t>((u >> 16) & 0xFF), static_cast<std::uint8_t>(u >> 24)};
}

std::int32_t position_value(std::span<const std::uint8_t> bytes) {
  if (bytes.size() != kPositionBytes) throw std::invalid_argument("a position has 4 bytes");
  const std::uint32_t u =
      bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
  return static_cast<std::int32_t>(u);
}

ParseResult parse(std::span<const std::uint8_t> stream) {
  ParseResult r;
  const auto header =
      std::search(stream.begin(), stream.end(), std::begin(kHeader), std::end(kHeader));
  if (header == stream.end()) {
    // Keep a tail that may be the start of a header still arriving.
    std::size_t keep = 0;
    for (std::size_t n = std::min<std::size_t>(kHeaderBytes - 1, stream.size()); n > 0; --n) {
      if (std::equal(stream.end() - static_cast<std::ptrdiff_t>(n), stream.end(),
                     std::begin(kHeader))) {
        keep = n;
        break;
      }
    }
    r.consumed = r.skipped = stream.size() - keep;
    return r;
  }
  const auto at = static_cast<std::size_t>(header - stream.begin());
  r.consumed = r.skipped = at;
  if (stream.size() < at + kPrefixBytes) return r;
  const std::size_t length = get16(stream, at + 5);
  if (length < kMinLength || kPrefixBytes + length > kMaxPacketBytes) {
    r.status = ParseStatus::bad_length;
    r.consumed = at + kHeaderBytes;
    return r;
  }
  const std::size_t end = at + kPrefixBytes + length;
  if (stream.size() < end) return r;
  r.consumed = end;
  const std::span<const std::uint8_t> packet = stream.subspan(at, end - at);
  if (crc16(packet.first(packet.size() - 2)) != get16(packet, packet.size() - 2)) {
    r.status = ParseStatus::bad_crc;
    return r;
  }
  const Bytes body = unstuff(packet.subspan(kPrefixBytes, length - 2));
  r.status = ParseStatus::packet;
  r.packet = Packet{packet[4], static_cast<Instruction>(body.front()),
                    Bytes(body.begin() + 1, body.end())};
  return r;
}

std::string error_text(std::uint8_t error) {
  static constexpr const char* kNames[] = {"",
                                           "result fail",
                                           "instruction error",
                                           "CRC error",
                                           "data range error",
                                           "data length error",
                                           "data limit error",
                                           "access error"};
  const std::uint8_t number = error & kErrorNumberMask;
  std::string text =
      number < std::size(kNames) ? kNames[number] : "error " + std::to_string(number);
  if ((error & kAlertBit) != 0) text += std::string(text.empty() ? "" : ", ") + "hardware alert";
  return text.empty() ? "no error" : text;
}

}  // namespace multicpg::hw::dxl
