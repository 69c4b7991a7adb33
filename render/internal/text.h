#pragma once
// Text geometry from stb_easy_font (ASCII, drawn as axis-aligned boxes; no font file needed).
#include <string>
#include <vector>

#include "core/types.h"

namespace canopy::render::internal {

/// Height of a line in font units: capitals are 7 units high, descenders reach 2 units lower.
inline constexpr double kTextLineHeight = 9.0;

/// Advance width of a line of text, in font units (characters outside printable ASCII count
/// as '?').
double textWidth(const std::string& text);

/// Appends boxes whose union is the text's glyphs; font units, x right, y down, origin at the
/// text's top-left corner.
void textBoxes(const std::string& text, std::vector<Aabb>& out);

}  // namespace canopy::render::internal
