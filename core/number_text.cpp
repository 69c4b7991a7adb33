#include "core/number_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace canopy {
namespace {

bool digit(char c) {
  return c >= '0' && c <= '9';
}

// Advances `i` over one or more digits; false when there is none.
bool digits(std::string_view text, std::size_t& i) {
  const std::size_t start = i;
  while (i < text.size() && digit(text[i])) ++i;
  return i > start;
}

}  // namespace

std::optional<double> strictNumber(std::string_view text) {
  if (text.empty() || text.size() > 400) return std::nullopt;
  std::size_t i = 0;
  if (text[i] == '-') ++i;
  if (i < text.size() && text[i] == '0') {
    ++i;
  } else if (!digits(text, i)) {
    return std::nullopt;
  }
  if (i < text.size() && text[i] == '.') {
    ++i;
    if (!digits(text, i)) return std::nullopt;
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (!digits(text, i)) return std::nullopt;
  }
  if (i != text.size()) return std::nullopt;
  const std::string copy(text);  // strtod needs the terminating NUL
  const double x = std::strtod(copy.c_str(), nullptr);
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

std::optional<long long> strictInteger(std::string_view text, long long min_value,
                                       long long max_value) {
  std::size_t i = text.empty() || text[0] != '-' ? 0 : 1;
  if (i >= text.size() || !digit(text[i])) return std::nullopt;
  if (text[i] == '0' && text.size() > i + 1) return std::nullopt;  // 007
  long long x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (x < min_value || x > max_value) return std::nullopt;
  return x;
}

}  // namespace canopy
