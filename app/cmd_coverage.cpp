// `canopy coverage RUN_DIR [--size WxH] [--check GOLDEN.csv [--tolerance F]]`: the rendered
// coverage of a finished run as CSV on stdout, or compared with a golden CSV (exit 0 when every
// row matches within the tolerance, 1 with the first differing rows, 2 on bad input).
#include <cstdio>
#include <optional>
#include <string>

#include "app/commands.h"
#include "app/help.h"
#include "core/printable.h"
#include "core/text_file.h"
#include "render/coverage_check.h"
#include "render/run_coverage.h"
#include "spec/error.h"

namespace canopy::app {
namespace {

namespace fs = std::filesystem;
using spec::ScenarioError;

int check(const std::string& csv, const std::string& golden_path, double tolerance) {
  std::error_code error;
  if (!fs::is_regular_file(golden_path, error)) {
    throw ScenarioError(golden_path, "",
                        "missing: expected a golden CSV (`canopy coverage RUN_DIR > GOLDEN.csv`)");
  }
  const std::optional<std::string> golden = readTextFile(golden_path);
  if (!golden) throw ScenarioError(golden_path, "", "cannot be read");
  const render::CoverageComparison result =
      render::compareCoverageCsv(*golden, csv, tolerance, 5, golden_path, "the run's coverage");
  if (!result.bad_input.empty()) throw ScenarioError("--check", "", result.bad_input);
  const std::string shown = printable(golden_path, 200);
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

}  // namespace

int coverageCommand(Args& args) {
  std::string run_dir, golden;
  std::optional<double> tolerance;
  std::optional<render::ImageSize> size;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--size") {
      size = imageSizeValue(args, arg);
    } else if (arg == "--check") {
      golden = args.value(arg);
    } else if (arg == "--tolerance") {
      tolerance = args.doubleValue(arg);
      if (*tolerance < 0.0 || *tolerance > 1.0)
        usageError(arg, "expected a fraction F in [0, 1] (of the AOI's pixels)");
    } else if (!arg.empty() && arg[0] == '-') {
      unknownOption("coverage", arg);
    } else if (run_dir.empty()) {
      run_dir = arg;
    } else {
      usageError(arg, "expected one run directory, got a second one");
    }
  }
  if (run_dir.empty())
    usageError("coverage", "expected RUN_DIR, the --out directory of `canopy run`");
  if (tolerance && golden.empty()) usageError("--tolerance", "only applies with --check");
  const std::string csv = render::coverageCsvOfRun(run_dir, size);
  if (!golden.empty())
    return check(csv, golden, tolerance.value_or(render::kDefaultCoverageTolerance));
  std::fputs(csv.c_str(), stdout);
  return kExitOk;
}

}  // namespace canopy::app
