// canopy: the command line. Thin: parses, calls the libraries, prints.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>

#include "app/commands.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "scenarios/error.h"

namespace {

constexpr const char* kUsage = R"(canopy — multi-UAV target tracking under unknown occlusions

usage:
  canopy run [SCENARIO] [--out DIR] [--seed N] [--set key=value]...
             [--frames] [--frame-every K] [--size WxH] [--video]
  canopy coverage RUN_DIR [--size WxH] [--check GOLDEN.csv [--tolerance F]]
  canopy validate SCENARIO [--set key=value]...
  canopy list
  canopy sweep SWEEP.json --out DIR [--jobs N] [--shard I/N | --mpi]
  canopy sweep --status DIR
  canopy analyze DIR [--out DIR] [--state NAME | --before-hiding SECONDS]
  canopy reproduce --out DIR [--trials N] [--jobs N] [--seed S] [--mpi]
  canopy forest --aoi x0,y0,x1,y1 --lambda L --radius R[,R_MAX] --seed S [--min-gap G]

SCENARIO is a path or the name of a built-in scenario (see `canopy list`); run without one
runs the built-in "demo". --set overrides any field by its dotted path, e.g.
--set planner.horizon=1 or --set uavs.0.v_max=3. Bad input exits with code 2, a failed write
with code 1 (and leaves no partial result).

run, validate, sweep and analyze also take --budget K and --allow-path DIR. A scenario is
checked at load time against work limits (trees, steps, tracking, planning, record size; a
sweep's configurations and trials) about a thousand times above the paper's scenarios;
--budget K multiplies every limit by K. Layout includes and track files are read only from
the scenario's folder tree and the scenario library; --allow-path DIR allows another folder.

--frames writes DIR/frames/frame_NNNNNN.png (NNNNNN = step) every K steps (default 1) at WxH px
(default 800 px along the longer side); --video also assembles DIR/frames.mp4 when ffmpeg is
on PATH. `canopy coverage` prints, per step of a finished run, the rendered coverage of the AOI
as CSV: step, t, covered_px, visible_px, multi_px, aoi_px, covered_fraction, visible_fraction,
then 0/1 per target covered and per target visible; --check GOLDEN.csv compares with a pinned
CSV (exit 0 match, 1 with the first differing rows, 2 bad input).
`canopy sweep --shard I/N` runs only shard I (0 <= I < N) of the trials, numbered
configuration-major and dealt round-robin; shards may run at once on several machines over one
folder, in any order, and may be killed and rerun. `--status DIR` counts the finished trials
per configuration; a run without --shard runs whatever is missing and writes summary.json, the
same bytes as a single run. Under `mpirun -n K`, `--mpi` deals the trials out dynamically over
the K ranks (each with --jobs threads); see scripts/slurm/README.md for clusters.
`canopy analyze` of a sweep with two numeric axes also draws sensitivity maps: the fraction of
trials in state NAME at L (default M*, or the hidden coverage for occlusion scenarios).
)";

using namespace canopy::app;

int dispatch(const std::string& command, Args& args) {
  if (command == "run") return runCommand(args);
  if (command == "validate") return validateCommand(args);
  if (command == "list") return listCommand(args);
  if (command == "forest") return forestCommand(args);
  if (command == "coverage") return coverageCommand(args);
  if (command == "sweep") return sweepCommand(args);
  if (command == "analyze") return analyzeCommand(args);
  if (command == "reproduce") return reproduceCommand(args);
  if (command == "help" || command == "--help" || command == "-h") {
    std::fputs(kUsage, stdout);
    return kExitOk;
  }
  std::fprintf(stderr, "canopy: unknown command '%s'\n\n%s",
               canopy::printable(command, 100).c_str(), kUsage);
  return kExitUsage;
}

// Every message may quote the user's text (names, paths, values): shown through printable().
void report(const std::string& message) {
  std::fprintf(stderr, "canopy: %s\n", canopy::printable(message).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return kExitUsage;
  }
  Args args(argc, argv, 2);
  int code = kExitFailure;
  try {
    code = dispatch(argv[1], args);
  } catch (const canopy::scenarios::ScenarioError& e) {
    report(e.what());
    return kExitUsage;
  } catch (const canopy::WriteError& e) {
    report(e.what());
    return kExitFailure;
  } catch (const std::filesystem::filesystem_error& e) {
    // Not e.what(), the library's own wording: the path and the system's reason.
    report("cannot access '" + e.path1().string() + "': " + e.code().message());
    return kExitFailure;
  } catch (const std::bad_alloc&) {
    report("out of memory");
    return kExitFailure;
  } catch (const std::exception& e) {
    report(std::string("error: ") + e.what());
    return kExitFailure;
  }
  // Results printed on stdout are output too: a full disk or a closed pipe must not exit 0.
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (!flushed || std::ferror(stdout)) {
    report(std::string("cannot write the standard output: ") +
           (flushed ? "a write failed" : std::strerror(error)));
    return code == kExitOk ? kExitFailure : code;
  }
  return code;
}
