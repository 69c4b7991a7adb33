#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "app/commands.h"
#include "app/help.h"
#include "core/printable.h"
#include "spec/budget.h"
#include "spec/error.h"
#include "spec/forest.h"
#include "spec/loader.h"

namespace canopy::app {

int validateCommand(Args& args) {
  std::string scenario;
  spec::LoadOptions load;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--set") {
      load.overrides.push_back(args.value(arg));
    } else if (takeLoadOption(args, arg, load)) {
    } else if (!arg.empty() && arg[0] == '-') {
      unknownOption("validate", arg);
    } else if (scenario.empty()) {
      scenario = arg;
    } else {
      usageError(arg, "expected one scenario, got a second one");
    }
  }
  if (scenario.empty()) usageError("validate", "expected a scenario to check");
  const spec::ScenarioSpec spec = spec::loadScenario(scenario, load);
  std::printf("%s: ok — %zu UAVs, %zu targets, %zu trees, %d steps of %g s\n",
              printable(spec.file.string(), 200).c_str(), spec.uavs.size(), spec.targets.size(),
              spec.trees.size(), spec.steps(), spec.dt);
  return kExitOk;
}

int listCommand(Args& args) {
  if (!args.done()) usageError(args.peek(), "`canopy list` takes no arguments");
  for (const std::string& name : spec::libraryScenarios()) {
    std::string description;
    try {
      description = spec::loadScenario(name).description;
    } catch (const spec::ScenarioError& e) {
      description = std::string("(invalid: ") + e.what() + ")";
    }
    std::printf("%-24s %s\n", printable(name, 100).c_str(), printable(description, 300).c_str());
  }
  return kExitOk;
}

int forestCommand(Args& args) {
  spec::PoissonForestDef def;
  spec::LoadOptions load;  // only its --budget
  bool has_aoi = false, has_lambda = false, has_radius = false;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--aoi") {
      const std::vector<double> v = args.listValue(arg, 4);
      def.region = {Vec2(v[0], v[1]), Vec2(v[2], v[3])};
      if (!(v[2] > v[0] && v[3] > v[1]))
        usageError(arg, "expected x0,y0,x1,y1 with x1 > x0 and y1 > y0");
      has_aoi = true;
    } else if (arg == "--lambda") {
      def.lambda = args.doubleValue(arg);
      if (def.lambda < 0.0) usageError(arg, "expected a density >= 0 (trees per m²)");
      has_lambda = true;
    } else if (arg == "--radius") {
      const std::string text = args.value(arg);
      const auto comma = text.find(',');
      char* end = nullptr;
      def.radius.lo = std::strtod(text.c_str(), &end);
      def.radius.hi =
          comma == std::string::npos ? def.radius.lo : std::strtod(text.c_str() + comma + 1, &end);
      if (!(def.radius.lo > 0.0) || def.radius.hi < def.radius.lo || *end != '\0') {
        usageError(arg, "expected a positive radius R or a range R_MIN,R_MAX, got '" + text + "'");
      }
      has_radius = true;
    } else if (arg == "--seed") {
      def.seed = args.unsignedValue(arg);
    } else if (arg == "--min-gap") {
      def.min_gap = args.doubleValue(arg);
      if (*def.min_gap < 0.0) usageError(arg, "expected a gap >= 0 (m)");
    } else if (arg == "--budget" && takeLoadOption(args, arg, load)) {
    } else {
      unknownOption("forest", arg);
    }
  }
  if (!has_aoi || !has_lambda || !has_radius) {
    usageError("forest", "expected --aoi, --lambda and --radius");
  }
  const double limit = spec::workLimits(load.budget_scale).trees;
  const double expected = def.lambda * spec::poissonDrawRegion(def).area();
  if (!(expected <= limit)) {
    usageError("--lambda", spec::budgetMessage(expected, limit,
                                               "trees drawn (λ × the region dilated by "
                                               "2 r_max + min_gap)"));
  }
  def.max_points = static_cast<std::size_t>(limit);
  using Json = nlohmann::json;
  std::vector<world::TreeDef> trees;
  try {
    trees = spec::poissonForest(def);
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
                def.lambda, def.radius.lo, def.radius.hi, static_cast<unsigned long long>(def.seed),
                def.min_gap ? (", min gap " + std::to_string(*def.min_gap) + " m").c_str() : "",
                trees.size());
  const Json layout = {{"description", description}, {"occluders", occluders}};
  std::printf("%s\n", layout.dump(2).c_str());
  return kExitOk;
}

}  // namespace canopy::app
