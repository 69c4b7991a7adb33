#pragma once
// Text from outside (file content, names, command-line values) made safe to show on a terminal.
#include <cstddef>
#include <string>
#include <string_view>

namespace canopy {

/// `text` with every control character (C0, DEL and the C1 range U+0080..U+009F) and every byte
/// that is not part of valid UTF-8 written as \n, \t, \r or \xNN (byte by byte), cut to at most
/// `max_chars` source bytes with "..." after the cut. Other valid multi-byte UTF-8 passes
/// unchanged.
std::string printable(std::string_view text, std::size_t max_chars = std::string_view::npos);

/// Whether `text` is well-formed UTF-8 (RFC 3629: no overlongs, no surrogates, at most U+10FFFF).
bool isValidUtf8(std::string_view text);

}  // namespace canopy
