#include "sim/json_line.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace canopy::sim {
namespace {

/// Writes the finite `value` at `out` in dump()'s layout and returns the end (at most 25 chars).
/// The digits are the shortest that read back exactly (std::to_chars, Ryu: the closest such);
/// the layout is nlohmann's format_buffer with its limits (min_exp = −4, max_exp = 15):
/// k digits d₁…d_k and decimal point position n (value = 0.d₁…d_k · 10ⁿ) give
///   "ddd000.0" (k ≤ n ≤ 15), "dd.dd" (0 < n ≤ 15), "0.000dd" (−4 < n ≤ 0), else "d.ddde±XX".
char* formatDouble(char* out, double value) {
  if (std::signbit(value)) {
    *out++ = '-';
    value = -value;
  }
  if (value == 0.0) {  // dump(): 0.0 and -0.0
    std::memcpy(out, "0.0", 4);
    return out + 3;
  }
  char sci[32];  // "d.ddde±XX" or "d.ddde±XXX"
  const char* end = std::to_chars(sci, sci + sizeof sci, value, std::chars_format::scientific).ptr;
  const bool three = end[-4] != 'e';  // a three-digit exponent
  const char* e = end - (three ? 5 : 4);
  int exponent = (e[2] - '0') * 10 + (e[3] - '0');  // value = d₁.d₂… · 10^exponent
  if (three) exponent = exponent * 10 + (e[4] - '0');
  if (e[1] == '-') exponent = -exponent;
  // The digits d₁…d_k contiguous: d₁ moves right onto the point.
  char* digits = sci;
  int k = 1;
  if (e != sci + 1) {
    sci[1] = sci[0];
    digits = sci + 1;
    k = static_cast<int>(e - digits);
  }
  const int n = exponent + 1;
  constexpr int kMinExp = -4, kMaxExp = 15;
  if (0 < n && n <= kMaxExp) {
    if (k <= n) {  // "ddd000.0"
      for (int i = 0; i < k; ++i) *out++ = digits[i];
      for (int i = k; i < n; ++i) *out++ = '0';
      *out++ = '.';
      *out++ = '0';
      return out;
    }
    for (int i = 0; i < n; ++i) *out++ = digits[i];  // "dd.dd"
    *out++ = '.';
    for (int i = n; i < k; ++i) *out++ = digits[i];
    return out;
  }
  if (kMinExp < n && n <= 0) {  // "0.000dd"
    *out++ = '0';
    *out++ = '.';
    for (int i = n; i < 0; ++i) *out++ = '0';
    for (int i = 0; i < k; ++i) *out++ = digits[i];
    return out;
  }
  *out++ = digits[0];  // "d.ddde±XX": nlohmann's append_exponent, a sign and ≥ 2 digits
  if (k > 1) {
    *out++ = '.';
    for (int i = 1; i < k; ++i) *out++ = digits[i];
  }
  *out++ = 'e';
  *out++ = exponent < 0 ? '-' : '+';
  int magnitude = exponent < 0 ? -exponent : exponent;
  if (magnitude >= 100) {
    *out++ = static_cast<char>('0' + magnitude / 100);
    magnitude %= 100;
  }
  *out++ = static_cast<char>('0' + magnitude / 10);
  *out++ = static_cast<char>('0' + magnitude % 10);
  return out;
}

constexpr std::uint64_t kNoDouble = 0x7ff8'0000'0000'0001;  // a NaN: never looked up

}  // namespace

DoubleTextCache::DoubleTextCache() {
  for (Slot& slot : slots_) {
    slot.bits = kNoDouble;
    slot.length = 0;
  }
}

std::string_view DoubleTextCache::text(double value) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
  // Fibonacci hashing: the top bits of bits · 2⁶⁴/φ.
  Slot& slot = slots_[(bits * 0x9e3779b97f4a7c15ULL) >> (64 - kSlotBits)];
  if (slot.bits != bits) {
    slot.bits = bits;
    slot.length = static_cast<std::uint8_t>(formatDouble(slot.chars, value) - slot.chars);
  }
  return {slot.chars, slot.length};
}

void JsonLine::separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (depth_ == 0) return;
  const std::uint64_t bit = std::uint64_t{1} << (depth_ - 1);
  if (has_member_ & bit) out_ += ',';
  has_member_ |= bit;
}

void JsonLine::open(char bracket) {
  separate();
  out_ += bracket;
  if (depth_ == 64) throw std::logic_error("JsonLine: nested deeper than 64");
  ++depth_;
  has_member_ &= ~(std::uint64_t{1} << (depth_ - 1));
}

void JsonLine::close(char bracket) {
  if (depth_ == 0 || after_key_) throw std::logic_error("JsonLine: close without an open value");
  --depth_;
  out_ += bracket;
}

void JsonLine::key(std::string_view name) {
  separate();
  out_ += '"';
  out_ += name;
  out_ += "\":";
  after_key_ = true;
}

void JsonLine::number(double value) {
  separate();
  if (!std::isfinite(value)) {  // dump() writes NaN and ±inf as null
    out_ += "null";
    return;
  }
  if (cache_ != nullptr) {
    out_ += cache_->text(value);
    return;
  }
  std::array<char, 64> buffer;
  const char* end = formatDouble(buffer.data(), value);
  out_.append(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
}

void JsonLine::integer(long long value) {
  separate();
  std::array<char, 24> buffer;
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out_.append(buffer.data(), static_cast<std::size_t>(result.ptr - buffer.data()));
}

void JsonLine::boolean(bool value) {
  separate();
  out_ += value ? "true" : "false";
}

void JsonLine::escapedString(std::string_view quoted) {
  separate();
  out_ += quoted;
}

std::string JsonLine::escaped(const std::string& text) {
  return nlohmann::json(text).dump();
}

}  // namespace canopy::sim
