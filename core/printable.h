#pragma once
// Text from outside (file content, names, command-line values) made safe to show on a terminal.
#include <cstddef>
#include <string>
#include <string_view>

namespace canopy {

/// `text` with every control character and every byte that is not part of valid UTF-8 written as
/// \n, \t, \r or \xNN, cut to at most `max_chars` source bytes with
/// "..." after the cut. Valid multi-byte UTF-8 passes unchanged.
std::string printable(std::string_view text, std::size_t max_chars = std::string_view::npos);

}  // namespace canopy
