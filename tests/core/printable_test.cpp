#include "core/printable.h"

#include <gtest/gtest.h>

namespace canopy {
namespace {

TEST(Printable, PlainAsciiPassesUnchanged) {
  EXPECT_EQ(printable("uavs[0].fov: 12 m"), "uavs[0].fov: 12 m");
}

TEST(Printable, ControlCharactersAreEscaped) {
  EXPECT_EQ(printable("a\nb\tc\rd"), "a\\nb\\tc\\rd");
  EXPECT_EQ(printable(std::string("\x1b[31mred", 8)), "\\x1B[31mred");
  EXPECT_EQ(printable(std::string("nul\0x", 5)), "nul\\x00x");
  EXPECT_EQ(printable("\x7f"), "\\x7F");
}

TEST(Printable, ValidUtf8PassesAndInvalidBytesAreEscaped) {
  EXPECT_EQ(printable("Ålesund τ 🌲"), "Ålesund τ 🌲");
  EXPECT_EQ(printable("\xC3"), "\\xC3");              // a lead byte without its continuation
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");     // overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a UTF-16 surrogate, U+D800
  EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
}

TEST(Printable, LongTextIsCut) {
  EXPECT_EQ(printable("abcdefgh", 3), "abc...");
  EXPECT_EQ(printable("abc", 3), "abc");
}

}  // namespace
}  // namespace canopy
