#include <cstdio>
#include <string>

#include "app/commands.h"
#include "scenarios/loader.h"
#include "scenarios/run.h"

namespace canopy::app {

int runCommand(Args& args) {
  std::string scenario;
  std::string out_dir;
  scenarios::LoadOptions load;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out_dir = args.value(arg);
    } else if (arg == "--seed") {
      load.seed = args.unsignedValue(arg);
    } else if (arg == "--set") {
      load.overrides.push_back(args.value(arg));
    } else if (!arg.empty() && arg[0] == '-') {
      usageError(arg, "unknown option for `canopy run`");
    } else if (scenario.empty()) {
      scenario = arg;
    } else {
      usageError(arg, "expected one scenario, got a second one");
    }
  }
  if (scenario.empty()) scenario = kDefaultScenario;
  const scenarios::ScenarioSpec spec = scenarios::loadScenario(scenario, load);
  if (out_dir.empty()) out_dir = "out/" + spec.name;

  scenarios::RunOptions options;
  options.out_dir = out_dir;
  options.command_line = args.joined();
  const scenarios::RunResult result = scenarios::runScenario(spec, options);
  std::printf("%s: %d steps in %.3f s → %s/{manifest.json, record.jsonl, summary.json}\n",
              spec.name.c_str(), result.steps, result.wall_seconds, out_dir.c_str());
  std::printf("%s\n", result.summary_json.c_str());
  return kExitOk;
}

}  // namespace canopy::app
