// `canopy coverage RUN_DIR [--size WxH] [--steps A:B] [--check GOLDEN.csv [--tolerance F]]`:
// the rendered coverage of a finished run (or of steps A to B − 1) as CSV on stdout, or compared
// with a golden CSV (exit 0 when every row matches within the tolerance, 1 with the first
// differing rows, 2 on bad input).
#include <cstdio>
#include <optional>
#include <string>

#include "app/commands.h"
#include "core/printable.h"
#include "core/text_file.h"
#include "render/coverage_check.h"
#include "render/run_coverage.h"
#include "spec/error.h"
#include "spec/json_text.h"

namespace canopy::app {
namespace {

using spec::ScenarioError;

int check(const std::string& csv, const std::string& golden_path, double tolerance) {
  // Bounded like every file canopy reads: a regular file (a link the user named is followed)
  // of at most kMaxCoverageCsvBytes, held once; its lines are compared as views into it.
  const std::string shown = printable(golden_path, 200);
  const std::string golden =
      spec::readResultText(golden_path, "a golden CSV (`canopy coverage RUN_DIR > GOLDEN.csv`)",
                           render::kMaxCoverageCsvBytes, /*follow_links=*/true);
  const render::CoverageComparison result =
      render::compareCoverageCsv(golden, csv, tolerance, 5, shown, "the run's coverage");
  if (!result.bad_input.empty()) throw ScenarioError("--check", "", result.bad_input);
  if (result.matches()) {
    std::printf("coverage matches %s: %d rows within tolerance %g\n", shown.c_str(), result.rows,
                tolerance);
    return kExitOk;
  }
  std::printf("coverage differs from %s: %d of %d rows outside tolerance %g; the first:\n",
              shown.c_str(), result.differing, result.rows, tolerance);
  for (const std::string& line : result.first) std::printf("  %s\n", printable(line).c_str());
  return kExitFailure;
}

class Coverage : public Command {
 public:
  explicit Coverage(CLI::App& canopy)
      : Command(canopy, "coverage", "canopy coverage RUN_DIR [options]",
                "Rendered coverage of a finished run, one CSV row per step, or --check against a "
                "golden CSV.") {
    CLI::App& o = options();
    o.add_option("RUN_DIR", run_dir_, "the --out directory of `canopy run`");
    addImageSize(o, size_, "size of the counting mask")
        ->default_str("the AOI at 800 px along its longer side");
    o.add_option("--check", golden_,
                 "compare with a pinned CSV: exit 0 match, 1 differing rows, 2 bad input")
        ->type_name("GOLDEN.csv")
        ->default_str("none (print the CSV)");
    char tolerance[32];
    std::snprintf(tolerance, sizeof tolerance, "%g", render::kDefaultCoverageTolerance);
    addValue(o, "--tolerance", "F", tolerance_,
             finiteNumber("a fraction F in [0, 1] (of the AOI's pixels)",
                          [](double f) { return f >= 0.0 && f <= 1.0; }),
             "with --check: pixel counts may differ by F·aoi_px, fractions by F")
        ->default_str(tolerance);
    addValue(o, "--steps", "A:B", steps_, stepRange(),
             "the rows of steps A to B − 1 only (a compact record decodes only their blocks)")
        ->default_str("every step");
  }
  int run() override;

 private:
  std::string run_dir_, golden_;
  std::optional<double> tolerance_;
  std::optional<render::ImageSize> size_;
  std::optional<sim::LineRange> steps_;
};

int Coverage::run() {
  if (run_dir_.empty())
    usageError("coverage", "expected RUN_DIR, the --out directory of `canopy run`");
  if (tolerance_ && golden_.empty()) usageError("--tolerance", "only applies with --check");
  if (steps_ && !golden_.empty()) usageError("--steps", "does not apply with --check (every step)");
  const std::string csv =
      render::coverageCsvOfRun(run_dir_, size_, steps_.value_or(sim::LineRange{}));
  if (!golden_.empty())
    return check(csv, golden_, tolerance_.value_or(render::kDefaultCoverageTolerance));
  std::fputs(csv.c_str(), stdout);
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeCoverage(CLI::App& canopy) {
  return std::make_unique<Coverage>(canopy);
}

}  // namespace canopy::app
