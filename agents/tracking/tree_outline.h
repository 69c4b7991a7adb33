#pragma once
// A tree track's outline estimate: the running mean of the outlines measured with it, vertex by
// vertex (each measured offset carries independent noise, so the mean's error falls as 1/√n).
#include "sensing/outline.h"

namespace canopy::agents::tracking {

struct TreeOutline {
  sensing::Outline mean;  // m, mean vertex offsets (vertices = 0: none measured yet)
  int observations = 0;   // outlines averaged into `mean`

  /// Averages `measured` in; an outline with another vertex count (a different crown) or none is
  /// ignored.
  void observe(const sensing::Outline& measured) {
    if (measured.vertices == 0) return;
    if (observations == 0) {
      mean = measured;
      observations = 1;
      return;
    }
    if (measured.vertices != mean.vertices) return;
    ++observations;
    for (int v = 0; v < mean.vertices; ++v) {  // x̄_n = x̄_{n−1} + (x_n − x̄_{n−1}) / n
      mean.offsets[v] += (measured.offsets[v] - mean.offsets[v]) / observations;
    }
  }
};

/// Targets carry no outline.
struct NoOutline {};

}  // namespace canopy::agents::tracking
