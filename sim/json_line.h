#pragma once
// A JSON text written straight into a string, value by value, without a document object: the
// record's per-step line (recorder.cpp). Its format is nlohmann::json::dump()'s (compact, no
// spaces; numbers laid out as dump() lays them out, non-finite doubles as null, integers in
// decimal), but a double's digits are the shortest that read back exactly (std::to_chars), where
// dump()'s Grisu2 sometimes writes one digit more. Keys are the caller's literals and must be
// written in dump()'s order (sorted by byte); strings from user files go through dump() itself
// (JsonLine::escaped).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace canopy::sim {

/// The text of recently written doubles, by bit pattern: a record writes the same values many
/// times a step (after consensus every agent holds the same fused tracks), and formatting one
/// costs about 540 instructions (callgrind, peer_poisson_h1) where a hit is a hash and a compare.
/// Direct-mapped: a new value takes its slot. Only ever returns the text formatted for its bits.
class DoubleTextCache {
 public:
  DoubleTextCache();
  /// The text of `value` (finite) in dump()'s layout, formatted on a miss.
  std::string_view text(double value);

 private:
  static constexpr int kSlotBits = 12;
  struct Slot {
    std::uint64_t bits;  // the double's bit pattern (initially a NaN no finite value has)
    std::uint8_t length;
    char chars[32];
  };
  std::array<Slot, 1 << kSlotBits> slots_;
};

class JsonLine {
 public:
  /// Appends to `out` (which it does not clear). `cache`: optional, kept by the caller across
  /// lines; the text is the same with or without it.
  explicit JsonLine(std::string& out, DoubleTextCache* cache = nullptr)
      : out_(out), cache_(cache) {}

  void beginObject() { open('{'); }
  void endObject() { close('}'); }
  void beginArray() { open('['); }
  void endArray() { close(']'); }
  /// An object's key: a plain literal that needs no escaping. The next value belongs to it.
  void key(std::string_view name);

  void number(double value);
  void integer(long long value);
  void boolean(bool value);
  /// A string value already escaped and quoted (see escaped()).
  void escapedString(std::string_view quoted);

  /// `text` as dump() writes a JSON string: quoted and escaped; throws nlohmann's type_error 316
  /// on invalid UTF-8, as dump() does.
  static std::string escaped(const std::string& text);

 private:
  void separate();
  void open(char bracket);
  void close(char bracket);

  std::string& out_;
  DoubleTextCache* cache_;
  std::uint64_t has_member_ = 0;  // bit d: the open container at depth d holds a value already
  int depth_ = 0;
  bool after_key_ = false;
};

}  // namespace canopy::sim
