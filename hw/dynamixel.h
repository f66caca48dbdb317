// DYNAMIXEL Protocol 2.0 as we speak it (docs/hardware.md "Dynamixel Protocol 2.0"; ROBOTIS
// e-Manual, "DYNAMIXEL Protocol 2.0"): instruction and status packets, byte stuffing, the
// protocol's CRC-16, and the X series' control table entries a walking robot needs. Pure functions:
// packets in, bytes out and back, testable without a port.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hw/bytes.h"

namespace multicpg::hw::dxl {

// Packet fields (e-Manual "Instruction Packet"): header FF FF FD, reserved 00, ID, length (2,
// little endian: instruction, parameters after stuffing and CRC), instruction, parameters, CRC.
inline constexpr std::uint8_t kHeader[] = {0xFF, 0xFF, 0xFD, 0x00};
inline constexpr std::size_t kHeaderBytes = 4;
inline constexpr std::size_t kPrefixBytes = 7;  // header, ID, length
inline constexpr std::uint8_t kBroadcastId = 0xFE;
inline constexpr std::uint8_t kMaxId = 252;  // IDs 0..252
// A packet's length field counts at least the instruction and the CRC.
inline constexpr std::size_t kMinLength = 3;
// Longest packet we accept (a sync read of 252 IDs is far shorter; the e-Manual's controllers
// buffer about 1 kB).
inline constexpr std::size_t kMaxPacketBytes = 1024;

enum class Instruction : std::uint8_t {
  ping = 0x01,
  read = 0x02,
  write = 0x03,
  status = 0x55,
  sync_read = 0x82,
  sync_write = 0x83,
};

// X series control table (e-Manual, e.g. "XM430-W350" control table): RAM items and sizes.
inline constexpr std::uint16_t kOperatingModeAddress = 11;     // 1 byte
inline constexpr std::uint8_t kPositionControlMode = 3;        // 0..360 deg, 0..4095
inline constexpr std::uint16_t kTorqueEnableAddress = 64;      // 1 byte, 0 or 1
inline constexpr std::uint16_t kGoalPositionAddress = 116;     // 4 bytes
inline constexpr std::uint16_t kPresentPositionAddress = 132;  // 4 bytes
inline constexpr std::uint16_t kPositionBytes = 4;
// Position control mode: 4096 counts per turn, 0..4095 (e-Manual: resolution 4096 pulse/rev).
inline constexpr int kCountsPerTurn = 4096;
inline constexpr int kMaxPosition = kCountsPerTurn - 1;

// The protocol's CRC-16 (e-Manual "CRC calculation"): polynomial 0x8005, initial value 0, bits
// not reflected, over every byte of the packet before the CRC, stuffing included.
std::uint16_t crc16(std::span<const std::uint8_t> bytes, std::uint16_t crc = 0);

// Byte stuffing (e-Manual "Byte Stuffing"): in the instruction and parameters, FF FF FD becomes
// FF FF FD FD, so the header cannot appear inside a packet; unstuff undoes it.
Bytes stuff(std::span<const std::uint8_t> body);
Bytes unstuff(std::span<const std::uint8_t> body);

// One packet: an instruction packet (the host's) or a status packet (a servo's answer, whose
// first parameter byte is its error field).
struct Packet {
  std::uint8_t id = 0;
  Instruction instruction = Instruction::ping;
  Bytes params;  // unstuffed; a status packet's start with its error byte
  bool operator==(const Packet&) const = default;
};

// The whole packet on the wire.
Bytes encode(const Packet& packet);

// Instruction packets.
Bytes ping(std::uint8_t id);
Bytes write(std::uint8_t id, std::uint16_t address, std::span<const std::uint8_t> data);
// SYNC WRITE of `size` bytes at `address` to each (ID, data) pair.
Bytes sync_write(std::uint16_t address, std::uint16_t size,
                 const std::vector<std::pair<std::uint8_t, Bytes>>& data);
// SYNC READ of `size` bytes at `address` from `ids`: each answers a status packet, in this order.
Bytes sync_read(std::uint16_t address, std::uint16_t size, std::span<const std::uint8_t> ids);
// A status packet (the emulator's answers): error field, then `data`.
Bytes status(std::uint8_t id, std::uint8_t error, std::span<const std::uint8_t> data);

// Little-endian 4-byte positions, as the control table stores them.
Bytes position_bytes(std::int32_t position);
std::int32_t position_value(std::span<const std::uint8_t> bytes);

// What parsing the front of a byte stream found.
enum class ParseStatus {
  packet,      // a whole, well-formed packet
  incomplete,  // a packet has begun (or nothing has): more bytes are needed
  bad_crc,     // a whole packet whose CRC does not match its bytes
  bad_length,  // a length field shorter than instruction + CRC, or past kMaxPacketBytes
};
struct ParseResult {
  ParseStatus status = ParseStatus::incomplete;
  // Bytes of the stream taken: noise before a header, and the packet (or the bad one's bytes).
  // A caller drops them and parses on.
  std::size_t consumed = 0;
  std::size_t skipped = 0;  // of them, bytes before the header (noise, a dropped packet's tail)
  std::optional<Packet> packet;
};

// Parses the first packet in `stream` (strictly: header, reserved byte, length, CRC).
ParseResult parse(std::span<const std::uint8_t> stream);

// The error field's meaning (e-Manual "Status Packet": bit 7 hardware alert, 1..7 the errors).
std::string error_text(std::uint8_t error);

}  // namespace multicpg::hw::dxl
