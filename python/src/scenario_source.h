#pragma once
// A Python Scenario (python/canopy/scenario.py) as the loader takes it: its configuration as
// JSON text, the file that names it in errors and anchors its relative includes, and the extra
// folders it may read from.
#include <cstdint>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "scenarios/spec.h"

namespace canopy::python {

/// Loads and validates `scenario` (anything with a `_source()` method returning (text, file,
/// allowed_roots)); `seed` replaces the scenario's seed. Throws scenarios::ScenarioError.
scenarios::ScenarioSpec specOf(const pybind11::object& scenario,
                               std::optional<std::uint64_t> seed = std::nullopt);

}  // namespace canopy::python
