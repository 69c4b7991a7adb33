#pragma once
// An enum's spelling in scenario files, declared once beside the enum: the loader reads it, the
// effective config writes it, and a default is the config struct's own value, never an index
// into a list of strings.
#include <array>
#include <cstddef>
#include <string_view>

namespace canopy {

template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

template <class Enum, std::size_t N>
using EnumNames = std::array<EnumName<Enum>, N>;

/// The spelling of `value`; empty when the table lacks it (a table covers every value, which
/// tests/core/enum_names_test.cpp checks for each table).
template <class Enum, std::size_t N>
constexpr std::string_view nameOf(const EnumNames<Enum, N>& names, Enum value) {
  for (const EnumName<Enum>& entry : names) {
    if (entry.value == value) return entry.name;
  }
  return {};
}

}  // namespace canopy
