#pragma once
// `canopy view`: a run folder → one self-contained replay.html (no server, no network: the style,
// the scripts and the run's data are all inside the file).
#include <filesystem>
#include <string>
#include <string_view>

#include "replay/run_folder.h"

namespace canopy::replay {

/// The page for `run`: web/replay.html with the style, the scripts and replayData(run) inlined
/// (gzipped, in base64; the page inflates it with the browser's own DecompressionStream and
/// reads its columns as typed arrays). The same run gives the same bytes.
std::string replayPage(const RunFolder& run);

/// Run `b` drawn over run `a` on one map and one clock (`canopy view A B --overlay`): a's page
/// with b's data as a second element; the page draws b's agents, footprints and people as
/// outlines over a's, at b's step of the same time (web/overlay.js).
std::string overlayPage(const RunFolder& a, const RunFolder& b);

/// writeReplay of overlayPage: returns the page's size in bytes.
std::size_t writeOverlay(const std::filesystem::path& run_a, const std::filesystem::path& run_b,
                         const std::filesystem::path& out);

/// Two runs' pages side by side on one clock (web/side_by_side.html): each page whole in an
/// iframe's srcdoc, a slider in seconds above them; stepping either sets the other to the step
/// of the same time.
std::string sideBySidePage(const RunFolder& a, const RunFolder& b);

/// writeReplay for two runs: their side-by-side page to `out`; returns its size in bytes.
std::size_t writeSideBySide(const std::filesystem::path& run_a, const std::filesystem::path& run_b,
                            const std::filesystem::path& out);

/// Reads the run in `run_dir` (readRunFolder: ScenarioError on bad input) and writes its page to
/// `out` (a new temporary renamed over it; WriteError when it cannot). Returns the page's size in
/// bytes.
std::size_t writeReplay(const std::filesystem::path& run_dir, const std::filesystem::path& out);

/// `text` with & < > " as HTML entities: safe inside an element or a double-quoted attribute.
std::string htmlEscaped(std::string_view text);

}  // namespace canopy::replay
