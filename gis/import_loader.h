#pragma once
// `canopy import` without linking GDAL: gis::importLayout and gis::layoutText run in the module
// canopy_gis, opened with dlopen on the first call from beside the program (the build tree) or
// from LIBDIR/canopy (an install).
#include <string>

#include "gis/import.h"

namespace canopy::gis {

struct ImportedLayout {
  ImportResult result;
  std::string text;  // layoutText(result.layout)
};

/// importLayout(options) and its text, through the module. Throws spec::ScenarioError for bad
/// input (as importLayout does) and std::runtime_error naming the module's path when it cannot
/// be loaded.
ImportedLayout importThroughModule(const ImportOptions& options);

}  // namespace canopy::gis
