// A JSON document as sealed bytes: CBOR (doubles bit for bit, binary arrays as they are) followed
// by the FNV-1a checksum of the CBOR (common/checksum.h), and back. For state that leaves the
// process and may come back damaged or made by hand: the Python module's pickled simulation
// states (sim/checkpoint.h). The checksum shows damage, not a forger: whoever reads a document
// still checks what it says.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace multicpg {

// Largest sealed document read back: 64 MiB, some thousand times an octopod's checkpoint.
inline constexpr std::size_t kMaxSealedBytes = std::size_t{64} << 20;
// Deepest nesting read back. nlohmann's CBOR reader recurses once per level, so a forged
// document of a million nested arrays would overflow the stack; a checkpoint nests 6 deep.
inline constexpr int kMaxSealedDepth = 32;

std::string seal_cbor(const nlohmann::json& document);

// Throws BadInput (one line) for bytes longer than kMaxSealedBytes or too short to hold a
// checksum, a checksum that does not match, or CBOR that does not parse or nests deeper than
// kMaxSealedDepth.
nlohmann::json unseal_cbor(std::string_view bytes);

}  // namespace multicpg
