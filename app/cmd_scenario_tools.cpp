#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/commands.h"
#include "core/number_text.h"
#include "core/printable.h"
#include "spec/budget.h"
#include "spec/error.h"
#include "spec/forest.h"
#include "spec/loader.h"
#include "world/tree.h"
#include "spec/solid_paths.h"

namespace canopy::app {

namespace {

class Validate : public Command {
 public:
  explicit Validate(CLI::App& canopy)
      : Command(canopy, "validate", "canopy validate SCENARIO [options]",
                "Checks a scenario file and reports every error found (exit code 2); prints the "
                "work a run will do, estimated in instructions and CPU time, by stage.") {
    CLI::App& o = options();
    o.add_option("SCENARIO", scenario_, "a path or a built-in name");
    o.add_option("--set", load_.overrides, "override a field by its dotted path (repeatable)")
        ->type_name("PATH=VALUE")
        ->default_str("none")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    addLoadOptions(o, load_);
    o.add_flag("--strict", strict_,
               "treat warnings as errors (exit 2): a target's or ground robot's scripted path "
               "into a trunk or wall");
  }
  int run() override;

 private:
  std::string scenario_;
  spec::LoadOptions load_;
  bool strict_ = false;
};

int Validate::run() {
  if (scenario_.empty()) usageError("validate", "expected a scenario to check");
  const spec::ScenarioSpec spec = spec::loadScenario(scenario_, load_);
  const std::vector<spec::SolidCrossing> crossings = spec::solidCrossings(spec);
  // The first kShown crossings in full, then their count (a city of 10⁵ trees has hundreds).
  constexpr std::size_t kShown = 10;
  const char* kind = strict_ ? "error" : "warning";
  for (std::size_t i = 0; i < std::min(crossings.size(), kShown); ++i) {
    std::fprintf(stderr, "%s: %s: %s\n", printable(spec.file.string(), 200).c_str(), kind,
                 printable(crossings[i].message, 400).c_str());
  }
  if (crossings.size() > kShown) {
    std::fprintf(stderr, "%s: %s: … and %zu more scripted paths into a trunk or wall\n",
                 printable(spec.file.string(), 200).c_str(), kind, crossings.size() - kShown);
  }
  if (strict_ && !crossings.empty()) return kExitUsage;
  // A run records steps k = 0 … duration/dt: one more than the number of dt it spans.
  std::printf("%s: ok — %zu UAVs, %zu targets, %zu trees, %d steps (k = 0 … %d, dt = %g s)\n",
              printable(spec.file.string(), 200).c_str(), spec.uavs.size(), spec.targets.size(),
              spec.trees.size(), spec.steps() + 1, spec.steps(), spec.dt);
  // The work budget's estimate (spec/budget.h): the run's instructions, in CPU time and by stage.
  const spec::WorkEstimate work = spec::estimateWork(spec);
  std::printf("  work: about %.2e instructions, about %.3g CPU-s on the machine the estimate was "
              "measured on (limit %.3g CPU-s)\n",
              work.instructions, work.cpuSeconds(), spec::workLimits(load_.budget_scale).cpu_seconds);
  std::printf("  work by stage (instructions): %s\n", work.stages.text().c_str());
  // Layouts made by `canopy import`: what each holds and where it came from.
  for (const std::string& line : spec.layout_sources)
    std::printf("  layout %s\n", printable(line, 600).c_str());
  return kExitOk;
}

class List : public Command {
 public:
  explicit List(CLI::App& canopy)
      : Command(canopy, "list", "canopy list", "The built-in scenarios and their descriptions.") {}
  int run() override;
};

int List::run() {
  std::vector<std::string> skipped;
  const std::vector<std::string> names = spec::libraryScenarios(&skipped);
  for (const std::string& entry : skipped)
    std::fprintf(stderr, "canopy: warning: %s\n", printable(entry, 300).c_str());
  for (const std::string& name : names) {
    std::string description;
    try {
      description = spec::loadScenario(name).description;
    } catch (const spec::ScenarioError& e) {
      description = std::string("(invalid: ") + e.what() + ")";
    } catch (const std::filesystem::filesystem_error& e) {
      description = std::string("(cannot be read: ") + e.code().message() + ")";
    }
    std::printf("%-24s %s\n", printable(name, 100).c_str(), printable(description, 300).c_str());
  }
  return kExitOk;
}

// "x0,y0,x1,y1" (m) with x1 > x0 and y1 > y0.
std::optional<Aabb> readRegion(const std::string& text) {
  std::vector<double> v;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    const std::optional<double> x = strictNumber(item);
    if (!x || std::abs(*x) > world::kMaxTreeCoordinate) return std::nullopt;
    v.push_back(*x);
  }
  if (text.empty() || text.back() == ',') return std::nullopt;
  if (v.size() != 4 || !(v[2] > v[0] && v[3] > v[1])) return std::nullopt;
  return Aabb{Vec2(v[0], v[1]), Vec2(v[2], v[3])};
}

// "R" or "R_MIN,R_MAX" (m), 0 < R_MIN <= R_MAX <= 1e7 (a crown Box2D can hold).
std::optional<spec::RadiusRange> readRadius(const std::string& text) {
  const auto comma = text.find(',');
  const std::optional<double> lo = strictNumber(std::string_view(text).substr(0, comma));
  const std::optional<double> hi =
      comma == std::string::npos ? lo : strictNumber(std::string_view(text).substr(comma + 1));
  if (!lo || !hi || !(*lo > 0.0) || !(*hi >= *lo)) return std::nullopt;
  for (double r : {*lo, *hi}) {
    if (!world::box2dProblem(world::TreeDef::disc(Vec2::Zero(), r)).empty()) return std::nullopt;
  }
  return spec::RadiusRange{*lo, *hi};
}

class Forest : public Command {
 public:
  explicit Forest(CLI::App& canopy)
      : Command(canopy, "forest", "canopy forest --aoi x0,y0,x1,y1 --lambda L --radius R [options]",
                "Prints a Poisson tree layout as a layout file.") {
    CLI::App& o = options();
    addValue(o, "--aoi", "x0,y0,x1,y1", def_.region,
             Reader<Aabb>{readRegion,
                          "x0,y0,x1,y1 (four numbers within ±1e7 m) with x1 > x0 and y1 > y0"},
             "the region (m)")
        ->default_str("required")
        ->required();
    addValue(o, "--lambda", "L", def_.lambda,
             finiteNumber("a density >= 0 (trees per m²)", [](double l) { return l >= 0.0; }),
             "trees per m²")
        ->default_str("required")
        ->required();
    addValue(o, "--radius", "R[,R_MAX]", def_.radius,
             Reader<spec::RadiusRange>{readRadius,
                                       "a radius R in (0, 1e7] or a range R_MIN,R_MAX within it"},
             "crown radius or range (m)")
        ->default_str("required")
        ->required();
    addValue(o, "--seed", "S", def_.seed, nonNegativeInteger(), "the layout's seed")
        ->default_str(std::to_string(def_.seed));
    addValue(o, "--min-gap", "G", def_.min_gap,
             finiteNumber("a gap in [0, 1e7] (m)",
                          [](double g) { return g >= 0.0 && g <= world::kMaxTreeCoordinate; }),
             "least gap between crowns (m), Matérn type-II thinning")
        ->default_str("none");
    addLoadOptions(o, load_, /*allow_path=*/false);
  }
  int run() override;

 private:
  spec::PoissonForestDef def_;
  spec::LoadOptions load_;  // only its --budget
};

int Forest::run() {
  const double limit = spec::workLimits(load_.budget_scale).trees;
  const double expected = def_.lambda * spec::poissonDrawRegion(def_).area();
  if (!(expected <= limit)) {
    // The option that drives the count: λ when the region itself would hold too many; else the
    // dilation, by min_gap or by the crowns (2 r_max), whichever is wider.
    const double in_region = def_.lambda * def_.region.width() * def_.region.height();
    const bool dilation = in_region <= limit;
    const bool gap = def_.min_gap && *def_.min_gap > 2.0 * def_.radius.hi;
    usageError(!dilation ? "--lambda"
               : gap     ? "--min-gap"
                         : "--radius",
               spec::budgetMessage(expected, limit,
                                   "trees drawn (λ × the region dilated by "
                                   "2 r_max + min_gap)"));
  }
  def_.max_points = static_cast<std::size_t>(limit);
  using Json = nlohmann::json;
  std::vector<world::TreeDef> trees;
  try {
    trees = spec::poissonForest(def_);
  } catch (const spec::ForestTooLarge& e) {
    usageError("--seed", "this seed's draw needs more than " + std::to_string(e.max_points) + " " +
                             e.what_counted +
                             "; change the seed or raise the limit with --budget K");
  }
  Json occluders = Json::array();
  for (const world::TreeDef& tree : trees) {
    occluders.push_back({{"type", "disc"},
                         {"centre", {tree.centre.x(), tree.centre.y()}},
                         {"radius", tree.radius}});
  }
  char description[256];
  std::snprintf(description, sizeof description,
                "Poisson forest: lambda %g per m2, radius [%g, %g] m, seed %llu%s, %zu trees",
                def_.lambda, def_.radius.lo, def_.radius.hi,
                static_cast<unsigned long long>(def_.seed),
                def_.min_gap ? (", min gap " + std::to_string(*def_.min_gap) + " m").c_str() : "",
                trees.size());
  // One tree a line: a layout of 10⁴ trees stays 10⁴ lines long, and still one JSON document.
  std::printf("{\n  \"description\": %s,\n  \"occluders\": [", Json(description).dump().c_str());
  for (std::size_t i = 0; i < occluders.size(); ++i)
    std::printf("%s\n    %s", i ? "," : "", occluders[i].dump().c_str());
  std::printf("%s]\n}\n", occluders.empty() ? "" : "\n  ");
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeValidate(CLI::App& canopy) {
  return std::make_unique<Validate>(canopy);
}

std::unique_ptr<Command> makeList(CLI::App& canopy) {
  return std::make_unique<List>(canopy);
}

std::unique_ptr<Command> makeForest(CLI::App& canopy) {
  return std::make_unique<Forest>(canopy);
}

}  // namespace canopy::app
