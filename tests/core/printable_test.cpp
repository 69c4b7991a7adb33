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
  EXPECT_EQ(printable("\xC3"), "\\xC3");                    // a lead byte without its continuation
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");           // overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a UTF-16 surrogate, U+D800
  EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
}

TEST(Printable, C1ControlsAreEscapedThoughValidUtf8) {
  EXPECT_EQ(printable("\xC2\x9B"
                      "2J"),
            "\\xC2\\x9B2J");                       // U+009B, CSI in some terminals
  EXPECT_EQ(printable("\xC2\x85"), "\\xC2\\x85");  // U+0085, next line
  EXPECT_EQ(printable("\xC2\xA0"), "\xC2\xA0");    // U+00A0 is not a control: kept
}

TEST(Printable, ValidUtf8IsRecognised) {
  EXPECT_TRUE(isValidUtf8(""));
  EXPECT_TRUE(isValidUtf8("Ålesund τ 🌲"));
  EXPECT_TRUE(isValidUtf8(std::string("nul\0", 4)));  // controls are valid UTF-8
  EXPECT_FALSE(isValidUtf8("bad\xFF"));
  EXPECT_FALSE(isValidUtf8("\xC3"));
  EXPECT_FALSE(isValidUtf8("\xC0\xAF"));
  EXPECT_FALSE(isValidUtf8("\xED\xA0\x80"));
}

TEST(Printable, LongTextIsCut) {
  EXPECT_EQ(printable("abcdefgh", 3), "abc...");
  EXPECT_EQ(printable("abc", 3), "abc");
}

}  // namespace
}  // namespace canopy
