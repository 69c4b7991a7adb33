#pragma once
// One function per `canopy` subcommand; each returns the process exit code.
#include <filesystem>
#include <string>

#include "app/cli.h"
#include "experiments/sweep.h"
#include "render/viewport.h"

namespace canopy::app {

int runCommand(Args& args);       // canopy run [SCENARIO] [options]
int validateCommand(Args& args);  // canopy validate SCENARIO [--set k=v]...
int listCommand(Args& args);      // canopy list
int forestCommand(Args& args);    // canopy forest --aoi … --lambda … --radius … --seed …
int coverageCommand(Args& args);  // canopy coverage RUN_DIR [--size WxH]
int viewCommand(Args& args);      // canopy view RUN_DIR [--out FILE]
int sweepCommand(Args& args);  // canopy sweep SWEEP.json --out DIR [--jobs N] [--shard I/N | --mpi]
int analyzeCommand(Args& args);  // canopy analyze DIR [--out DIR]
int reproduceCommand(Args& args);
int schemaCommand(Args& args);  // canopy schema [--markdown]  // canopy reproduce --out DIR
                                // [--trials N] [--jobs N] [--seed S]

/// The value after option `name` as "WxH" (px); a usage error (exit code 2) otherwise.
render::ImageSize imageSizeValue(Args& args, const std::string& name);
/// Runs a sweep (the trials `shard` owns) with a progress bar on stderr; returns the number of
/// trials run now.
int runSweepWithProgress(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                         int jobs, const experiments::Shard& shard = {});
/// Runs a sweep over the MPI ranks (experiments/sweep_mpi.h); exit 2 naming --mpi without MPI.
int runSweepOverMpi(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                    int jobs);

/// The scenario `canopy run` uses when none is given.
inline constexpr const char* kDefaultScenario = "demo";

}  // namespace canopy::app
