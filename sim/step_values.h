#pragma once
// The recorded values of an occlusion-map entry and of a track, in the order the record writes
// them (record_line.cpp): the covariance's upper triangle row by row, the mean, then a tree's
// outline offsets or a track's existence. Shared by the compact record's encoder and decoder
// (step_columns.h), so both gather and scatter the same values.
#include <array>
#include <cstring>

#include "agents/belief.h"

namespace canopy::sim {

inline constexpr int kTreeValues = 6 + 3 + 2 * sensing::Outline::kMaxVertices;
inline constexpr int kTrackValues = 10 + 4 + 1;

using TreeValues = std::array<double, kTreeValues>;
using TrackValues = std::array<double, kTrackValues>;

template <int N, typename Values>
int gatherGaussian(const agents::Gaussian<N>& g, Values& v) {
  int n = 0;
  for (int r = 0; r < N; ++r) {
    for (int c = r; c < N; ++c) v[static_cast<std::size_t>(n++)] = g.P(r, c);
  }
  for (int r = 0; r < N; ++r) v[static_cast<std::size_t>(n++)] = g.x(r);
  return n;
}
template <int N, typename Values>
int scatterGaussian(const Values& v, agents::Gaussian<N>& g) {
  int n = 0;
  for (int r = 0; r < N; ++r) {
    for (int c = r; c < N; ++c) g.P(r, c) = g.P(c, r) = v[static_cast<std::size_t>(n++)];
  }
  for (int r = 0; r < N; ++r) g.x(r) = v[static_cast<std::size_t>(n++)];
  return n;
}

/// A tree entry's values; returns how many (9 + 2 per outline vertex).
inline int gather(const agents::TreeEstimate& t, TreeValues& v) {
  int n = gatherGaussian(t.belief, v);
  for (int k = 0; k < t.outline.vertices; ++k) {
    v[static_cast<std::size_t>(n++)] = t.outline.offsets[static_cast<std::size_t>(k)].x();
    v[static_cast<std::size_t>(n++)] = t.outline.offsets[static_cast<std::size_t>(k)].y();
  }
  return n;
}
/// Sets t's values from v (t.outline.vertices set already).
inline void scatter(const TreeValues& v, agents::TreeEstimate& t) {
  int n = scatterGaussian(v, t.belief);
  for (int k = 0; k < t.outline.vertices; ++k) {
    t.outline.offsets[static_cast<std::size_t>(k)].x() = v[static_cast<std::size_t>(n++)];
    t.outline.offsets[static_cast<std::size_t>(k)].y() = v[static_cast<std::size_t>(n++)];
  }
}
inline int gather(const agents::TrackEstimate& t, TrackValues& v) {
  const int n = gatherGaussian(t.belief, v);
  v[static_cast<std::size_t>(n)] = t.existence;
  return n + 1;
}
inline void scatter(const TrackValues& v, agents::TrackEstimate& t) {
  const int n = scatterGaussian(v, t.belief);
  t.existence = v[static_cast<std::size_t>(n)];
}

/// The first n values of a and b have the same bits.
template <typename Values>
bool sameBits(const Values& a, const Values& b, int n) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(n)) == 0;
}

}  // namespace canopy::sim
