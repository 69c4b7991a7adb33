#pragma once
// Loading a scenario: JSON (comments allowed) → --set overrides → validation → ScenarioSpec.
// Every problem is a ScenarioError naming the file, the field path and what was expected.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "spec/field_log.h"
#include "spec/scenario_spec.h"

namespace canopy::spec {

struct LoadOptions {
  std::vector<std::string> overrides;  // "dotted.path=value", value parsed as JSON or else a string
  std::optional<std::uint64_t> seed;   // replaces the file's seed
  /// Folders besides the scenario's own and the library from which includes and track files may
  /// be read (`--allow-path DIR`).
  std::vector<std::filesystem::path> allowed_roots;
  /// Multiplies every work limit of spec/budget.h (`--budget K`); 1 keeps the defaults.
  double budget_scale = 1.0;
  /// When set, every field the loader reads is recorded here (spec/field_log.h).
  FieldLog* field_log = nullptr;
  /// loadScenarioText: the text is the file's own, so errors name its lines (loadScenario always
  /// does). Off for text made elsewhere (Python's edits, a manifest's configuration), whose
  /// lines would point into a file that does not hold them.
  bool text_is_the_file = false;
};

/// scenario: a path to a file, or the name of a file in the scenario library (with or without
/// ".json").
ScenarioSpec loadScenario(const std::string& scenario, const LoadOptions& options = {});

/// Loads from text; `file` names it in errors and anchors relative includes.
ScenarioSpec loadScenarioText(const std::string& text, const std::string& file,
                              const LoadOptions& options = {});

/// The folder of the built-in scenarios (library/) and the schema's probe files: the one
/// setBuiltinScenarioDir named, else $CANOPY_BUILTIN_SCENARIOS when set (an installed copy: the
/// Python package carries one and its `canopy` command sets it), else scenarios/ in the source
/// tree canopy was built from.
std::filesystem::path builtinScenarioDir();
/// Points builtinScenarioDir() at `dir` for the rest of the process (the Python module, at import,
/// to the copy inside the installed package). Not thread-safe: call before loading anything.
void setBuiltinScenarioDir(std::filesystem::path dir);
/// The directory of built-in scenarios: builtinScenarioDir() / "library".
std::filesystem::path libraryDir();
/// Where scenario names are looked up, in order: each folder of $CANOPY_PATH (':'-separated),
/// then $CANOPY_LIBRARY_DIR if set, then the built-in library.
std::vector<std::filesystem::path> scenarioSearchPath();
/// Names of the scenarios in every folder of the search path, sorted, each once. An entry that
/// cannot be judged (a symbolic link loop, a link to nowhere) or a folder that cannot be listed
/// is skipped, and said in `skipped` when given ("DIR/x.json: a symbolic link loop"), so that
/// one bad entry does not hide the others.
std::vector<std::string> libraryScenarios(std::vector<std::string>* skipped = nullptr);
/// A path for `scenario`: an existing file, or NAME / NAME.json in the first folder of the search
/// path that has it; a ScenarioError when none does.
std::filesystem::path resolveScenario(const std::string& scenario);

/// The occluders a layout file describes (the same grammar as a scenario's "occluders" list),
/// generated: for tools and tests.
std::vector<world::TreeDef> loadLayout(const std::string& path);
/// The same from text (a layout document or a bare occluder list); `file` names it in errors.
/// No includes are read (there is no folder to read them from).
std::vector<world::TreeDef> layoutFromText(const std::string& text, const std::string& file);

}  // namespace canopy::spec
