#pragma once
// A zlib stream (RFC 1950) of one fixed-Huffman DEFLATE block (RFC 1951) for rendered images:
// LZ77 matches are sought only one pixel back and one row back. Frames are mostly flat colour
// and repeated rows, so this finds nearly every match a general compressor would, in linear
// time with no hash tables.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace canopy::render::internal {

/// Compresses `data` (rows of `row_bytes` bytes, pixels of `pixel_bytes`) into a zlib stream.
/// Needs row_bytes ≤ 32768 (DEFLATE's window). Deterministic.
std::vector<std::uint8_t> zlibCompress(std::span<const std::uint8_t> data, std::size_t pixel_bytes,
                                       std::size_t row_bytes);

/// CRC-32 (ISO-HDLC, as PNG uses) of `data`, continuing from `crc` (0 to start).
std::uint32_t crc32(std::span<const std::uint8_t> data, std::uint32_t crc = 0);

}  // namespace canopy::render::internal
