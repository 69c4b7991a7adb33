#include "spec/work_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "spec/budget.h"
#include "spec/error.h"
#include "spec/loader.h"

namespace canopy::spec {
namespace {

// The per-unit coefficients of spec/work_model.cpp as bench/RESULTS.md ("Work budget in
// instructions") states them; the formulas are worked by hand below.
constexpr double kSearch = 68, kPenalty = 38, kSkip = 106, kPrepare = 395, kFusion = 1950,
                 kTracking = 1070, kSensing = 2800, kWorld = 2300, kRecord = 5000, kMetrics = 199,
                 kSetup = 5670,
                 kStart = 1.5e7;

// The hand-sized files below: two UAVs at (100, 100) and (900, 900), SMA-NBO H = 2 with 10
// particles per step and stall_iterations 5, 2 s at dt = 0.2 s; `people` (the targets' JSON),
// `fusion` (the fusion section's fields, or none) and planner.cost_scope `scope`.
const std::string kThreePeople = R"({"path": {"start": [105, 100], "velocity": [1, 0]}},
                {"path": {"start": [100, 110], "velocity": [0, 0]}},
                {"path": {"start": [500, 500], "velocity": [0, 0]}})";
ScenarioSpec handSized(const std::string& name, const std::string& people = kThreePeople,
                       const std::string& fusion = "", const std::string& scope = "team") {
  return loadScenarioText(R"({
    "aoi": [0, 0, 1000, 1000], "clock": {"dt": 0.2, "duration": 2.0},
    "uavs": [{"start": [100, 100]}, {"start": [900, 900]}],
    "targets": [)" + people + "]," +
                              (fusion.empty() ? "" : R"( "fusion": {)" + fusion + "},") +
                              R"(
    "planner": {"algorithm": "sma", "horizon": 2, "cost_scope": ")" + scope + R"(",
                "pso": {"particles_per_step": 10, "stall_iterations": 5}}
  })",
                          name);
}

// Two UAVs far apart (100, 100) and (900, 900) with 20 × 20 m footprints (circumradius
// 10√2 = 14.142 m, area 400 m²) at v_max 5 m/s; three people: two beside the first UAV (5 and
// 10 m off, 11.18 m apart, one walking at 1 m/s) and one alone at (500, 500). SMA-NBO H = 2,
// 10 particles per step (20 particles), stall_iterations 5 (2 × 5 = 10 iterations), Δ = 1 s;
// 2 s at dt = 0.2 s: 11 steps, 3 epochs (t = 0, 1, 2). No trees, no clutter.
TEST(WorkModel, EveryStageOfAHandSizedFileMatchesItsFormulaWorkedByHand) {
  const ScenarioSpec spec = handSized("hand.json");
  const WorkGeometry g = workGeometry(spec);
  EXPECT_DOUBLE_EQ(g.steps, 11.0);
  EXPECT_DOUBLE_EQ(g.epochs, 3.0);
  EXPECT_NEAR(g.reach, 2 * 1 * 5 + 10 * std::sqrt(2.0), 1e-9);  // R = H·Δ·v_max + circumradius
  EXPECT_DOUBLE_EQ(g.tracks_held, 3.0);
  // Within R + H·Δ·1 m/s = 26.1 m: both people near the first UAV, none near the second.
  EXPECT_DOUBLE_EQ(g.tracks_in_reach, 1.0);
  EXPECT_DOUBLE_EQ(g.uavs_in_reach, 1.0);  // 2R = 48 m: each alone
  EXPECT_DOUBLE_EQ(g.neighbours, 1.0);     // full communication: the other one
  EXPECT_DOUBLE_EQ(g.trees_known, 0.0);
  // A disc of the footprint's area (radius 11.28 m) holds both people at the first UAV: mean 1.
  EXPECT_DOUBLE_EQ(g.seen, 1.0);
  EXPECT_DOUBLE_EQ(g.people_within_cutoff, 5.0 / 3.0);  // 2, 2 and 1 within 50 m
  EXPECT_DOUBLE_EQ(g.swarms, 3.0 * 2);                  // epochs × agents
  EXPECT_DOUBLE_EQ(g.evaluations, 3.0 * 2 * 20 * 10);   // swarms × particles × iterations

  const StageWork w = estimateStageWork(spec);
  const double steps = 11, uavs = 2, evaluations = 1200, held = 3, seen = 1;
  EXPECT_NEAR(w.planning_search, kSearch * evaluations * 2 * (1 + 1.0), 1e-6);  // 326 400
  EXPECT_NEAR(w.planning_penalty, kPenalty * evaluations * 3, 1e-6);            // 136 800
  // Six swarms (3 epochs × 2 agents), each prepared over 3 tracks × 2 UAVs.
  EXPECT_NEAR(w.planning_prepare, kPrepare * 6 * 3 * 2, 1e-6);  // 14 220
  // Two UAVs: association pair by pair (0.7 per neighbour), consensus in rounds (not a closed
  // form below 16 UAVs): held × (1 + 0.7 × 1 + 1 × 5 / 31).
  EXPECT_NEAR(w.fusion, kFusion * steps * uavs * held * (1 + 0.7 + 5 / 31.0), 1e-6);
  // held + seen + people seen² × min(people seen, 64)
  EXPECT_NEAR(w.tracking, kTracking * steps * uavs * (held + seen + 1 * 1 * 1), 1e-6);
  EXPECT_NEAR(w.sensing, kSensing * steps * uavs * (1 + seen), 1e-6);
  EXPECT_NEAR(w.world, kWorld * steps * (1 * (2 + 3) + 3), 1e-6);  // one sub-step a step
  EXPECT_NEAR(w.record, kRecord * steps * uavs * (1 + held + seen) + kStart, 1e-6);
  // One solve per agent (no closed form: the agents' sets may differ), and each agent's tracks
  // compared and counted in the team's figures (0.75 each).
  const double group = 5.0 / 3.0;  // min(held, people within the cut-off)
  EXPECT_NEAR(w.metrics,
              kMetrics * steps *
                  (uavs * (3 + 11.5 * held + 0.1 * held * group * group) + 0.75 * uavs * held),
              1e-6);
  EXPECT_NEAR(w.setup, kSetup * (0 + 2 + 3), 1e-6);
  EXPECT_EQ(w.largest(), "record");  // the program's start outweighs this little run
  EXPECT_DOUBLE_EQ(estimateWork(spec).instructions, w.total());
}

// The same file with cost_scope "reach", comm_range 100 m and interest_range 50 m: the penalty
// and the preparation count only what lies within reach (the first UAV's two people, the UAV
// itself), no UAV has a neighbour, and the lone person at (500, 500) is held by no agent.
TEST(WorkModel, ReachScopeAndRangesCountTheNeighbourhoodFromTheStarts) {
  const ScenarioSpec spec = handSized("reach.json", kThreePeople,
                                      R"("comm_range": 100, "interest_range": 50)", "reach");
  const WorkGeometry g = workGeometry(spec);
  EXPECT_DOUBLE_EQ(g.neighbours, 0.0);
  EXPECT_DOUBLE_EQ(g.tracks_held, 1.0);  // 2 people within 50 m of the first UAV, none of the other
  EXPECT_DOUBLE_EQ(g.tracks_in_reach, 1.0);
  const StageWork w = estimateStageWork(spec);
  EXPECT_NEAR(w.planning_penalty, kPenalty * 1200 * 1.0, 1e-6);
  EXPECT_NEAR(w.planning_prepare, kPrepare * 6 * 1.0 * 1.0, 1e-6);
  EXPECT_NEAR(w.fusion, kFusion * 11 * 2 * 1.0, 1e-6);  // no neighbour: its own tracks
}

// The hand-sized file with 20 more people standing far from both UAVs: 22 tracks held, 1 in
// reach on average, so 21 that no candidate of one free UAV changes (≥ 16): the penalty's skip,
// (1 + tracks in reach) per evaluation. In reach scope the same file charges its tracks in reach.
TEST(WorkModel, ThePenaltysSkipCountsTheTracksInReach) {
  std::string people = R"({"path": {"start": [105, 100], "velocity": [1, 0]}},
                          {"path": {"start": [100, 110], "velocity": [0, 0]}})";
  for (int i = 0; i < 20; ++i)
    people += R"(, {"path": {"start": [)" + std::to_string(500 + i) + R"(, 500], "velocity": [0, 0]}})";
  const ScenarioSpec team = handSized("skip.json", people);
  const WorkGeometry g = workGeometry(team);
  EXPECT_DOUBLE_EQ(g.tracks_held, 22.0);
  EXPECT_DOUBLE_EQ(g.tracks_in_reach, 1.0);  // 2 at the first UAV, 0 at the second
  EXPECT_DOUBLE_EQ(g.evaluations, 1200.0);
  EXPECT_NEAR(estimateStageWork(team).planning_penalty, kSkip * 1200 * (1 + 1.0), 1e-6);
  // Reach scope: 1 track in scope, fewer than 16 beyond reach: every track, every evaluation.
  EXPECT_NEAR(estimateStageWork(handSized("skip.json", people, "", "reach")).planning_penalty, kPenalty * 1200 * 1.0, 1e-6);
}

// A swarm runs about 2 × stall_iterations (the stall rule), at most max_iterations: the
// evaluations follow stall_iterations until max_iterations caps them.
TEST(WorkModel, EvaluationsFollowTheStallRuleUntilMaxIterationsCapsThem) {
  auto evaluations = [](const std::string& pso) {
    return workGeometry(loadScenarioText(
                            R"({"aoi": [0, 0, 100, 100], "uavs": [{"start": [10, 10]}],
                                "targets": [{"path": {"start": [30, 30], "velocity": [1, 0]}}],
                                "planner": {"algorithm": "sma", "pso": )" +
                                pso + "}}",
                            "pso.json"))
        .evaluations;
  };
  // 21 epochs (20 s, Δ = 1 s) × 1 agent × 100 particles (20 per step × H = 5) × 100 iterations.
  EXPECT_DOUBLE_EQ(evaluations(R"({"stall_iterations": 50})"), 21.0 * 100 * 100);
  EXPECT_DOUBLE_EQ(evaluations(R"({"stall_iterations": 100})"), 21.0 * 100 * 200);
  EXPECT_DOUBLE_EQ(evaluations(R"({"stall_iterations": 100, "max_iterations": 150})"),
                   21.0 * 100 * 150);
}

// A scale point as bench/scale_point.py writes it, in memory: U UAVs on a square grid over a
// Poisson forest of 0.005 crowns/m² (side √(trees / 0.005)), M people in groups around them (15 m),
// SMA-NBO H = 5 on the a-priori map, canopy's defaults elsewhere.
std::string scalePoint(int uavs, int people, double trees, double duration, unsigned seed = 21) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double side = trees > 0 ? std::sqrt(trees / 0.005) : 200.0;
  const int grid = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(uavs))));
  const double cell = side / grid;
  auto start = [&](int i) { return std::pair((i % grid + 0.5) * cell, (i / grid + 0.5) * cell); };
  std::string text = R"({"aoi": [0, 0, )" + std::to_string(side) + ", " + std::to_string(side) +
                     R"(], "clock": {"duration": )" + std::to_string(duration) + R"(}, "uavs": [)";
  for (int i = 0; i < uavs; ++i) {
    const auto [x, y] = start(i);
    text += (i ? ", " : "") + std::string(R"({"start": [)") + std::to_string(x) + ", " +
            std::to_string(y) + R"(], "fov": {"size": [20, 20]}})";
  }
  text += R"(], "targets": [)";
  for (int k = 0; k < people; ++k) {
    const auto [cx, cy] = start(k % uavs);
    const double r = 15.0 * std::sqrt(unit(rng)), a = 6.283185307179586 * unit(rng);
    const double v = 1.4 * unit(rng), h = 6.283185307179586 * unit(rng);
    text += (k ? ", " : "") + std::string(R"({"path": {"start": [)") +
            std::to_string(std::clamp(cx + r * std::cos(a), 0.0, side)) + ", " +
            std::to_string(std::clamp(cy + r * std::sin(a), 0.0, side)) + R"(], "velocity": [)" +
            std::to_string(v * std::cos(h)) + ", " + std::to_string(v * std::sin(h)) + "]}}";
  }
  text += R"(], "planner": {"algorithm": "sma", "horizon": 5, "occlusion_map": "a_priori"})";
  if (trees > 0)
    text += R"(, "occluders": [{"type": "poisson", "lambda": 0.005, "radius": 2.5, "seed": 21}])";
  return text + "}";
}

double instructions(int uavs, int people, double trees, double duration) {
  LoadOptions any;
  any.budget_scale = 1e6;
  return estimateWork(loadScenarioText(scalePoint(uavs, people, trees, duration), "s.json", any))
      .instructions;
}

// Sixteen UAVs in full communication without losses: the consensus is the closed form, every
// agent holds the team's one set, and the summary solves one assignment per step (sim/summary.cpp
// reuses it for every agent). The same file with lost messages: one per agent.
TEST(WorkModel, AgentsThatAgreeShareOneSolvePerStep) {
  LoadOptions any;
  any.budget_scale = 1e6;
  const ScenarioSpec agree = loadScenarioText(scalePoint(16, 64, 1e4, 4), "agree.json", any);
  ScenarioSpec lossy = agree;
  lossy.fusion.comm_drop = 0.1;
  const WorkGeometry g = workGeometry(agree);
  const double per_solve = 64 + 11.5 * g.tracks_held +
                           0.1 * g.tracks_held * std::pow(std::min(g.tracks_held,
                                                                   g.people_within_cutoff), 2);
  const double copies = 0.75 * 16 * g.tracks_held;
  EXPECT_NEAR(estimateStageWork(agree).metrics, kMetrics * g.steps * (per_solve + copies),
              1e-6 * kMetrics * g.steps * per_solve);
  EXPECT_NEAR(estimateStageWork(lossy).metrics, kMetrics * g.steps * (16 * per_solve + copies),
              1e-6 * kMetrics * g.steps * per_solve);
}

// More UAVs, more people or a longer run never make the estimate smaller.
TEST(WorkModel, TheEstimateGrowsWithUavsPeopleAndDuration) {
  const double base = instructions(4, 16, 1000, 4);
  EXPECT_GT(instructions(8, 16, 1000, 4), base);
  EXPECT_GT(instructions(4, 64, 1000, 4), base);
  EXPECT_GT(instructions(4, 16, 1000, 8), base);
  EXPECT_GT(instructions(16, 64, 1000, 4), instructions(8, 64, 1000, 4));
  EXPECT_GT(instructions(16, 256, 1000, 4), instructions(16, 64, 1000, 4));
  EXPECT_GT(instructions(16, 64, 1000, 20), instructions(16, 64, 1000, 4));
}

// Issue 48's largest scale point, 256 UAVs × 1024 people × 10⁶ crowns for 4 s, runs in about a
// minute of CPU (bench/RESULTS.md): admitted by the defaults. The same file with 100 times the
// particles and 10 times the iterations (a thousand times the search, its largest part then)
// would take hours: refused, naming the field of its largest stage and the time. (400 s of it
// are refused too, by the record's size.)
TEST(WorkModel, TheLargestScalePointIsAdmittedAndOneHundredTimesItIsRefused) {
  const ScenarioSpec four = loadScenarioText(scalePoint(256, 1024, 1e6, 4), "city.json");
  EXPECT_GT(four.trees.size(), 950000u);
  const WorkEstimate work = estimateWork(four);
  EXPECT_LT(work.cpuSeconds(), 600.0) << work.stages.text();  // within 10 CPU-minutes
  EXPECT_NO_THROW(checkWork(four, 1.0));
  ScenarioSpec many = four;
  many.planner.pso.particles_per_step *= 100;
  many.planner.pso.stall_iterations *= 10;  // 2 × 500 iterations, max_iterations 1000
  many.file = "swarm100.json";
  try {
    checkWork(many, 1.0);
    FAIL() << "expected a ScenarioError";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), "swarm100.json");
    EXPECT_EQ(e.field(), "planner.pso") << e.message();  // the search is the largest
    EXPECT_NE(e.message().find("expected at most about 30 CPU-minutes of work"), std::string::npos)
        << e.message();
    EXPECT_NE(e.message().find("this file asks for about "), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("fewer planner.pso.particles_per_step"), std::string::npos)
        << e.message();
  }
  EXPECT_NO_THROW(checkWork(many, 100.0));  // --budget 100
  ScenarioSpec longer = four;
  longer.duration = 400.0;
  EXPECT_THROW(checkWork(longer, 1.0), ScenarioError);
}

}  // namespace
}  // namespace canopy::spec
