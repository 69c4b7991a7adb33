#pragma once
// Lines of a JSON-lines result file (record.jsonl) read back within bounds: a line's length is
// bounded, its document is built only when the memory it takes can be had, and integers are
// read as 64 bits before they are narrowed.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "spec/json_text.h"

namespace canopy::spec {

/// Longest line of a result file read back: 256 MiB (`canopy run` writes one line per step).
constexpr std::size_t kMaxResultLineBytes = std::size_t{256} << 20;
/// Lines at least this long are counted before they are parsed (below it the check costs more
/// than the at most kJsonBytesPerValue × 2²⁰ bytes such a line's document can take).
constexpr std::size_t kCountedLineBytes = std::size_t{1} << 20;
/// Memory one JSON value of a document takes at most, counted generously: 16 bytes for the value,
/// as much again for the spare capacity of the array holding it, and an object member's node
/// (about 48 bytes) and key.
constexpr std::size_t kJsonBytesPerValue = 96;

/// One line of a result file as a document (parseBoundedJson: depth, duplicate keys), or nullopt
/// when it is not valid JSON within those bounds. A line of kCountedLineBytes or more is first
/// read without building anything, counting its values; when the memory its document needs
/// (kJsonBytesPerValue per value, plus the line again) cannot be had now, std::bad_alloc is
/// thrown before any of it is built. (A document that runs out of memory while it is built is
/// destroyed by the JSON library's destructor, which allocates inside noexcept:
/// std::terminate, an abort instead of "out of memory".) The caller refuses lines longer than
/// kMaxResultLineBytes first.
std::optional<Json> parseResultLine(const std::string& line);

/// `value` as an integer within [lo, hi], read as 64 bits (2³² + 1 is not 1, 2⁶⁴ − 1 is not −1),
/// or nullopt when it is not an integer or lies outside.
std::optional<std::int64_t> integerWithin(const Json& value, std::int64_t lo, std::int64_t hi);

}  // namespace canopy::spec
