#pragma once
// The data a replay page embeds: a run folder packed as a JSON header (the scenario, the agents,
// the sensing, numbers rounded to what the eye and the timelines need) followed by typed columns
// (the crowns, the poses and positions over time, the tracks, and the occlusion maps and plans
// stored only when they change: little-endian Int32 and Float32 arrays, columns.h). The page's
// decoders (web/columns.js, web/decode.js) read exactly this layout.
#include <string>

#include "replay/run_folder.h"

namespace canopy::replay {

/// Rounding of the packed numbers: positions, radii and velocities to 1 cm (cm/s), headings to
/// 1 mrad, covariances (as Float32s), costs and OSPA to 4 significant digits.
inline constexpr int kPositionDecimals = 2;
inline constexpr int kYawDecimals = 3;
inline constexpr int kSignificantDigits = 4;
/// An occlusion-map entry is sent again only when one of its numbers moved this much (m).
inline constexpr double kMapResend = 0.05;

/// The run's data: 4 bytes (little-endian) giving the header's length, the header (a JSON object
/// with "format": 3 and "columns", the name, type, byte offset, count and delta stride of each
/// column; padded with spaces so that the columns start 4-byte aligned), then the columns. Its
/// layout: replay_data.cpp's writers, in order; docs/design-notes.md, "The replay page".
/// Deterministic: the same run, the same bytes.
std::string replayData(const RunFolder& run);

}  // namespace canopy::replay
