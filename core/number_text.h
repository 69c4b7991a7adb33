#pragma once
// Numbers typed by the user on the command line or in a CSV cell, read strictly: the JSON number
// grammar (-?digits[.digits][e[+-]digits]), the whole text, finite. strtod alone would also take
// leading blanks, a '+', hexadecimal, "inf" and "nan", and stop silently at the first stray
// character.
#include <cstdint>
#include <optional>
#include <string_view>

namespace canopy {

/// The finite number `text` spells in JSON's grammar, or nothing.
std::optional<double> strictNumber(std::string_view text);

/// The integer `text` spells as decimal digits with an optional leading '-' (no '+', no blanks,
/// no leading zeros unless it is 0), within [min_value, max_value], or nothing.
std::optional<long long> strictInteger(std::string_view text, long long min_value,
                                       long long max_value);

}  // namespace canopy
