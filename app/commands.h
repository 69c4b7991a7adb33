#pragma once
// One function per `canopy` subcommand; each returns the process exit code.
#include <string>

#include "app/cli.h"
#include "render/viewport.h"

namespace canopy::app {

int runCommand(Args& args);       // canopy run [SCENARIO] [options]
int validateCommand(Args& args);  // canopy validate SCENARIO [--set k=v]...
int listCommand(Args& args);      // canopy list
int forestCommand(Args& args);    // canopy forest --aoi … --lambda … --radius … --seed …
int coverageCommand(Args& args);  // canopy coverage RUN_DIR [--size WxH]

/// The value after option `name` as "WxH" (px); a usage error (exit code 2) otherwise.
render::ImageSize imageSizeValue(Args& args, const std::string& name);

/// The scenario `canopy run` uses when none is given.
inline constexpr const char* kDefaultScenario = "demo";

}  // namespace canopy::app
