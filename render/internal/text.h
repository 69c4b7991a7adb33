#pragma once
// Text geometry: widths from the FreeType font when it is installed (font.h), else from
// stb_easy_font; stb_easy_font's boxes are the fallback glyphs (ASCII; no font file needed).
#include <string>
#include <vector>

#include "core/types.h"

namespace canopy::render::internal {

/// Height of a line in font units: capitals are 7 units high, descenders reach 2 units lower.
inline constexpr double kTextLineHeight = 9.0;

/// Advance width of a line of text, in font units: the font's (font.h), or stb_easy_font's
/// without it (characters outside printable ASCII then count as '?').
double textWidth(const std::string& text);

/// Appends boxes whose union is the text's glyphs; font units, x right, y down, origin at the
/// text's top-left corner.
void textBoxes(const std::string& text, std::vector<Aabb>& out);

}  // namespace canopy::render::internal
