#include "render/internal/deflate.h"

#include <array>
#include <cstring>
#include <stdexcept>

namespace canopy::render::internal {
namespace {

constexpr std::size_t kMinMatch = 3, kMaxMatch = 258, kWindow = 32768;

// Bits go out least-significant first (RFC 1951 §3.1.1).
class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  void put(std::uint32_t bits, int count) {
    buffer_ |= static_cast<std::uint64_t>(bits) << used_;
    used_ += count;
    while (used_ >= 8) {
      out_.push_back(static_cast<std::uint8_t>(buffer_));
      buffer_ >>= 8;
      used_ -= 8;
    }
  }
  void flush() {
    if (used_ > 0) put(0, 8 - used_);
  }

 private:
  std::vector<std::uint8_t>& out_;
  std::uint64_t buffer_ = 0;
  int used_ = 0;
};

std::uint32_t reversed(std::uint32_t code, int length) {
  std::uint32_t r = 0;
  for (int i = 0; i < length; ++i) r |= ((code >> i) & 1u) << (length - 1 - i);
  return r;
}

struct Code {
  std::uint32_t bits = 0;  // already reversed for the LSB-first stream
  int length = 0;
};

// The fixed literal/length code (RFC 1951 §3.2.6): 0–143 → 8 bits from 0x30, 144–255 → 9 bits
// from 0x190, 256–279 → 7 bits from 0, 280–287 → 8 bits from 0xC0.
std::array<Code, 288> fixedLiteralCodes() {
  std::array<Code, 288> codes{};
  for (std::uint32_t v = 0; v < 288; ++v) {
    std::uint32_t code = 0;
    int length = 0;
    if (v < 144) {
      code = 0x30 + v, length = 8;
    } else if (v < 256) {
      code = 0x190 + v - 144, length = 9;
    } else if (v < 280) {
      code = v - 256, length = 7;
    } else {
      code = 0xC0 + v - 280, length = 8;
    }
    codes[v] = {reversed(code, length), length};
  }
  return codes;
}

// Length 3..258 → symbol 257..285 with extra bits (RFC 1951 §3.2.5).
constexpr std::array<std::uint16_t, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                                       15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                                       67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<std::uint8_t, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<std::uint16_t, 30> kDistanceBase = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};

// One distance's code, its reversed 5-bit symbol and extra bits, written as a single put.
struct DistanceCode {
  std::uint32_t bits = 0;
  int length = 0;
};

DistanceCode distanceCode(std::size_t distance) {
  int symbol = 29;
  while (kDistanceBase[static_cast<std::size_t>(symbol)] > distance) --symbol;
  const int extra = symbol < 4 ? 0 : symbol / 2 - 1;
  const auto offset =
      static_cast<std::uint32_t>(distance - kDistanceBase[static_cast<std::size_t>(symbol)]);
  return {reversed(static_cast<std::uint32_t>(symbol), 5) | (offset << 5), 5 + extra};
}

// How many bytes from `at` repeat those `distance` back, up to `limit`; 8 bytes at a time.
std::size_t matchLength(const std::uint8_t* at, std::size_t distance, std::size_t limit) {
  std::size_t n = 0;
  while (n + 8 <= limit) {
    std::uint64_t a, b;
    std::memcpy(&a, at + n, 8);
    std::memcpy(&b, at + n - distance, 8);
    if (a != b) return n + static_cast<std::size_t>(__builtin_ctzll(a ^ b) / 8);
    n += 8;
  }
  while (n < limit && at[n] == at[n - distance]) ++n;
  return n;
}

std::uint32_t adler32(std::span<const std::uint8_t> data) {
  constexpr std::uint32_t kMod = 65521;
  std::uint32_t a = 1, b = 0;
  std::size_t i = 0;
  while (i < data.size()) {
    // 5552 bytes is the most that cannot overflow b before the modulo (zlib's NMAX).
    const std::size_t end = std::min(data.size(), i + 5552);
    for (; i < end; ++i) {
      a += data[i];
      b += a;
    }
    a %= kMod;
    b %= kMod;
  }
  return (b << 16) | a;
}

}  // namespace

std::vector<std::uint8_t> zlibCompress(std::span<const std::uint8_t> data, std::size_t pixel_bytes,
                                       std::size_t row_bytes) {
  if (pixel_bytes == 0 || row_bytes > kWindow)
    throw std::invalid_argument("zlibCompress: bad strides");
  static const std::array<Code, 288> literal = fixedLiteralCodes();
  // Symbol and extra bits of every match length, indexed by length.
  static const std::array<Code, kMaxMatch + 1> length_code = [] {
    std::array<Code, kMaxMatch + 1> codes{};
    for (std::size_t len = kMinMatch; len <= kMaxMatch; ++len) {
      std::size_t s = 28;
      while (kLengthBase[s] > len) --s;
      const Code& c = literal[257 + s];
      codes[len] = {c.bits | (static_cast<std::uint32_t>(len - kLengthBase[s]) << c.length),
                    c.length + kLengthExtra[s]};
    }
    return codes;
  }();
  const std::size_t distances[2] = {pixel_bytes, row_bytes};
  const DistanceCode distance_codes[2] = {distanceCode(pixel_bytes), distanceCode(row_bytes)};

  std::vector<std::uint8_t> out;
  out.reserve(data.size() / 8 + 64);
  out.push_back(0x78);  // CMF: deflate, 32 KiB window
  out.push_back(0x01);  // FLG: fastest level, no dictionary; (CMF·256 + FLG) mod 31 = 0
  BitWriter bits(out);
  bits.put(0b011, 3);  // BFINAL = 1, BTYPE = 01 (fixed Huffman)
  const std::uint8_t* p = data.data();
  const std::size_t n = data.size();
  std::size_t i = 0;
  while (i < n) {
    std::size_t best = 0, which = 0;
    const std::size_t limit = std::min(kMaxMatch, n - i);
    for (std::size_t k = 0; k < 2; ++k) {
      if (i < distances[k] || limit < kMinMatch) continue;
      const std::size_t len = matchLength(p + i, distances[k], limit);
      if (len > best) best = len, which = k;
    }
    if (best >= kMinMatch) {
      const Code& lc = length_code[best];
      bits.put(lc.bits, lc.length);
      bits.put(distance_codes[which].bits, distance_codes[which].length);
      i += best;
    } else {
      const Code& c = literal[p[i]];
      bits.put(c.bits, c.length);
      ++i;
    }
  }
  bits.put(literal[256].bits, literal[256].length);  // end of block
  bits.flush();
  const std::uint32_t check = adler32(data);
  for (const int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::uint8_t>(check >> shift));
  return out;
}

std::uint32_t crc32(std::span<const std::uint8_t> data, std::uint32_t crc) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1u ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (const std::uint8_t byte : data) crc = table[(crc ^ byte) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

}  // namespace canopy::render::internal
