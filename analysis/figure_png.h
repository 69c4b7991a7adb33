#pragma once
// A figure as PNG, drawn by the renderer's OSMesa canvas (no Python, no plotting library).
#include <filesystem>

#include "analysis/figure.h"
#include "analysis/figure_style.h"

namespace canopy::analysis {

/// Draws `figure` and writes it as a PNG; throws std::runtime_error when GL or the file fails.
void writeFigurePng(const Figure& figure, const std::filesystem::path& path);

/// Writes `figure` in `style` as <stem>.svg, <stem>.pdf (figure_pdf.h) and <stem>.png; throws
/// std::runtime_error when a file fails.
void writeFigure(const Figure& figure, const std::filesystem::path& stem,
                 const FigureStyle& style = {});

}  // namespace canopy::analysis
