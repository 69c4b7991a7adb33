#pragma once
// A frame's scene as a vector document (SVG or PDF) through cairo (Debian libcairo2-dev): the
// same primitives the canvas rasterises, for a paper's figure (issue 51, `run --frames --format`).
#include <string>

#include "render/scene.h"

namespace canopy::render {

enum class VectorFormat { svg, pdf };

/// The scene as one page of scene.viewport.size px (1 px = 1 pt in a PDF), drawn in the canvas'
/// order: world primitives (metres through the viewport), then the overlay (px), then every text
/// on top (DejaVu Sans, an em of 8·scale px, the top-left corner at the text's position, as the
/// canvas places it). The same scene gives the same bytes. Throws std::runtime_error when cairo
/// fails.
std::string sceneToVector(const Scene& scene, VectorFormat format);

/// The dart an arrow marker draws (px, centre c, half size h, heading ψ counter-clockwise from +x
/// on the image): tip, left barb, notch, right barb.
std::vector<Vec2> arrowDart(const Vec2& c, double h, double heading);

}  // namespace canopy::render
