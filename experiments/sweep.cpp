#include "experiments/sweep.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdio>
#include <map>
#include <set>

#include "core/nearest_word.h"
#include "core/printable.h"
#include "core/random.h"
#include "core/text_file.h"
#include "spec/budget.h"
#include "spec/error.h"
#include "spec/json_reader.h"
#include "spec/loader.h"

namespace canopy::experiments {
namespace fs = std::filesystem;
using spec::Field;
using spec::Json;
using spec::ObjectReader;

namespace {

// "planner.horizon" = 5 → "horizon-5", "planner.algorithm" = "sma" → "algorithm-sma"; characters
// unsafe in a directory name become '_'.
std::string slug(const std::string& path, const std::string& value) {
  const bool quoted = value.size() >= 2 && value.front() == '"' && value.back() == '"';
  std::string text =
      path.substr(path.rfind('.') + 1) + "-" + (quoted ? value.substr(1, value.size() - 2) : value);
  for (char& c : text) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  }
  return text;
}

// The hexadecimal FNV-1a of `text`, for ids and fingerprints.
std::string hexHash(const std::string& text, int digits) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(text)));
  return std::string(hex).substr(16 - digits);
}

// A value's part of a directory name stays short; a long one is cut and keeps a hash of itself.
std::string boundedSlug(const std::string& path, const std::string& value) {
  constexpr std::size_t kMaxSlug = 60;
  std::string text = slug(path, value);
  if (text.size() > kMaxSlug) text = text.substr(0, kMaxSlug - 9) + "~" + hexHash(value, 8);
  return text;
}

// A dotted override path in one spelling: an index as its number ("uavs.00" → "uavs.0").
std::string canonicalPath(const std::string& path) {
  std::string out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = path.find('.', start);
    std::string part = path.substr(start, dot == std::string::npos ? dot : dot - start);
    const std::size_t nonzero = part.find_first_not_of('0');
    if (!part.empty() && part.find_first_not_of("0123456789") == std::string::npos)
      part = nonzero == std::string::npos ? "0" : part.substr(nonzero);
    out += (out.empty() ? "" : ".") + part;
    if (dot == std::string::npos) return out;
    start = dot + 1;
  }
}

// The scenario fields an axis writes, canonical: its path, or every key of a named axis's groups.
std::vector<std::string> fieldsWritten(const SweepAxis& axis) {
  std::vector<std::string> fields;
  if (axis.set.empty()) return {canonicalPath(axis.path)};
  for (const std::vector<std::string>& group : axis.set) {
    for (const std::string& assignment : group) {
      const std::string field = canonicalPath(assignment.substr(0, assignment.find('=')));
      if (std::find(fields.begin(), fields.end(), field) == fields.end()) fields.push_back(field);
    }
  }
  return fields;
}

// True when one field is the other or lies inside it ("planner" and "planner.horizon").
bool overlaps(const std::string& a, const std::string& b) {
  const std::string& shorter = a.size() < b.size() ? a : b;
  const std::string& longer = a.size() < b.size() ? b : a;
  return longer.compare(0, shorter.size(), shorter) == 0 &&
         (longer.size() == shorter.size() || longer[shorter.size()] == '.');
}

// Each axis once, each of its values once (as JSON values: 1 and 1.0 are the same value). Two
// axes that write one field — the same path spelt twice ("uavs.0.v_max", "uavs.00.v_max"), a
// path and a named axis whose groups set it, or a field and the object holding it — are one
// axis given twice: the later would silently override the earlier.
void requireDistinct(const Field& axes, const std::vector<SweepAxis>& read) {
  // A read-only view (no effective-config slot): the fields were recorded when first read.
  const std::vector<Field> axis_fields =
      Field(axes.json(), axes.file(), axes.path(), nullptr).elements();
  for (std::size_t a = 0; a < read.size(); ++a) {
    for (std::size_t b = 0; b < a; ++b) {
      if (read[a].path == read[b].path) {
        axis_fields[a].fail("expected each axis once, \"" + read[a].path + "\" is also axes[" +
                            std::to_string(b) + "]");
      }
      for (const std::string& mine : fieldsWritten(read[a])) {
        for (const std::string& theirs : fieldsWritten(read[b])) {
          if (!overlaps(mine, theirs)) continue;
          axis_fields[a].fail("expected each scenario field on one axis only: this axis writes \"" +
                              printable(mine, 100) + "\", which axes[" + std::to_string(b) +
                              "] writes as \"" + printable(theirs, 100) + "\"");
        }
      }
    }
    const Field values = axis_fields[a].object().required("values");
    const std::vector<Field> value_fields = values.elements();
    for (std::size_t i = 0; i < value_fields.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (value_fields[i].json() == value_fields[j].json()) {
          value_fields[i].fail("expected each value once on an axis, this one repeats values[" +
                               std::to_string(j) + "]");
        }
      }
    }
  }
}

void requireFeasibleSweep(const Field& root, const SweepSpec& sweep) {
  const spec::WorkLimits limits = spec::workLimits(sweep.load.budget_scale);
  double configurations = 1.0;
  for (const SweepAxis& axis : sweep.axes)
    configurations *= static_cast<double>(axis.values.size());
  if (configurations > limits.sweep_configurations) {
    throw spec::ScenarioError(
        root.file(), "axes",
        spec::budgetMessage(configurations, limits.sweep_configurations,
                            "configurations (the product of the axes' lengths)"));
  }
  // Each configuration holds its own copy of the fixed overrides and of one value per axis, and
  // later its loaded scenario (a few kB for the library's).
  double bytes = 4096.0;
  for (const std::string& fixed : sweep.fixed) bytes += static_cast<double>(fixed.size());
  for (const SweepAxis& axis : sweep.axes) {
    std::size_t largest = 0;
    for (std::size_t v = 0; v < axis.values.size(); ++v) {
      std::size_t size = axis.path.size() + axis.values[v].size();
      if (!axis.set.empty()) {
        for (const std::string& o : axis.set[v]) size += o.size();
      }
      largest = std::max(largest, size);
    }
    bytes += static_cast<double>(largest);
  }
  if (configurations * bytes > limits.sweep_bytes) {
    throw spec::ScenarioError(
        root.file(), "axes",
        spec::budgetMessage(configurations * bytes, limits.sweep_bytes,
                            "bytes of configurations (configurations × (their "
                            "overrides' text + 4 kB))"));
  }
  if (configurations * sweep.trials > limits.sweep_trials) {
    throw spec::ScenarioError(
        root.file(), "trials",
        spec::budgetMessage(configurations * sweep.trials, limits.sweep_trials,
                            "trials (configurations × trials)"));
  }
}

// A trial file in a configuration's folder that another sweep wrote (another configuration id):
// its numbers would be averaged with this sweep's.
void requireOwnTrial(const TrialResult& trial, const SweepConfig& config, const SweepSpec& sweep,
                     const fs::path& path) {
  if (trial.config_id == config.id) return;
  throw spec::ScenarioError(
      path.string(), "config_id",
      "this trial belongs to another sweep (configuration \"" + printable(trial.config_id, 100) +
          "\", expected \"" + printable(config.id, 100) + "\" of sweep \"" +
          printable(sweep.name, 100) + "\"); its folder mixes two sweeps' results");
}

}  // namespace

SweepSpec loadSweepText(const std::string& text, const std::string& file,
                        const spec::LoadOptions& load) {
  Json document = spec::parseJson(text, file);
  Json effective = Json::object();
  spec::ObjectReader root = Field(document, file, "", &effective).object();
  SweepSpec sweep;
  sweep.file = file;
  sweep.load = load;
  sweep.name = root.string("name", fs::path(file).stem().string());
  const std::string scenario = root.required("scenario").string();
  // A file beside the sweep, else a path or library name as given; stored resolved so that
  // DIR/sweep.json reloads from anywhere.
  const fs::path beside = fs::path(file).parent_path() / scenario;
  std::error_code error;
  sweep.scenario =
      fs::is_regular_file(beside, error)     ? fs::absolute(beside).lexically_normal().string()
      : fs::is_regular_file(scenario, error) ? fs::absolute(scenario).lexically_normal().string()
                                             : scenario;
  try {
    spec::resolveScenario(sweep.scenario);
  } catch (const spec::ScenarioError&) {
    root.required("scenario")
        .fail("expected a scenario file or a built-in scenario name, got \"" + scenario + "\"");
  }
  effective["scenario"] = sweep.scenario;
  sweep.trials = root.integer("trials", 1, 1, 1000000);
  if (auto seed = root.optional("seed")) sweep.seed = seed->unsignedInteger();
  if (auto set = root.optional("set")) {
    spec::ObjectReader fixed = set->object();
    for (const auto& [key, value] : set->json().items()) {
      fixed.optional(key)->keepAsIs();
      sweep.fixed.push_back(key + "=" + value.dump());
    }
    fixed.finish();
  }
  if (auto axes = root.optional("axes")) {
    for (const Field& element : axes->elements()) {
      spec::ObjectReader axis_reader = element.object();
      SweepAxis axis;
      const auto name = axis_reader.optional("name");
      axis.path = name ? name->string() : axis_reader.required("path").string();
      for (const Field& value : axis_reader.required("values").elements(1)) {
        value.keepAsIs();
        axis.values.push_back(value.json().dump());
      }
      if (name) {
        const Field groups = axis_reader.required("set");
        const std::vector<Field> per_value = groups.elements(1);
        if (per_value.size() != axis.values.size()) {
          groups.fail("expected one object of overrides per value (" +
                      std::to_string(axis.values.size()) + "), got " +
                      std::to_string(per_value.size()));
        }
        for (const Field& group : per_value) {
          spec::ObjectReader group_reader = group.object();
          std::vector<std::string> overrides;
          for (const auto& [key, value] : group.json().items()) {
            group_reader.optional(key)->keepAsIs();
            overrides.push_back(key + "=" + value.dump());
          }
          group_reader.finish();
          axis.set.push_back(std::move(overrides));
        }
      }
      axis_reader.finish();
      sweep.axes.push_back(std::move(axis));
    }
    requireDistinct(*axes, sweep.axes);
  }
  root.finish();
  requireFeasibleSweep(root.field(), sweep);
  effective["seed"] = sweep.seed;
  sweep.effective_json = effective.dump(2);
  return sweep;
}

std::vector<std::string> builtinSweeps() {
  std::vector<std::string> names;
  std::error_code error;
  const fs::path dir = spec::builtinScenarioDir() / "sweeps";
  for (fs::directory_iterator it(dir, error); !error && it != fs::directory_iterator();
       it.increment(error)) {
    std::error_code kind;
    if (it->path().extension() == ".json" && it->is_regular_file(kind))
      names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

fs::path resolveSweep(const std::string& sweep) {
  std::error_code error;
  if (fs::is_regular_file(sweep, error) || fs::exists(fs::symlink_status(sweep, error)))
    return sweep;  // a file, or something the reader refuses with its own message
  const fs::path dir = spec::builtinScenarioDir() / "sweeps";
  if (fs::path(sweep).filename() == sweep && sweep != "." && sweep != "..") {
    for (const fs::path& candidate : {dir / sweep, dir / (sweep + ".json")})
      if (fs::is_regular_file(candidate, error)) return candidate;
  }
  const std::vector<std::string> builtin = builtinSweeps();
  std::string names;
  for (const std::string& name : builtin) names += (names.empty() ? "" : ", ") + name;
  const std::string guess = nearestWord(sweep, builtin);
  throw spec::ScenarioError(printable(sweep, 200), "",
                            "no such sweep file, and no built-in sweep of that name" +
                                (guess.empty() ? "" : "; did you mean " + guess + "?") +
                                " (built-in: " + names + ")");
}

SweepSpec loadSweep(const std::string& path, const spec::LoadOptions& load) {
  return loadSweepText(spec::readJsonFile(path).dump(), path, load);
}

SweepSpec withTrialsAndSeed(SweepSpec sweep, int trials, std::uint64_t seed) {
  Json effective = Json::parse(sweep.effective_json);
  effective["trials"] = sweep.trials = trials;
  effective["seed"] = sweep.seed = seed;
  sweep.effective_json = effective.dump(2);
  return sweep;
}

std::vector<SweepConfig> configurations(const SweepSpec& sweep) {
  std::vector<SweepConfig> configs{{"", sweep.fixed, {}}};
  for (const SweepAxis& axis : sweep.axes) {
    std::vector<SweepConfig> next;
    for (const SweepConfig& config : configs) {
      for (std::size_t v = 0; v < axis.values.size(); ++v) {
        const std::string& value = axis.values[v];
        SweepConfig point = config;
        point.id += (point.id.empty() ? "" : "_") + boundedSlug(axis.path, value);
        point.point.push_back(axis.path + "=" + value);
        if (axis.set.empty()) {
          point.overrides.push_back(axis.path + "=" + value);
        } else {
          point.overrides.insert(point.overrides.end(), axis.set[v].begin(), axis.set[v].end());
        }
        next.push_back(std::move(point));
      }
    }
    configs = std::move(next);
  }
  if (configs.size() == 1 && configs.front().id.empty()) configs.front().id = "base";
  // Readable ids can coincide ("a b" and "a_b" both read a_b): those get a hash of their point.
  std::map<std::string, int> uses;
  for (const SweepConfig& config : configs) ++uses[config.id];
  for (SweepConfig& config : configs) {
    if (uses[config.id] < 2) continue;
    std::string point;
    for (const std::string& p : config.point) point += p + "\n";
    config.id += "~" + hexHash(point, 8);
  }
  std::set<std::string> ids;
  for (const SweepConfig& config : configs) {
    if (!ids.insert(config.id).second)  // two points whose hashes also coincide
      throw spec::ScenarioError(sweep.name, "axes", "two configurations share the id " + config.id);
  }
  return configs;
}

std::string scenarioFingerprint(const spec::ScenarioSpec& spec) {
  return hexHash(spec.effective_config, 16);
}

std::uint64_t trialSeed(std::uint64_t sweep_seed, int index) {
  return RandomStream(sweep_seed, "trial-seed", static_cast<std::uint64_t>(index)).nextU64();
}

fs::path trialPath(const fs::path& out_dir, const std::string& config_id, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "trial_%04d.json", index);
  return out_dir / "trials" / config_id / name;
}

SweepResults loadSweepResults(const fs::path& out_dir, const spec::LoadOptions& load) {
  SweepResults results;
  const fs::path manifest = out_dir / "sweep.json";
  std::error_code error;
  if (!fs::exists(fs::symlink_status(manifest, error))) {
    throw spec::ScenarioError(out_dir.string(), "", "not a sweep directory (no sweep.json)");
  }
  results.sweep =
      loadSweepText(spec::readResultText(manifest, "the sweep.json that `canopy sweep` writes"),
                    manifest.string(), load);
  results.configs = configurations(results.sweep);
  for (const SweepConfig& config : results.configs) {
    std::vector<TrialResult> trials;
    for (int t = 0; t < results.sweep.trials; ++t) {
      const fs::path path = trialPath(out_dir, config.id, t);
      if (!fs::exists(fs::symlink_status(path, error))) continue;  // not run yet
      const TrialResult& trial = trials.emplace_back(trialFromJson(
          spec::readResultText(path, "a trial file that `canopy sweep` writes"), path.string()));
      requireOwnTrial(trial, config, results.sweep, path);
    }
    results.trials.push_back(std::move(trials));
  }
  return results;
}

std::string summariseSweep(const SweepResults& results) {
  Json configs = Json::array();
  for (std::size_t c = 0; c < results.configs.size(); ++c) {
    double ospa = 0.0, trace = 0.0, visible = 0.0, samples = 0.0;
    for (const TrialResult& trial : results.trials[c]) {
      for (int k = 0; k < trial.steps(); ++k) {
        TargetBits seen = 0;
        for (const TargetBits s : trial.visible[k]) seen |= s;
        ospa += trial.ospa[k];
        trace += trial.trace[k];
        visible += trial.targets ? static_cast<double>(std::popcount(seen)) / trial.targets : 0.0;
        samples += 1.0;
      }
    }
    const double n = std::max(1.0, samples);
    configs.push_back({{"id", results.configs[c].id},
                       {"overrides", results.configs[c].overrides},
                       {"trials", results.trials[c].size()},
                       {"mean_ospa_m", ospa / n},
                       {"mean_trace_pos_m2", trace / n},
                       {"mean_visible_fraction", visible / n}});
  }
  return Json{{"sweep", results.sweep.name},
              {"scenario", results.sweep.scenario},
              {"trials_per_config", results.sweep.trials},
              {"configs", configs}}
             .dump(2) +
         "\n";
}

}  // namespace canopy::experiments
