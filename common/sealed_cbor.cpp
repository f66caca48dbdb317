#include "common/sealed_cbor.h"

#include <array>
#include <cstdint>

#include "common/checksum.h"
#include "common/errors.h"

namespace multicpg {
namespace {

using Json = nlohmann::json;
constexpr std::size_t kChecksumBytes = sizeof(std::uint64_t);

std::array<char, kChecksumBytes> checksum_bytes(std::string_view payload) {
  const std::uint64_t sum = fnv1a64(payload);
  std::array<char, kChecksumBytes> out{};
  for (std::size_t i = 0; i < kChecksumBytes; ++i) {
    out[i] = static_cast<char>((sum >> (8 * i)) & 0xffU);  // little-endian on every host
  }
  return out;
}

// nlohmann's DOM builder, refusing to open a level past kMaxSealedDepth (a refusal stops the
// reader before it recurses further). The builder is nlohmann's own (a detail class, but the
// one json::from_cbor uses), so only the depth count is ours.
class BoundedDom {
 public:
  explicit BoundedDom(Json& root) : dom_(root) {}

  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(Json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(Json::number_float_t v, const Json::string_t& s) {
    return dom_.number_float(v, s);
  }
  bool string(Json::string_t& v) { return dom_.string(v); }
  bool binary(Json::binary_t& v) { return dom_.binary(v); }
  bool start_object(std::size_t n) { return open() && dom_.start_object(n); }
  bool key(Json::string_t& v) { return dom_.key(v); }
  bool end_object() {
    --depth_;
    return dom_.end_object();
  }
  bool start_array(std::size_t n) { return open() && dom_.start_array(n); }
  bool end_array() {
    --depth_;
    return dom_.end_array();
  }
  bool parse_error(std::size_t position, const std::string& token,
                   const nlohmann::detail::exception& e) {
    return dom_.parse_error(position, token, e);
  }
  bool too_deep() const { return depth_ > kMaxSealedDepth; }

 private:
  bool open() { return ++depth_ <= kMaxSealedDepth; }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  int depth_ = 0;
};

}  // namespace

std::string seal_cbor(const Json& document) {
  std::string out;
  Json::to_cbor(document, out);
  const std::array<char, kChecksumBytes> sum = checksum_bytes(out);
  out.append(sum.data(), sum.size());
  return out;
}

Json unseal_cbor(std::string_view bytes) {
  if (bytes.size() > kMaxSealedBytes) {
    throw BadInput("the sealed document is " + std::to_string(bytes.size()) +
                   " bytes, more than the " + std::to_string(kMaxSealedBytes) + " allowed");
  }
  if (bytes.size() <= kChecksumBytes) throw BadInput("the sealed document is truncated");
  const std::string_view payload = bytes.substr(0, bytes.size() - kChecksumBytes);
  const std::array<char, kChecksumBytes> sum = checksum_bytes(payload);
  if (bytes.substr(payload.size()) != std::string_view(sum.data(), sum.size())) {
    throw BadInput("the sealed document is damaged (its checksum does not match)");
  }
  Json document;
  BoundedDom dom(document);
  bool parsed = false;
  try {
    parsed = Json::sax_parse(payload.begin(), payload.end(), &dom, Json::input_format_t::cbor);
  } catch (const Json::exception& e) {
    throw BadInput(std::string("the sealed document is not CBOR: ") + e.what());
  }
  if (dom.too_deep()) {
    throw BadInput("the sealed document nests deeper than " + std::to_string(kMaxSealedDepth) +
                   " levels");
  }
  if (!parsed) throw BadInput("the sealed document is not CBOR");
  return document;
}

}  // namespace multicpg
