#pragma once
// Printing and freeing a large parsed document with progress (core/progress.h): a scenario of 10⁶
// trees spends seconds in each, which would otherwise pass with no line on stderr.
#include <string>

#include "spec/json_text.h"

namespace canopy::spec {

/// value.dump(2), byte for byte, reporting under `stage` as it goes through the elements of the
/// arrays that are values of `value`'s top-level keys (where a scenario's long lists live).
std::string dumpIndented2(const Json& value, const char* stage);

/// Empties `value`, the elements of its top-level arrays one by one, reporting under `stage`.
void releaseReporting(Json& value, const char* stage);

}  // namespace canopy::spec
