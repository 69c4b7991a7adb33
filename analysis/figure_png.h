#pragma once
// A figure as PNG, drawn by the renderer's OSMesa canvas (no Python, no plotting library).
#include <filesystem>

#include "analysis/figure.h"

namespace canopy::analysis {

/// Draws `figure` and writes it as a PNG; throws std::runtime_error when GL or the file fails.
void writeFigurePng(const Figure& figure, const std::filesystem::path& path);

}  // namespace canopy::analysis
