// The module canopy_gis's one entry point (gis/import_module.h).
#include <type_traits>

#include "gis/import_module.h"

extern "C" __attribute__((visibility("default"))) void canopy_gis_import(
    const canopy::gis::ImportOptions* options, canopy::gis::ImportResult* result,
    std::string* text) {
  *result = canopy::gis::importLayout(*options);
  *text = canopy::gis::layoutText(result->layout);
}

// The signature above is the one the program calls through.
static_assert(std::is_same_v<decltype(&canopy_gis_import), canopy::gis::ImportEntry>);
