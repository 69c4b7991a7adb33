#include "scenarios/internal/json_line.h"

#include <array>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace canopy::scenarios::internal {

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
  std::array<char, 64> buffer;  // dump()'s own buffer size
  char* end = nlohmann::detail::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
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

}  // namespace canopy::scenarios::internal
