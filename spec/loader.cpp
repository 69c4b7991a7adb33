#include "spec/loader.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <map>
#include <utility>
#include <set>

#include "core/printable.h"
#include "core/progress.h"
#include "spec/budget.h"
#include "spec/internal/referenced_file.h"
#include "spec/internal/sections.h"
#include "spec/json_lines.h"
#include "spec/json_progress.h"

namespace canopy::spec {
namespace fs = std::filesystem;

namespace {

constexpr double kMaxCoordinate = 1e7;  // m

Aabb readAoi(ObjectReader& root) {
  const Field field = root.required("aoi");
  const std::vector<Field> v = field.elements(4, 4);
  const Aabb aoi{Vec2(v[0].number(), v[1].number()), Vec2(v[2].number(), v[3].number())};
  if (!(aoi.hi.x() > aoi.lo.x() && aoi.hi.y() > aoi.lo.y())) {
    field.fail("expected [x_min, y_min, x_max, y_max] with x_max > x_min and y_max > y_min");
  }
  // Box2D holds positions in single precision: beyond 10⁷ m a step is coarser than a metre.
  if (aoi.lo.cwiseAbs().maxCoeff() > kMaxCoordinate ||
      aoi.hi.cwiseAbs().maxCoeff() > kMaxCoordinate)
    field.fail("expected an AOI within ±1e7 m of the origin (Box2D keeps positions as floats)");
  return aoi;
}

void readClock(ObjectReader& root, ScenarioSpec& spec) {
  const auto field = root.optional("clock");
  if (!field) {
    root.field().out()->operator[]("clock") = Json{{"dt", spec.dt}, {"duration", spec.duration}};
    return;
  }
  ObjectReader clock = field->object();
  spec.dt = clock.number("dt", spec.dt, Bound::positive);
  spec.duration = clock.number("duration", spec.duration, Bound::positive);
  clock.finish();
  if (spec.duration < spec.dt) {
    throw ScenarioError(
        field->file(), field->path() + ".duration",
        "expected a duration of at least one step (dt = " + std::to_string(spec.dt) + " s)");
  }
  if (spec.duration / spec.dt > 1e7) {
    throw ScenarioError(field->file(), field->path() + ".duration",
                        "expected at most 10 million steps of dt");
  }
}

// Labels: "tree" first, then the targets' labels in order of first appearance, then clutter's.
void resolveLabels(const std::vector<std::string>& target_labels, const std::string& clutter_label,
                   ScenarioSpec& spec) {
  spec.labels = {"tree"};
  auto idOf = [&spec](const std::string& label) {
    const auto it = std::find(spec.labels.begin(), spec.labels.end(), label);
    if (it != spec.labels.end()) return static_cast<sensing::LabelId>(it - spec.labels.begin());
    spec.labels.push_back(label);
    return static_cast<sensing::LabelId>(spec.labels.size() - 1);
  };
  for (std::size_t t = 0; t < spec.targets.size(); ++t)
    spec.targets[t].label = idOf(target_labels[t]);
  spec.sensing.clutter_label = idOf(clutter_label);
}

// Several errors in file order: the scenario file's own by the line of their field (`lines`), each
// with its line appended; errors of other files (includes, layouts) and of --set overrides keep
// their place after them, in the order they were found.
std::vector<ScenarioError> inFileOrder(std::vector<ScenarioError> errors, const std::string& file,
                                       const std::map<std::string, int>& lines) {
  std::vector<std::pair<int, ScenarioError>> keyed;
  for (ScenarioError& e : errors) {
    const auto at = e.file() == file ? lines.find(e.field()) : lines.end();
    if (at == lines.end()) {
      keyed.emplace_back(std::numeric_limits<int>::max(), std::move(e));
    } else {
      keyed.emplace_back(at->second,
                         ScenarioError(e.file(), e.field(),
                                       e.message() + " (line " + std::to_string(at->second) + ")"));
    }
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ScenarioError> sorted;
  for (auto& [line, e] : keyed) sorted.push_back(std::move(e));
  return sorted;
}

ScenarioSpec loadDocument(Json document, const std::string& file, const LoadOptions& options,
                          const std::string& text = "") {
  // Each override is applied even when an earlier one failed: one pass reports every bad --set.
  std::vector<ScenarioError> errors;
  for (const std::string& assignment : options.overrides) {
    try {
      internal::applyOverride(document, assignment);
    } catch (const ScenarioError& e) {
      errors.push_back(e);
    }
  }

  ScenarioSpec spec;
  spec.file = file;
  Json effective = Json::object();
  LoadContext context = internal::loadContextFor(file, options.allowed_roots);
  context.budget_scale = options.budget_scale;
  context.log = options.field_log;
  context.errors = &errors;  // a field that fails is recorded, its default used, reading goes on
  ObjectReader root = Field(document, file, "", &effective, &context).object();
  auto failed = [&errors, &file, &text] {
    std::set<std::string> wanted;  // only the errors' fields: the text may hold 10⁶ values
    for (const ScenarioError& e : errors) wanted.insert(e.field());
    std::vector<ScenarioError> sorted =
        text.empty() ? std::move(errors)
                     : inFileOrder(std::move(errors), file, jsonValueLines(text, wanted));
    if (sorted.size() == 1) throw sorted[0];
    throw ScenarioErrors(std::move(sorted));
  };

  // Each section is read even when an earlier one failed, so that one pass reports every error
  // it can; sections that depend on a failed one are skipped (their errors would be echoes).
  auto attempt = [&errors](auto&& read) {
    try {
      read();
      return true;
    } catch (const ScenarioErrors& e) {
      errors.insert(errors.end(), e.errors().begin(), e.errors().end());
    } catch (const ScenarioError& e) {
      errors.push_back(e);
    }
    return false;
  };
  attempt([&] { spec.name = root.string("name", fs::path(file).stem().string()); });
  attempt([&] { spec.description = root.string("description", ""); });
  attempt([&] {
    if (options.seed) {
      spec.seed = *options.seed;
      effective["seed"] = spec.seed;
      root.optional("seed");  // accepted, replaced by the command line
    } else if (auto seed = root.optional("seed")) {
      spec.seed = seed->unsignedInteger();
    } else {
      effective["seed"] = spec.seed;
    }
  });
  const std::size_t before_aoi = errors.size();
  const bool aoi_ok = attempt([&] { spec.aoi = readAoi(root); }) && errors.size() == before_aoi;
  // A failed clock leaves its defaults in place, which every later section can be read against.
  attempt([&] { readClock(root, spec); });
  if (!aoi_ok) {
    // Everything placed in the AOI is skipped (its errors could be echoes of the AOI's); the
    // sections that are not are still read, and so are the top-level keys.
    for (const char* key : {"uavs", "targets", "occluders", "planner", "analysis"})
      root.optional(key);
    attempt([&] { internal::readTracking(root, spec); });
    attempt([&] { internal::readFusion(root, spec); });
    attempt([&] { root.finish(); });
    failed();
  }
  std::string clutter_label;
  bool bodies_ok = attempt([&] { clutter_label = internal::readSensing(root, spec); });
  bodies_ok = attempt([&] { internal::readUavs(root, spec); }) && bodies_ok;
  std::vector<std::string> target_labels;
  bodies_ok = attempt([&] { target_labels = internal::readTargets(root, spec); }) && bodies_ok;

  attempt([&] {
    Json occluders_effective = Json::array();
    if (auto list = root.optional("occluders")) {
      std::vector<std::string> include_stack{fs::weakly_canonical(fs::path(file)).string()};
      internal::readOccluders(*list, spec.aoi, spec.trees, occluders_effective, include_stack,
                              &spec.layout_sources);
    }
    effective["occluders"] = std::move(occluders_effective);
  });
  attempt([&] { internal::readTracking(root, spec); });
  attempt([&] { internal::readFusion(root, spec); });
  if (bodies_ok) {
    // Labels, the planner and the analysis name UAVs and targets.
    resolveLabels(target_labels, clutter_label, spec);
    attempt([&] { internal::readPlanner(root, spec); });
    attempt([&] { internal::readAnalysis(root, spec); });
  } else {
    root.optional("planner");  // skipped above, not unknown
    root.optional("analysis");
  }
  attempt([&] { root.finish(); });  // unknown top-level fields, once every section was read
  if (!errors.empty()) failed();
  // Stages without a loop of their own report where they start (core/progress.h).
  reportProgress("checking the work budget", 0.0, 0.0);
  checkWork(spec, options.budget_scale);

  // Each seconds long for 10⁶ trees: both report as they go (spec/json_progress.h).
  spec.effective_config = dumpIndented2(effective, "writing the effective configuration");
  releaseReporting(effective, "releasing the parsed document");
  releaseReporting(document, "releasing the parsed document");
  return spec;
}

// The lists whose length alone bounds the work (spec/budget.h), counted as the text is parsed: a
// list past its limit is refused before the rest of the document is built. A list that a --set
// override replaces is not limited here (the override's value is checked when it is read).
std::vector<ArrayLimit> listLimits(const LoadOptions& options) {
  auto overridden = [&options](const std::string& key) {
    for (const std::string& assignment : options.overrides) {
      const std::size_t end = assignment.find_first_of(".=");
      if (assignment.compare(0, end, key) == 0) return true;
    }
    return false;
  };
  auto fixed = [](std::size_t min_size, std::size_t max_size) {
    return "expected an array of " + std::to_string(min_size) + " to " + std::to_string(max_size) +
           " elements, got more than " + std::to_string(max_size) +
           " (refused as it was read; the rest of the file was not)";
  };
  std::vector<ArrayLimit> limits = {
      {"uavs", internal::kMaxUavs, fixed(1, internal::kMaxUavs)},
      {"targets", internal::kMaxTargets, fixed(0, internal::kMaxTargets)},
      internal::occluderListLimit(workLimits(options.budget_scale).trees)};
  std::erase_if(limits, [&](const ArrayLimit& limit) { return overridden(limit.key); });
  return limits;
}

}  // namespace

ScenarioSpec loadScenarioText(const std::string& text, const std::string& file,
                              const LoadOptions& options) {
  return loadDocument(parseJson(text, file, listLimits(options)), file, options,
                      options.text_is_the_file ? text : std::string());
}

ScenarioSpec loadScenario(const std::string& scenario, const LoadOptions& options) {
  const fs::path path = resolveScenario(scenario);
  const std::string text = readJsonText(path.string());
  return loadDocument(parseJson(text, path.string(), listLimits(options)), path.string(), options,
                      text);
}

namespace {
fs::path& builtinOverride() {
  static fs::path dir;
  return dir;
}
}  // namespace

fs::path builtinScenarioDir() {
  if (!builtinOverride().empty()) return builtinOverride();
  if (const char* dir = std::getenv("CANOPY_BUILTIN_SCENARIOS"); dir && *dir) return dir;
  return fs::path(CANOPY_SOURCE_DIR) / "scenarios";
}

void setBuiltinScenarioDir(fs::path dir) {
  builtinOverride() = std::move(dir);
}

fs::path libraryDir() {
  return builtinScenarioDir() / "library";
}

std::vector<fs::path> scenarioSearchPath() {
  std::vector<fs::path> dirs;
  if (const char* list = std::getenv("CANOPY_PATH"); list && *list) {
    std::string text = list;
    for (std::size_t start = 0; start <= text.size();) {
      const std::size_t colon = std::min(text.find(':', start), text.size());
      if (colon > start) dirs.emplace_back(text.substr(start, colon - start));
      start = colon + 1;
    }
  }
  if (const char* dir = std::getenv("CANOPY_LIBRARY_DIR"); dir && *dir) dirs.emplace_back(dir);
  dirs.push_back(libraryDir());
  return dirs;
}

namespace {

// Why `path` (an entry of a search-path folder) is no file at all, or "" when it is one or is
// absent: a link loop or a link to nowhere.
std::string brokenEntry(const fs::path& path) {
  std::error_code error;
  const fs::file_status link = fs::symlink_status(path, error);
  if (error || !fs::is_symlink(link)) return "";
  (void)fs::status(path, error);
  if (error == std::errc::too_many_symbolic_link_levels) return "a symbolic link loop";
  if (error) return "a symbolic link that leads nowhere (" + error.message() + ")";
  return "";
}

}  // namespace

std::vector<std::string> libraryScenarios(std::vector<std::string>* skipped) {
  std::vector<std::string> names;
  auto skip = [skipped](const fs::path& path, const std::string& why) {
    if (skipped) skipped->push_back(printable(path.string(), 200) + ": " + why);
  };
  for (const fs::path& dir : scenarioSearchPath()) {
    std::error_code error;
    fs::directory_iterator it(dir, error);
    if (error) {
      if (error != std::errc::no_such_file_or_directory)
        skip(dir, "cannot be listed (" + error.message() + ")");
      continue;
    }
    for (; it != fs::directory_iterator(); it.increment(error)) {
      if (error) {
        skip(dir, "cannot be listed (" + error.message() + ")");
        break;
      }
      const fs::path& path = it->path();
      if (path.extension() != ".json") continue;
      if (const std::string why = brokenEntry(path); !why.empty()) {
        skip(path, why + "; skipped");
        continue;
      }
      std::error_code kind;
      if (it->is_regular_file(kind)) names.push_back(path.stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

fs::path resolveScenario(const std::string& scenario) {
  std::error_code error;
  if (fs::is_regular_file(scenario, error)) return scenario;
  if (const std::string why = brokenEntry(scenario); !why.empty())
    throw ScenarioError(printable(scenario, 200), "", "cannot be read: " + why);
  for (const fs::path& dir : scenarioSearchPath()) {
    for (const fs::path& candidate : {dir / scenario, dir / (scenario + ".json")}) {
      if (fs::is_regular_file(candidate, error)) return candidate;
      if (const std::string why = brokenEntry(candidate); !why.empty())
        throw ScenarioError(printable(candidate.string(), 200), "", "cannot be read: " + why);
    }
  }
  if (fs::exists(scenario, error)) {
    throw ScenarioError(printable(scenario, 200), "",
                        "not a regular file (expected a scenario JSON file or a built-in name)");
  }
  throw ScenarioError(printable(scenario, 200), "",
                      "no such scenario file, and no scenario of that name in $CANOPY_PATH or "
                      "the built-in library (see `canopy list`)");
}

namespace {

std::vector<world::TreeDef> readLayout(const Json& document, const std::string& file,
                                       const LoadContext* context) {
  const Json list =
      document.is_object() && document.contains("occluders") ? document["occluders"] : document;
  std::vector<world::TreeDef> trees;
  Json effective = Json::array();
  std::vector<std::string> include_stack{fs::weakly_canonical(fs::path(file)).string()};
  const Aabb everywhere{Vec2::Constant(-1e9), Vec2::Constant(1e9)};
  internal::readOccluders(Field(list, file, "occluders", nullptr, context), everywhere, trees,
                          effective, include_stack);
  return trees;
}

}  // namespace

std::vector<world::TreeDef> loadLayout(const std::string& path) {
  const LoadContext context = internal::loadContextFor(path, {});
  return readLayout(readJsonFile(path), path, &context);
}

std::vector<world::TreeDef> layoutFromText(const std::string& text, const std::string& file) {
  return readLayout(parseJson(text, file), file, nullptr);
}

}  // namespace canopy::spec
