#pragma once
// One style for every figure canopy draws (issue 51): the series colours, the ink of axes and
// text, the background, and scales for text and lines, read from a JSON file
// (`sweep … --style FILE`, `reproduce --style FILE`; docs/figure-style.json holds the defaults)
// and applied to a finished figure.
#include <array>
#include <filesystem>

#include "analysis/figure.h"

namespace canopy::analysis {

struct FigureStyle {
  std::array<Colour, 8> series;  // seriesColour(0 … 7) by default
  Colour ink = kInk;
  Colour background{255, 255, 255};
  double font_scale = 1.0;  // text sizes × this
  double line_scale = 1.0;  // line widths × this

  FigureStyle();
};

/// The style in `path`: {"series": ["#rrggbb", … up to 8], "ink": "#rrggbb", "background":
/// "#rrggbb", "font_scale": s, "line_scale": s}, every field optional (the default keeps it).
/// Throws spec::ScenarioError (exit code 2) naming the file and the field for anything else:
/// unknown fields, a colour that is not #rrggbb, a scale outside [0.25, 4], more than 8 colours.
FigureStyle readFigureStyle(const std::filesystem::path& path);

/// The figure in `style`: shapes in a default series colour take the style's colour of the same
/// index (their opacity kept), the default ink and background the style's, text sizes and line
/// widths scaled. The default style leaves a figure as it is.
void restyle(Figure& figure, const FigureStyle& style);

}  // namespace canopy::analysis
