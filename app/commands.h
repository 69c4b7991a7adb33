#pragma once
// One function per `canopy` subcommand; each returns the process exit code.
#include "app/cli.h"

namespace canopy::app {

int runCommand(Args& args);       // canopy run [SCENARIO] [options]
int validateCommand(Args& args);  // canopy validate SCENARIO [--set k=v]...
int listCommand(Args& args);      // canopy list
int forestCommand(Args& args);    // canopy forest --aoi … --lambda … --radius … --seed …
int sweepCommand(Args& args);     // canopy sweep SWEEP.json --out DIR [--jobs N]
int analyzeCommand(Args& args);   // canopy analyze DIR [--out DIR]

/// The scenario `canopy run` uses when none is given.
inline constexpr const char* kDefaultScenario = "demo";

}  // namespace canopy::app
