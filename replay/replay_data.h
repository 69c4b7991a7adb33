#pragma once
// The data a replay page embeds: a run folder packed as one compact JSON text (numbers rounded
// to what the eye and the timelines need, the occlusion maps and plans stored only when they
// change). The page's decoder (web/decode.js) reads exactly this layout.
#include <string>

#include "replay/run_folder.h"

namespace canopy::replay {

/// Rounding of the packed numbers: positions, radii and velocities to 1 cm (cm/s), headings to
/// 1 mrad, covariances, costs and OSPA to 4 significant digits.
inline constexpr int kPositionDecimals = 2;
inline constexpr int kYawDecimals = 3;
inline constexpr int kSignificantDigits = 4;
/// An occlusion-map entry is sent again only when one of its numbers moved this much (m).
inline constexpr double kMapResend = 0.05;

/// The run as the JSON object web/decode.js reads (its layout: replay_data.cpp's writers, in
/// order; docs/design-notes.md, "The replay page"). Deterministic: the same run, the same text.
std::string replayDataJson(const RunFolder& run);

}  // namespace canopy::replay
