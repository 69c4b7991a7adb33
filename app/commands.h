#pragma once
// The `canopy` subcommands: each declares its options on CLI11 when made, and runs once they are
// parsed.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/cli.h"
#include "experiments/sweep.h"
#include "render/viewport.h"

namespace canopy::app {

/// One subcommand and the values of its options.
class Command {
 public:
  virtual ~Command() = default;
  /// Runs with the parsed options; returns the process exit code.
  virtual int run() = 0;
  const CLI::App& app() const { return *app_; }
  /// "canopy run [SCENARIO] [options]", the first line of its --help.
  const std::string& synopsis() const { return synopsis_; }

 protected:
  /// Adds the subcommand `name` to `canopy`; `summary` is its paragraph in --help.
  Command(CLI::App& canopy, const std::string& name, std::string synopsis,
          const std::string& summary)
      : app_(canopy.add_subcommand(name, summary)), synopsis_(std::move(synopsis)) {}
  CLI::App& options() { return *app_; }

 private:
  CLI::App* app_;  // owned by `canopy`
  std::string synopsis_;
};

/// Every command, in the order `canopy --help` lists them. `command_line` (the whole argv) goes
/// to the manifest of a run.
std::vector<std::unique_ptr<Command>> makeCommands(CLI::App& canopy,
                                                   const std::string& command_line);

std::unique_ptr<Command> makeRun(CLI::App& canopy, const std::string& command_line);
std::unique_ptr<Command> makeValidate(CLI::App& canopy);
std::unique_ptr<Command> makeCoverage(CLI::App& canopy);
std::unique_ptr<Command> makeView(CLI::App& canopy);
std::unique_ptr<Command> makeRecord(CLI::App& canopy);
std::unique_ptr<Command> makeSweep(CLI::App& canopy);
std::unique_ptr<Command> makeAnalyze(CLI::App& canopy);
std::unique_ptr<Command> makeReproduce(CLI::App& canopy);
std::unique_ptr<Command> makeForest(CLI::App& canopy);
std::unique_ptr<Command> makeImport(CLI::App& canopy);
std::unique_ptr<Command> makeSchema(CLI::App& canopy);
std::unique_ptr<Command> makeList(CLI::App& canopy);
std::unique_ptr<Command> makeImitate(CLI::App& canopy);

/// `--size WxH` (px) on `command`, read into `size`.
CLI::Option* addImageSize(CLI::App& command, std::optional<render::ImageSize>& size,
                          const std::string& meaning);
/// Refuses (OutputRefused, exit 2) a device, FIFO or socket among the entries of the sweep's
/// folder `out` and its configurations' trial folders, and (WriteError) a link planted on the way
/// to them: before anything runs.
void checkSweepOutputs(const experiments::SweepSpec& sweep, const std::filesystem::path& out);
/// Runs a sweep (the trials `shard` owns) with a progress bar on stderr; returns the number of
/// trials run now.
int runSweepWithProgress(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                         int jobs, const experiments::Shard& shard = {});
/// Runs a sweep over the MPI ranks (experiments/sweep_mpi.h); exit 2 naming --mpi without MPI.
int runSweepOverMpi(const experiments::SweepSpec& sweep, const std::filesystem::path& out,
                    int jobs);
/// Trials run at once unless --jobs says: the number of cores.
int defaultJobs();

/// The scenario `canopy run` uses when none is given.
inline constexpr const char* kDefaultScenario = "demo";

}  // namespace canopy::app
