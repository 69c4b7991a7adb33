#pragma once
// The rendered coverage of a finished run, from RUN_DIR/manifest.json (the effective scenario) and
// its record (record.jsonl or record.jsonl.zst): what `canopy coverage` prints and the golden
// tests compare.
#include <filesystem>
#include <optional>
#include <string>

#include "render/viewport.h"
#include "sim/record_lines.h"

namespace canopy::render {

/// The coverage CSV (render/coverage.h: header, then one row per recorded step) of the run in
/// `run_dir`, on a mask of `size` px (default: the AOI fitted to the frames' default size).
/// `steps`: only the rows of those steps (the compact record decodes only their blocks).
/// Throws ScenarioError naming the file, line and field when the directory is not a finished run.
std::string coverageCsvOfRun(const std::filesystem::path& run_dir,
                             std::optional<render::ImageSize> size = std::nullopt,
                             const sim::LineRange& steps = {});

}  // namespace canopy::render
