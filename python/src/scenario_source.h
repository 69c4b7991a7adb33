#pragma once
// A Python Scenario (python/canopy/scenario.py) as the loader takes it: its configuration as
// JSON text, the file that names it in errors and anchors its relative includes, and the extra
// folders it may read from.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spec/loader.h"
#include "spec/scenario_spec.h"

namespace canopy::python {

/// LoadOptions from Python's arguments: extra readable folders (--allow-path) and the seed.
inline spec::LoadOptions loadOptions(const std::vector<std::string>& allowed_roots,
                                     std::optional<std::uint64_t> seed) {
  spec::LoadOptions options;
  options.seed = seed;
  for (const std::string& root : allowed_roots) options.allowed_roots.emplace_back(root);
  return options;
}

/// The spec of `scenario` (anything with a `_spec()` method returning the loader's result for its
/// current configuration, cached by python/canopy/scenario.py while the configuration is
/// unchanged); `seed` replaces the scenario's seed, as `--seed` does. Throws
/// spec::ScenarioError. effective_config keeps the scenario's own seed: for a Simulation,
/// which does not read it, not for writing a manifest.
spec::ScenarioSpec specOf(const pybind11::object& scenario,
                          std::optional<std::uint64_t> seed = std::nullopt);

}  // namespace canopy::python
