#include "app/help.h"

#include <algorithm>
#include <cstdio>

#include "app/cli.h"
#include "core/version.h"

namespace canopy::app {
namespace {

// The options of run, validate, sweep and analyze that load scenarios (app/cli.h).
#define CANOPY_LOAD_OPTIONS                                                             \
  {"--budget", "K", "1", "multiply every load-time work limit (spec/budget.h) by K"}, { \
    "--allow-path", "DIR", "none",                                                      \
        "also read layout includes and track files from DIR (repeatable)"               \
  }

constexpr OptionHelp kRun[] = {
    {"--out", "DIR", "out/NAME (the scenario's name)", "where the run's files go"},
    {"--seed", "N", "the scenario's seed", "the seed of every random stream"},
    {"--set", "PATH=VALUE", "none", "override a field by its dotted path (repeatable)"},
    {"--json", "", "off", "print summary.json on stdout instead of the short table"},
    {"--frames", "", "off", "write DIR/frames/frame_NNNNNN.png"},
    {"--frame-every", "K", "1", "a frame every K steps"},
    {"--size", "WxH", "800 px along the view's longer side", "frame size"},
    {"--view", "aoi|action|x0,y0,x1,y1", "action",
     "what every frame shows: the AOI, the padded box of everything that moves, or a box (m)"},
    {"--video", "", "off", "also assemble DIR/frames.mp4 with ffmpeg (Debian ffmpeg)"},
    {"--fps", "F", "real time, 1/(dt·K)", "frames per second of the video"},
    {"--html", "", "off", "also write DIR/replay.html (as `canopy view DIR`)"},
    CANOPY_LOAD_OPTIONS,
};
constexpr OptionHelp kValidate[] = {
    {"--set", "PATH=VALUE", "none", "override a field by its dotted path (repeatable)"},
    CANOPY_LOAD_OPTIONS,
};
constexpr OptionHelp kCoverage[] = {
    {"--size", "WxH", "the AOI at 800 px along its longer side", "size of the counting mask"},
    {"--check", "GOLDEN.csv", "none (print the CSV)",
     "compare with a pinned CSV: exit 0 match, 1 differing rows, 2 bad input"},
    {"--tolerance", "F", "0.001",
     "with --check: pixel counts may differ by F·aoi_px, fractions by F"},
};
constexpr OptionHelp kView[] = {
    {"--out", "FILE", "RUN_DIR/replay.html", "where the page goes"},
};
constexpr OptionHelp kSweep[] = {
    {"--out", "DIR", "required", "the sweep's folder (resumable)"},
    {"--jobs", "N", "the number of cores", "trials run at once"},
    {"--shard", "I/N", "all trials", "run only shard I of N (0 <= I < N)"},
    {"--mpi", "", "off", "deal trials over the ranks of mpirun"},
    {"--status", "DIR", "none", "count the finished trials in DIR and exit"},
    CANOPY_LOAD_OPTIONS,
};
constexpr OptionHelp kAnalyze[] = {
    {"--out", "DIR", "DIR/analysis", "where tables and figures go"},
    {"--state", "NAME", "M* (or hidden coverage for occlusion scenarios)",
     "the state the sensitivity maps count at L"},
    {"--before-hiding", "S", "off", "maps: coverage in the S seconds before the target is hidden"},
    CANOPY_LOAD_OPTIONS,
};
constexpr OptionHelp kReproduce[] = {
    {"--out", "DIR", "required", "where the sweeps and report.md go"},
    {"--trials", "N", "40", "trials per configuration (sensitivity maps: N/2)"},
    {"--jobs", "N", "the number of cores", "trials run at once"},
    {"--seed", "S", "1", "the sweeps' seed"},
    {"--mpi", "", "off", "deal trials over the ranks of mpirun"},
};
constexpr OptionHelp kForest[] = {
    {"--aoi", "x0,y0,x1,y1", "required", "the region (m)"},
    {"--lambda", "L", "required", "trees per m²"},
    {"--radius", "R[,R_MAX]", "required", "crown radius or range (m)"},
    {"--seed", "S", "0", "the layout's seed"},
    {"--min-gap", "G", "none", "least gap between crowns (m), Matérn type-II thinning"},
    {"--budget", "K", "1", "multiply the tree limit by K"},
};

constexpr OptionHelp kSchema[] = {
    {"--markdown", "", "off (JSON Schema)", "print the reference page instead"},
};

#undef CANOPY_LOAD_OPTIONS

constexpr CommandHelp kCommands[] = {
    {"run", "canopy run [SCENARIO] [options]",
     "Runs a scenario (a path or a built-in name; default demo) and writes manifest.json, "
     "record.jsonl, timings.jsonl and summary.json; prints a short table of the outcome.",
     kRun},
    {"validate", "canopy validate SCENARIO [options]",
     "Checks a scenario file and reports every error found (exit code 2).", kValidate},
    {"coverage", "canopy coverage RUN_DIR [options]",
     "Rendered coverage of a finished run, one CSV row per step, or --check against a golden "
     "CSV.",
     kCoverage},
    {"view", "canopy view RUN_DIR [--out FILE]",
     "Writes one self-contained replay.html of a finished run: plays it in any browser, offline, "
     "with the agents' beliefs, maps, plans and per-target timelines.",
     kView},
    {"sweep", "canopy sweep SWEEP.json --out DIR [options]",
     "Monte Carlo trials of a sweep file on a thread pool, a shard or MPI ranks; resumable.",
     kSweep},
    {"analyze", "canopy analyze DIR [options]",
     "Behaviour statistics of a sweep with 95 % intervals: CSV tables and figures.", kAnalyze},
    {"reproduce", "canopy reproduce --out DIR [options]",
     "The paper's experiment table and three sensitivity studies → DIR/report.md.", kReproduce},
    {"forest", "canopy forest --aoi x0,y0,x1,y1 --lambda L --radius R [options]",
     "Prints a Poisson tree layout as a layout file.", kForest},
    {"schema", "canopy schema [--markdown]",
     "Prints the JSON Schema of scenario files (types, ranges, defaults, units, meaning) from the "
     "loader's own field table; --markdown prints docs/scenario-reference.md.",
     kSchema},
    {"list", "canopy list", "The built-in scenarios and their descriptions.", {}},
};

// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
// neighbours ("rnu" → "run") each cost one.
std::size_t editDistance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

}  // namespace

std::span<const CommandHelp> commands() {
  return kCommands;
}

const CommandHelp* findCommand(const std::string& name) {
  for (const CommandHelp& c : kCommands) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

std::string helpText(const CommandHelp& command) {
  std::string text = std::string("usage: ") + command.synopsis + "\n\n" + command.summary + "\n";
  if (command.options.empty()) return text;
  std::size_t width = 0;
  for (const OptionHelp& o : command.options)
    width = std::max(width, std::string(o.name).size() + 1 + std::string(o.value).size());
  text += "\noptions (default in brackets):\n";
  for (const OptionHelp& o : command.options) {
    std::string flag = std::string(o.name) + (*o.value ? " " : "") + o.value;
    flag.resize(width, ' ');
    text += "  " + flag + "  " + o.meaning + " [" + o.default_value + "]\n";
  }
  text += "  --help" + std::string(width - 6, ' ') + "  this text\n";
  return text;
}

std::string overviewText() {
  std::string text = "canopy — multi-UAV target tracking under unknown occlusions\n\ncommands:\n";
  for (const CommandHelp& c : kCommands)
    text += std::string("  ") + c.synopsis + "\n      " + c.summary + "\n";
  text +=
      "\n`canopy COMMAND --help` lists a command's options with their defaults; `canopy "
      "--version` prints the version.\nBad input exits with code 2, a failed write with code 1.\n";
  return text;
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

void unknownOption(const std::string& command, const std::string& option) {
  std::vector<std::string> names = {"--help"};
  if (const CommandHelp* c = findCommand(command)) {
    for (const OptionHelp& o : c->options) names.emplace_back(o.name);
  }
  const std::string guess = nearest(option, names);
  usageError(option, "unknown option for `canopy " + command + "`" +
                         (guess.empty() ? "" : "; did you mean " + guess + "?") + " (`canopy " +
                         command + " --help` lists them)");
}

const char* versionText() {
  static const std::string text = std::string("canopy ") + kVersion + " (git " + kGitCommit + ")";
  return text.c_str();
}

}  // namespace canopy::app
