#pragma once
// Typed columns of the replay page's data (replay_data.cpp): little-endian Int32 and Float32
// arrays laid one after another, described by name, type, offset and count in the data's JSON
// header; the page reads each as a typed array (web/columns.js).
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "replay/packed_json.h"

namespace canopy::replay {

/// The Int32 a column holds for a missing number (a non-finite one); the page reads it as NaN.
inline constexpr std::int32_t kMissing = std::numeric_limits<std::int32_t>::min();

/// round(x * scale) as an Int32 (kMissing when x is not finite or out of the Int32 range): a
/// position in centimetres with scale 100, a heading in milliradians with 1000.
inline std::int32_t fixedPoint(double x, double scale) {
  const double v = std::round(x * scale);
  if (!std::isfinite(v) || v <= static_cast<double>(kMissing) ||
      v > static_cast<double>(std::numeric_limits<std::int32_t>::max()))
    return kMissing;
  return static_cast<std::int32_t>(v);
}

/// x to kSignificantDigits significant digits, as the nearest Float32 (NaN stays NaN).
inline float significantFloat(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<float>::quiet_NaN();
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", kSignificantDigits, x);
  return static_cast<float>(std::strtod(buffer, nullptr));
}

class Columns {
 public:
  /// Adds a column of Int32s; with `delta`, each value but the first of every run of `stride`
  /// values is stored as its difference from the one before (positions over time: small
  /// numbers, which compress well; the page adds them up again).
  void int32(const std::string& name, const std::vector<std::int32_t>& values,
             std::size_t stride = 0) {
    add(name, stride ? "i32delta" : "i32", values.size(), stride);
    for (std::size_t n = 0; n < values.size(); ++n) {
      const bool first = stride == 0 || n % stride == 0;
      const std::int32_t v =
          first ? values[n]
                : static_cast<std::int32_t>(static_cast<std::uint32_t>(values[n]) -
                                            static_cast<std::uint32_t>(values[n - 1]));
      word(static_cast<std::uint32_t>(v));
    }
  }
  void float32(const std::string& name, const std::vector<float>& values) {
    add(name, "f32", values.size(), 0);
    for (float v : values) word(std::bit_cast<std::uint32_t>(v));
  }

  /// ,"columns":[{"name":…,"type":"i32"|"i32delta"|"f32","offset":bytes,"count":n,"stride":s},…]
  void describe(Writer& w) const {
    w.raw(",\"columns\":[");
    bool first = true;
    for (const Column& c : list_) {
      w.comma(first);
      w.raw("{\"name\":");
      w.string(c.name);
      w.raw(",\"type\":");
      w.string(c.type);
      w.raw(",\"offset\":");
      w.integer(static_cast<long long>(c.offset));
      w.raw(",\"count\":");
      w.integer(static_cast<long long>(c.count));
      w.raw(",\"stride\":");
      w.integer(static_cast<long long>(c.stride));
      w.raw("}");
    }
    w.raw("]");
  }
  const std::string& bytes() const { return bytes_; }

 private:
  struct Column {
    std::string name, type;
    std::size_t offset, count, stride;
  };
  void add(const std::string& name, const char* type, std::size_t count, std::size_t stride) {
    list_.push_back({name, type, bytes_.size(), count, stride});
  }
  void word(std::uint32_t v) {  // little-endian whatever the machine
    for (int shift = 0; shift < 32; shift += 8) bytes_ += static_cast<char>(v >> shift & 0xffu);
  }
  std::vector<Column> list_;
  std::string bytes_;
};

}  // namespace canopy::replay
