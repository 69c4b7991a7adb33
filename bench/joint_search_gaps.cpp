// How close each joint search of Dec-POMDP gets to the optimum of its own cost (issue 32;
// docs/design-notes.md, "Dec-POMDP's joint search"). Runs Resource Allocation with Dec-POMDP
// NBO (H = 5) and saves the first agent's planning state at every epoch (its fused tracks, the
// UAVs, its map, the previous joint plan shifted: TeamPlanner::observeJointProblems), the trials
// cycling through the three searches so the states cover what each one visits, until --states
// states are saved. On every state it then runs each search exactly as the planner does (the
// epoch's "pso.joint" stream, the same warm start) and --reference-runs long independent runs
// (local-best and block searches with three times the particles and a 100-iteration stall window,
// each on its own stream, no warm start). The reference optimum J* of a state is the lowest cost
// any of them reached; a search's gap is (J − J*)/J*. Prints the median and 90th percentile gap and
// the mean cost evaluations per call of each search; --csv FILE writes one row per state.
//
//   build/release/bench/joint_search_gaps [--states 200] [--reference-runs 20] [--csv FILE]
//       [--neighbours K] [--restart-after R] [--particles-per-step P] [--stride K]
//       [--reference-csv FILE] [--max-iterations N] [--local-particles-per-step P]
//       [--only SEARCH]
// --stride K keeps every K-th saved state; --reference-csv FILE takes J* from an earlier --csv of
// the same states (the same --states and --stride) instead of running the long runs; --only SEARCH
// runs that search alone on the states (no gaps; with --reference-runs 0, for callgrind's
// --toggle-collect='*comparedSearch*', which counts the compared calls and nothing else); the
// other options shape the local-best search.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "agents/planning/team_planner.h"
#include "experiments/sweep.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy {
namespace {

using agents::JointSearch;
using agents::OcclusionMap;
using agents::PlannerConfig;
using agents::TargetGaussian;
using namespace agents::planning;

// One saved planning state: everything PlanningProblem points to, owned.
struct SavedState {
  std::uint64_t seed = 0;  // the trial's
  int epoch = 0;
  std::vector<TargetGaussian> tracks;
  std::vector<UavState> uavs;
  std::optional<OcclusionMap> map;
  CostSettings settings;
  std::vector<Plan> warm;
  const char* visited_by = "";  // the search of the trial it came from

  PlanningProblem problem() const { return {tracks, uavs, map ? &*map : nullptr, settings}; }
};

struct Options {
  int states = 200;
  int reference_runs = 20;
  std::string csv;
  SwarmShape local = kLocalBest;
  int particles_per_step = 0;  // 0: the scenario's
  int stride = 1;              // keep every stride-th saved state
  std::string reference_csv;   // J* per state from an earlier --csv (no long runs)
  bool show = false;           // print every search's plans
  std::optional<JointSearch> only;  // run this search alone
};

// The calls compared (kept out of line so that callgrind can count them alone).
[[gnu::noinline]] PlanSearch comparedSearch(PlanOptimizer& optimizer, const PlanningProblem& problem,
                                            const PlannerConfig& config, std::span<const int> order,
                                            std::span<const Plan> warm, RandomStream& rng,
                                            const SwarmShape& local) {
  return searchJointPlan(optimizer, problem, config, order, warm, rng, local);
}

const char* searchName(JointSearch s) {
  return nameOf(agents::kJointSearchNames, s).data();
}

std::vector<SavedState> saveStates(const spec::ScenarioSpec& base, int count) {
  std::vector<SavedState> states;
  const JointSearch searches[] = {JointSearch::global_best, JointSearch::local_best,
                                  JointSearch::block_coordinate};
  for (int trial = 0; static_cast<int>(states.size()) < count; ++trial) {
    spec::ScenarioSpec spec = base;
    spec.seed = experiments::trialSeed(3232, trial);
    spec.planner.joint_search = searches[trial % 3];
    sim::Simulation simulation(spec);
    simulation.observeJointProblems(
        [&](int epoch, int agent, const PlanningProblem& problem, std::span<const Plan> warm) {
          if (agent != 0 || static_cast<int>(states.size()) >= count) return;
          SavedState s;
          s.seed = spec.seed;
          s.epoch = epoch;
          s.tracks.assign(problem.targets.begin(), problem.targets.end());
          s.uavs.assign(problem.uavs.begin(), problem.uavs.end());
          if (problem.map) s.map = *problem.map;
          s.settings = problem.settings;
          s.warm.assign(warm.begin(), warm.end());
          s.visited_by = searchName(spec.planner.joint_search);
          states.push_back(std::move(s));
        });
    while (!simulation.done()) simulation.tick();
  }
  return states;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double at = q * (static_cast<double>(v.size()) - 1.0);
  const std::size_t lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(v.size() - 1, lo + 1);
  return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

int run(const Options& options) {
  spec::ScenarioSpec base = spec::loadScenario("resource_allocation");
  base.planner.algorithm = agents::PlannerAlgorithm::dec_pomdp;
  base.planner.horizon = 5;
  if (options.particles_per_step > 0)
    base.planner.pso.particles_per_step = options.particles_per_step;
  std::vector<SavedState> states = saveStates(base, options.states * options.stride);
  for (std::size_t i = 1; options.stride > 1 && i * options.stride < states.size(); ++i) {
    states[i] = std::move(states[i * options.stride]);
  }
  states.resize(options.states);
  std::vector<double> loaded;  // J* per state, from --reference-csv
  if (!options.reference_csv.empty()) {
    std::ifstream in(options.reference_csv);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::size_t at = 0;
      for (int comma = 0; comma < 3; ++comma) at = line.find(',', at) + 1;
      loaded.push_back(std::strtod(line.c_str() + at, nullptr));
    }
    if (loaded.size() < states.size()) {
      std::fprintf(stderr, "%s: %zu states, expected at least %zu\n", options.reference_csv.c_str(),
                   loaded.size(), states.size());
      return 2;
    }
  }
  std::fprintf(stderr, "saved %zu planning states\n", states.size());

  const JointSearch searches[] = {JointSearch::global_best, JointSearch::local_best,
                                  JointSearch::block_coordinate};
  constexpr int kSearches = 3;
  PlanOptimizer optimizer;
  const int n = static_cast<int>(states.front().uavs.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;

  // The long runs: three times the particles, a 100-iteration stall window; half local-best,
  // half block search with four rounds.
  PlannerConfig long_config = base.planner;
  long_config.pso.particles_per_step *= 3;
  long_config.pso.stall_iterations = 100;
  long_config.pso.max_iterations = 1000;
  long_config.joint_rounds = 4;

  std::vector<double> gaps[kSearches];
  double evaluations[kSearches] = {0, 0, 0};
  std::vector<double> reference_spread;  // (second-best long run − J*)/J*: is J* settled?
  std::FILE* csv = options.csv.empty() ? nullptr : std::fopen(options.csv.c_str(), "w");
  if (!options.csv.empty() && !csv) {
    std::fprintf(stderr, "%s: cannot open the file for writing\n", options.csv.c_str());
    return 2;
  }
  if (csv)
    std::fprintf(csv, "seed,epoch,visited_by,reference,global_best,local_best,block_coordinate\n");
  for (std::size_t index = 0; index < states.size(); ++index) {
    const SavedState& s = states[index];
    const PlanningProblem problem = s.problem();
    double cost[kSearches];
    for (int k = 0; k < kSearches; ++k) {
      cost[k] = 0.0;
      if (options.only && *options.only != searches[k]) continue;
      PlannerConfig config = base.planner;
      config.joint_search = searches[k];
      RandomStream rng(s.seed, "pso.joint", static_cast<std::uint64_t>(s.epoch));
      const PlanSearch search =
          comparedSearch(optimizer, problem, config, order, s.warm, rng, options.local);
      cost[k] = search.cost;
      if (options.show) {
        std::printf("state %zu %-16s J %8.3f", index, searchName(searches[k]), search.cost);
        for (const Plan& p : search.plans) {
          std::printf("  |");
          for (const Vec2& a : p.velocities) std::printf(" (%5.2f,%5.2f)", a.x(), a.y());
        }
        std::printf("\n");
      }
      evaluations[k] += static_cast<double>(search.evaluations);
    }
    std::vector<double> long_costs;
    if (!loaded.empty()) long_costs.push_back(loaded[index]);
    for (int r = 0; r < (loaded.empty() ? options.reference_runs : 0); ++r) {
      PlannerConfig config = long_config;
      config.joint_search = r % 2 == 0 ? JointSearch::local_best : JointSearch::block_coordinate;
      RandomStream rng(s.seed * 1000003ULL + static_cast<std::uint64_t>(s.epoch), "reference",
                       static_cast<std::uint64_t>(r));
      const PlanSearch search = searchJointPlan(optimizer, problem, config, order, {}, rng);
      long_costs.push_back(search.cost);
      if (options.show) {
        std::printf("state %zu long %-11s J %8.3f", index, searchName(config.joint_search),
                    search.cost);
        for (const Plan& p : search.plans) {
          std::printf("  |");
          for (const Vec2& a : p.velocities) std::printf(" (%5.2f,%5.2f)", a.x(), a.y());
        }
        std::printf("\n");
      }
    }
    std::sort(long_costs.begin(), long_costs.end());
    double reference = long_costs.empty() ? cost[0] : long_costs.front();
    for (const double c : cost) reference = std::min(reference, c);
    if (long_costs.size() > 1 && loaded.empty()) {
      reference_spread.push_back((long_costs[1] - reference) / reference);
    }
    for (int k = 0; k < kSearches; ++k) gaps[k].push_back((cost[k] - reference) / reference);
    if (csv) {
      std::fprintf(csv, "%llu,%d,%s,%.9g,%.9g,%.9g,%.9g\n", static_cast<unsigned long long>(s.seed),
                   s.epoch, s.visited_by, reference, cost[0], cost[1], cost[2]);
    }
  }
  if (csv) std::fclose(csv);

  std::printf(
      "%zu Resource Allocation planning states (Dec-POMDP, H = 5, first agent), reference "
      "optimum: best of %d long runs and the searches\n",
      states.size(), options.reference_runs);
  std::printf("local-best shape: ring ±%d, restart after %d, particles/step %d\n",
              options.local.neighbours, options.local.restart_after,
              base.planner.pso.particles_per_step);
  std::printf("%-18s %12s %12s %12s %16s\n", "search", "median gap", "p90 gap", "max gap",
              "evaluations/call");
  for (int k = 0; k < kSearches; ++k) {
    std::printf("%-18s %11.2f%% %11.2f%% %11.2f%% %16.0f\n", searchName(searches[k]),
                100 * quantile(gaps[k], 0.5), 100 * quantile(gaps[k], 0.9),
                100 * quantile(gaps[k], 1.0), evaluations[k] / static_cast<double>(states.size()));
  }
  if (!reference_spread.empty()) {
    std::printf("second-best long run above J*: median %.2f%%, p90 %.2f%%\n",
                100 * quantile(reference_spread, 0.5), 100 * quantile(reference_spread, 0.9));
  }
  return 0;
}

int integerArgument(int argc, char** argv, int& i) {
  if (i + 1 >= argc) {
    std::fprintf(stderr, "%s: expected a value\n", argv[i]);
    std::exit(2);
  }
  char* end = nullptr;
  const long value = std::strtol(argv[++i], &end, 10);
  if (*end != '\0' || value < 0 || value > 1000000) {
    std::fprintf(stderr, "%s: expected a non-negative integer, got \"%s\"\n", argv[i - 1], argv[i]);
    std::exit(2);
  }
  return static_cast<int>(value);
}

}  // namespace
}  // namespace canopy

int main(int argc, char** argv) {
  canopy::Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--states") {
      options.states = std::max(1, canopy::integerArgument(argc, argv, i));
    } else if (a == "--reference-runs") {
      options.reference_runs = canopy::integerArgument(argc, argv, i);
    } else if (a == "--neighbours") {
      options.local.neighbours = canopy::integerArgument(argc, argv, i);
    } else if (a == "--restart-after") {
      options.local.restart_after = canopy::integerArgument(argc, argv, i);
    } else if (a == "--particles-per-step") {
      options.particles_per_step = canopy::integerArgument(argc, argv, i);
    } else if (a == "--show") {
      options.show = true;
    } else if (a == "--stride") {
      options.stride = std::max(1, canopy::integerArgument(argc, argv, i));
    } else if (a == "--max-iterations") {
      options.local.max_iterations = canopy::integerArgument(argc, argv, i);
    } else if (a == "--local-particles-per-step") {
      options.local.particles_per_step = canopy::integerArgument(argc, argv, i);
    } else if (a == "--reference-csv" && i + 1 < argc) {
      options.reference_csv = argv[++i];
    } else if (a == "--only" && i + 1 < argc) {
      const std::string name = argv[++i];
      for (const auto& entry : canopy::agents::kJointSearchNames) {
        if (entry.name == name) options.only = entry.value;
      }
      if (!options.only) {
        std::fprintf(stderr, "--only: expected global_best, local_best or block_coordinate\n");
        return 2;
      }
    } else if (a == "--csv" && i + 1 < argc) {
      options.csv = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: joint_search_gaps [--states N] [--reference-runs N] [--csv FILE] "
                   "[--neighbours K] [--restart-after R] [--particles-per-step P] [--stride K] "
                   "[--reference-csv FILE] [--max-iterations N] [--local-particles-per-step P] "
                   "[--only SEARCH]\n");
      return 2;
    }
  }
  return canopy::run(options);
}
