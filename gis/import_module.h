#pragma once
// The entry point of the module canopy_gis (gis/gis_module.cpp), which holds every use of GDAL
// and PROJ; the program opens it with dlopen (gis/import_loader.h) and calls it through this
// C name. Both sides are built together, so the C++ types cross as they are; an exception thrown
// inside (spec::ScenarioError for bad input) reaches the caller unchanged.
#include <string>

#include "gis/import.h"

namespace canopy::gis {

/// importLayout(*options) into *result, and layoutText of its layout into *text.
using ImportEntry = void (*)(const ImportOptions* options, ImportResult* result, std::string* text);
inline constexpr const char* kImportEntryName = "canopy_gis_import";

}  // namespace canopy::gis
