#pragma once
// The byte coding of the compact record's step columns (step_columns.h): unsigned integers as
// LEB128 varints (7 bits a byte, low first), signed ones zigzag-mapped first (0, −1, 1, −2, … →
// 0, 1, 2, 3, …), doubles as their 8 bytes little-endian, optionally XORed with a previous value's
// bits (equal leading bits become zero bytes). Reading never runs past its bytes: a short or
// malformed column throws std::runtime_error.
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace canopy::sim {

static_assert(std::endian::native == std::endian::little, "the record's columns are little-endian");

class ColumnOut {
 public:
  void u(std::uint64_t v) {
    while (v >= 0x80) {
      bytes_ += static_cast<char>((v & 0x7F) | 0x80);
      v >>= 7;
    }
    bytes_ += static_cast<char>(v);
  }
  void i(std::int64_t v) {  // zigzag: 2v for v ≥ 0, −2v − 1 below
    u((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
  }
  void d(double v) { bits(std::bit_cast<std::uint64_t>(v)); }
  /// v's bits XOR previous's.
  void dx(double v, double previous) {
    bits(std::bit_cast<std::uint64_t>(v) ^ std::bit_cast<std::uint64_t>(previous));
  }
  std::string& bytes() { return bytes_; }
  std::size_t size() const { return bytes_.size(); }

 private:
  void bits(std::uint64_t b) {
    char raw[8];
    std::memcpy(raw, &b, 8);
    bytes_.append(raw, 8);
  }
  std::string bytes_;
};

class ColumnIn {
 public:
  ColumnIn() = default;
  ColumnIn(std::string_view bytes, const char* name) : bytes_(bytes), name_(name) {}

  std::uint64_t u() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (at_ >= bytes_.size()) fail("ends inside a number");
      const auto byte = static_cast<unsigned char>(bytes_[at_++]);
      v |= std::uint64_t{byte & 0x7Fu} << shift;
      if ((byte & 0x80u) == 0) return v;
    }
    fail("a number over 64 bits");
  }
  std::int64_t i() {
    const std::uint64_t z = u();
    return static_cast<std::int64_t>(z >> 1) ^ -static_cast<std::int64_t>(z & 1);
  }
  /// An int within [lo, hi].
  int bounded(long long lo, long long hi, const char* what) {
    const std::int64_t v = i();
    if (v < lo || v > hi) fail(std::string("a ") + what + " out of range");
    return static_cast<int>(v);
  }
  /// A count of items that take at least `min_bytes` each of this column's remaining bytes.
  std::size_t count(std::size_t min_bytes = 1) {
    const std::uint64_t n = u();
    if (n > (bytes_.size() - at_) / min_bytes) fail("a count larger than its bytes");
    return static_cast<std::size_t>(n);
  }
  /// A count of items whose values take `bytes_each` of `values`' remaining bytes.
  std::size_t countOf(const ColumnIn& values, std::size_t bytes_each) {
    const std::uint64_t n = u();
    if (n > values.remaining() / bytes_each) fail("a count larger than its values' bytes");
    return static_cast<std::size_t>(n);
  }
  /// The next n bytes as they are.
  std::string_view raw(std::size_t n) {
    if (n > remaining()) fail("ends inside a text");
    const std::string_view out = bytes_.substr(at_, n);
    at_ += n;
    return out;
  }
  double d() { return std::bit_cast<double>(bits()); }
  double dx(double previous) {
    return std::bit_cast<double>(bits() ^ std::bit_cast<std::uint64_t>(previous));
  }
  std::size_t remaining() const { return bytes_.size() - at_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(std::string("column ") + name_ + ": " + what);
  }

 private:
  std::uint64_t bits() {
    if (bytes_.size() - at_ < 8) fail("ends inside a number");
    std::uint64_t b = 0;
    std::memcpy(&b, bytes_.data() + at_, 8);
    at_ += 8;
    return b;
  }
  std::string_view bytes_;
  const char* name_ = "";
  std::size_t at_ = 0;
};

}  // namespace canopy::sim
