// The malformed-scenario table: each broken file, run through `canopy validate`, must exit with
// code 2 and a message that names the file, the field path and what was expected.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;

struct Case {
  std::string name;
  std::string scenario;               // the file under test (scenario.json)
  std::vector<std::string> expected;  // fragments the message must contain
  std::map<std::string, std::string> extra_files = {};
  std::string extra_args = "";
  bool names_file = true;  // errors in --set values name "--set" instead
};

// A valid base; cases splice their error into it.
std::string base(
    const std::string& uavs = R"([{"start": [10, 10]}])",
    const std::string& targets = R"([{"path": {"start": [20, 20], "velocity": [1, 0]}}])",
    const std::string& rest = "") {
  return R"({"aoi": [0, 0, 100, 50], "uavs": )" + uavs + R"(, "targets": )" + targets + rest + "}";
}

// 256 UAVs in a row, for the tracking-work case.
std::string manyUavs() {
  std::string list = "[";
  for (int i = 0; i < 256; ++i) list += (i ? ", " : "") + std::string(R"({"start": [10, 10]})");
  return list + "]";
}

// clang-format off: one case per line reads as a table.
const std::vector<Case>& cases() {
  static const std::vector<Case> table = {
      {"SyntaxError", R"({"aoi": [0, 0, 100, 50] "uavs": []})", {"line 1, column", "invalid JSON"}},
      {"InfiniteNumber", R"({"aoi": [0, 0, 1e999, 50]})", {"number overflow", "finite"}},
      {"NaNLiteral", R"({"aoi": [0, 0, NaN, 50]})", {"invalid JSON"}},
      {"NotAnObject", R"([1, 2, 3])", {"expected an object, got an array"}},
      {"UnknownTopLevelField",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "speed": 3)"),
       {"speed: unknown field"}},
      // A near miss gets a "did you mean" (issue 51: "qualty" listed the valid fields only).
      {"MistypedFieldGetsASuggestion",
       base(R"([{"start": [10, 10], "qualty": 0.5}])"),
       {"uavs[0].qualty: unknown field; did you mean \"quality\"? (expected one of: "}},
      {"MistypedChoiceGetsASuggestion",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"algorithm": "dec_pomdb"})"),
       {"got the string \"dec_pomdb\"; did you mean \"dec_pomdp\"?"}},
      {"UnknownNestedField",
       base(R"([{"start": [10, 10], "fov": {"sise": [10, 10]}}])"),
       {"uavs[0].fov.sise: unknown field"}},
      {"AoiWrongType",
       R"({"aoi": "big", "uavs": [{"start": [1, 1]}]})",
       {"aoi: expected an array of 4 elements, got the string \"big\""}},
      {"AoiInverted",
       R"({"aoi": [10, 0, 0, 50], "uavs": [{"start": [1, 1]}]})",
       {"aoi: expected [x_min, y_min, x_max, y_max]"}},
      {"NegativeDt",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "clock": {"dt": -0.2})"),
       {"clock.dt: expected a positive number, got the number -0.2"}},
      {"DurationShorterThanAStep",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "clock": {"dt": 0.5, "duration": 0.1})"),
       {"clock.duration: expected a duration of at least one step"}},
      {"MissingUavs", R"({"aoi": [0, 0, 100, 50]})", {"uavs: missing required field"}},
      {"EmptyUavs", base("[]"), {"uavs: expected an array of 1 to 256 elements, got 0 elements"}},
      {"UavOutsideAoi",
       base(R"([{"start": [10, 60]}])"),
       {"uavs[0].start: expected a start inside the AOI [0, 0, 100, 50], got (10, 60)"}},
      {"UavMissingStart", base(R"([{"v_max": 3}])"), {"uavs[0].start: missing required field"}},
      {"NegativeFootprint",
       base(R"([{"start": [10, 10], "fov": {"size": [10, -4]}}])"),
       {"uavs[0].fov.size[1]: expected a positive number, got the number -4"}},
      {"FootprintTwoShapes",
       base(R"([{"start": [10, 10], "fov": {"size": [10, 4], "radius": 3}}])"),
       {"uavs[0].fov: give only one of \"size\" and \"radius\""}},
      {"ZeroVmax",
       base(R"([{"start": [10, 10], "v_max": 0}])"),
       {"uavs[0].v_max: expected a positive number, got the number 0"}},
      {"BadYawMode",
       base(R"([{"start": [10, 10], "yaw": "north"}])"),
       {"uavs[0].yaw: expected one of \"velocity\", got the string \"north\""}},
      {"DuplicateUavNames",
       base(R"([{"name": "a", "start": [1, 1]}, {"name": "a", "start": [2, 2]}])"),
       {"uavs[1].name: expected a unique UAV name"}},
      {"EmptyWaypoints",
       base("[{\"start\": [10, 10]}]", R"([{"path": {"waypoints": []}}])"),
       {"targets[0].path.waypoints: expected an array of at least 1 element, got 0 elements"}},
      {"NonMonotonicWaypoints",
       base(
           "[{\"start\": [10, 10]}]",
           R"([{"path": {"waypoints": [{"t": 0, "p": [1, 1]}, {"t": 5, "p": [2, 2]}, {"t": 5, "p": [3, 3]}]}}])"),
       {"targets[0].path.waypoints[2].t: expected a time greater than the previous point's (5 s)"}},
      {"WaypointOutsideAoi",
       base("[{\"start\": [10, 10]}]",
            R"([{"path": {"waypoints": [{"t": 0, "p": [1, 1]}, {"t": 5, "p": [200, 2]}]}}])"),
       {"targets[0].path.waypoints[1].p: expected a waypoint inside the AOI"}},
      {"VelocityPathLeavesAoi",
       base("[{\"start\": [10, 10]}]", R"([{"path": {"start": [20, 20], "velocity": [10, 0]}}])"),
       {"targets[0].path: expected the position at the end of the run"}},
      {"PathWithNoKind",
       base("[{\"start\": [10, 10]}]", R"([{"path": {}}])"),
       {"targets[0].path: expected a path"}},
      {"PathWithTwoKinds",
       base("[{\"start\": [10, 10]}]",
            R"([{"path": {"waypoints": [{"t": 0, "p": [1, 1]}], "track": [[0, 1, 1]]}}])"),
       {"targets[0].path: give only one of"}},
      {"TargetLabelTree",
       base("[{\"start\": [10, 10]}]",
            R"([{"label": "tree", "path": {"start": [20, 20], "velocity": [0, 0]}}])"),
       {"targets[0].label: expected a target label other than \"tree\""}},
      {"MissingTrackFile",
       base("[{\"start\": [10, 10]}]", R"([{"path": {"track": "nowhere.csv"}}])"),
       {"targets[0].path.track: cannot read the track file"}},
      {"MalformedTrackFile",
       base("[{\"start\": [10, 10]}]", R"([{"path": {"track": "walk.csv"}}])"),
       {"walk.csv: line 3: expected \"t,x,y\""},
       {{"walk.csv", "t,x,y\n0,1,1\n2,oops,1\n"}}},
      {"UnknownOccluderType",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "occluders": [{"type": "bush"}])"),
       {"occluders[0].type: expected one of \"disc\", \"polygon\", \"poisson\", \"grid\", "
        "\"cluster\""}},
      {"NegativeTreeRadius",
       base("[{\"start\": [10, 10]}]", "[]",
            R"(, "occluders": [{"type": "disc", "centre": [5, 5], "radius": -1}])"),
       {"occluders[0].radius: expected a positive number"}},
      {"TreeOutsideAoi",
       base("[{\"start\": [10, 10]}]", "[]",
            R"(, "occluders": [{"type": "disc", "centre": [500, 5], "radius": 1}])"),
       {"occluders[0].centre: expected every tree inside the AOI"}},
      {"SelfCrossingPolygon",  // a bow tie: edge 0 (0,0)→(4,4) crosses edge 2 (4,0)→(0,4)
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "occluders": [{"type": "polygon", "vertices": [[0, 0], [4, 4], [4, 0], [0, 4]]}])"),
       {"occluders[0].vertices: edges 0 (vertices 0 to 1) and 2 (vertices 2 to 3) cross"}},
      {"ConcavePolygonWithATrunk",  // a concave polygon is a wall cut into pieces: no trunk
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "occluders": [{"type": "polygon", "vertices": [[0, 0], [4, 0], [2, 1], [4, 4], [0, 4]], "trunk_radius": 0.3}])"),
       {"occluders[0].trunk_radius: expected no trunk on a concave polygon"}},
      {"HugePoissonForest",
       base("[{\"start\": [10, 10]}]", "[]",
            R"(, "occluders": [{"type": "poisson", "lambda": 1000, "radius": 1}])"),
       {"occluders[0]: expected at most 2.0e+06 trees drawn",
        "asks for about 5.0e+06"}},  // 1000 × 100 × 50
      // Work budget (spec/budget.h): each estimate by hand in the comment.
      {"PoissonGapDilatesTheDrawRegion",  // λ 1 × (100 + 2·1002) × (50 + 2·1002) = 4.3e6
       base("[{\"start\": [10, 10]}]", "[]",
            R"(, "occluders": [{"type": "poisson", "lambda": 1, "radius": 1, "min_gap": 1000}])"),
       {"occluders[0]: expected at most 2.0e+06 trees drawn", "asks for about 4.3e+06"}},
      {"PoissonWideRadiusDilatesTheDrawRegion",  // 0.01 × (100 + 2·10000) × (50 + 2·10000) = 4.0e6
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "occluders": [{"type": "poisson", "lambda": 0.01, "radius": [1, 5000], "min_gap": 0}])"),
       {"occluders[0]: expected at most 2.0e+06 trees drawn", "asks for about 4.0e+06"}},
      {"ClusterHugeMeanTrees",
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "occluders": [{"type": "cluster", "parent_lambda": 1e-9, "mean_trees": 1e9, "spread": 1, "radius": 1}])"),
       {"occluders[0].mean_trees: expected at most 2.0e+06 trees per cluster", "about 1.0e+09"}},
      {"ClusterHugeParents",  // 1000 × (100 + 10) × (50 + 10) = 6.6e6
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "occluders": [{"type": "cluster", "parent_lambda": 1000, "mean_trees": 0, "spread": 1, "radius": 1}])"),
       {"occluders[0].parent_lambda: expected at most 2.0e+06 cluster parents", "about 6.6e+06"}},
      // Expected 0.5 parents × 1.5e6 trees, within the limit; seed 18 draws two parents (P ≈ 9 %).
      {"ClusterDrawBeyondItsExpectation",
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "occluders": [{"type": "cluster", "parent_lambda": 7.5758e-5, "mean_trees": 1500000, "spread": 1, "radius": 0.1, "seed": 18}])"),
       {"occluders[0]: expected a layout of at most 2000000 drawn points", "this seed's draw"}},
      {"PlannerThatWouldRunForDays",
       base(
           "[{\"start\": [10, 10]}]", "[]",
           R"(, "planner": {"algorithm": "sma", "horizon": 50, "pso": {"particles_per_step": 10000, "max_iterations": 1000000, "stall_iterations": 1000000}})"),
       {"planner.pso: expected at most about 30 CPU-minutes of work"}},
      // 5001 steps × 256 UAVs × (2² + 10⁷) = 1.3e13
      {"TrackingHypothesesTimesUavsTimesSteps",
       base(
           manyUavs(),
           R"([{"path": {"start": [20, 20], "velocity": [0, 0]}}, {"path": {"start": [30, 20], "velocity": [0, 0]}}])",
           R"(, "clock": {"dt": 0.2, "duration": 1000}, "tracking": {"max_hypotheses": 10000000})"),
       // 5001 steps × 256 UAVs × (1001 × 2² + 10⁷ events × depth 2) = 2.6e13
       {"tracking.max_hypotheses: expected at most 5.0e+11 tracking units", "about 2.6e+13"}},
      // 10⁷ + 1 steps × 1 UAV × (1000 + 600 × 20 targets) = 1.3e11 bytes of record.jsonl, past
      // 6.4e7 written compact: a 20th, 6.5e9 bytes
      {"RecordTooLargeForTheDisk",
       base("[{\"start\": [10, 10]}]",
            R"([{"path": {"start": [20, 20], "velocity": [0, 0]}},
                {"path": {"start": [21, 20], "velocity": [0, 0]}},
                {"path": {"start": [22, 20], "velocity": [0, 0]}},
                {"path": {"start": [23, 20], "velocity": [0, 0]}},
                {"path": {"start": [24, 20], "velocity": [0, 0]}},
                {"path": {"start": [25, 20], "velocity": [0, 0]}},
                {"path": {"start": [26, 20], "velocity": [0, 0]}},
                {"path": {"start": [27, 20], "velocity": [0, 0]}},
                {"path": {"start": [28, 20], "velocity": [0, 0]}},
                {"path": {"start": [29, 20], "velocity": [0, 0]}},
                {"path": {"start": [30, 20], "velocity": [0, 0]}},
                {"path": {"start": [31, 20], "velocity": [0, 0]}},
                {"path": {"start": [32, 20], "velocity": [0, 0]}},
                {"path": {"start": [33, 20], "velocity": [0, 0]}},
                {"path": {"start": [34, 20], "velocity": [0, 0]}},
                {"path": {"start": [35, 20], "velocity": [0, 0]}},
                {"path": {"start": [36, 20], "velocity": [0, 0]}},
                {"path": {"start": [37, 20], "velocity": [0, 0]}},
                {"path": {"start": [38, 20], "velocity": [0, 0]}},
                {"path": {"start": [39, 20], "velocity": [0, 0]}}])",
            R"(, "clock": {"dt": 0.01, "duration": 100000})"),
       {"clock.duration: expected at most 4.0e+09 bytes of record (record.jsonl", "about 6.5e+09"}},
      {"DuplicateKey",
       R"({"aoi": [0, 0, 100, 50], "aoi": [0, 0, 10, 10], "uavs": [{"start": [5, 5]}]})",
       {"the key \"aoi\" appears twice in one object"}},
      {"AoiBeyondSinglePrecision",
       R"({"aoi": [-1e300, -1e300, 1e300, 1e300], "uavs": [{"start": [5, 5]}]})",
       {"aoi: expected an AOI within ±1e7 m"}},
      {"FootprintAstronomical",
       base(R"([{"start": [10, 10], "fov": {"size": [1e300, 1e300]}}])"),
       {"uavs[0].fov.size: expected at most 2e7 m a side"}},
      {"MissingInclude",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "occluders": [{"include": "none.json"}])"),
       {"occluders[0].include: cannot read the layout file", "none.json': No such file"}},
      {"IncludeCycle",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "occluders": [{"include": "loop.json"}])"),
       {"loop.json: occluders[0].include: include cycle"},
       {{"loop.json", R"({"occluders": [{"include": "loop.json"}]})"}}},
      {"BrokenIncludedLayout",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "occluders": [{"include": "bad.json"}])"),
       {"bad.json: occluders[0].radius: expected a positive number"},
       {{"bad.json", R"({"occluders": [{"type": "disc", "centre": [1, 1], "radius": "big"}]})"}}},
      {"UnknownPlanner",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"algorithm": "greedy"})"),
       {"planner.algorithm: expected one of \"none\", \"sma\", \"dec_pomdp\", \"centralized\""}},
      {"ZeroHorizon",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"horizon": 0})"),
       {"planner.horizon: expected an integer in [1, 50], got the number 0"}},
      {"FractionalHorizon",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"horizon": 2.5})"),
       {"planner.horizon: expected an integer in [1, 50], got the number 2.5"}},
      {"PlanPeriodNotAMultipleOfDt",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"plan_period": 0.3})"),
       {"planner.plan_period: expected a whole multiple of clock.dt (0.2 s)"}},
      {"ReplanPeriodNotAMultipleOfDt",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"replan_period": 0.5})"),
       {"planner.replan_period: expected a whole multiple of clock.dt (0.2 s) no longer than "
        "plan_period (1 s), got 0.5"}},
      {"ReplanPeriodLongerThanTheAction",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "planner": {"replan_period": 2})"),
       {"planner.replan_period: expected a whole multiple of clock.dt (0.2 s) no longer than "
        "plan_period (1 s), got 2"}},
      {"GateProbabilityOne",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "tracking": {"gate_probability": 1.0})"),
       {"tracking.gate_probability: expected a probability in (0, 1)"}},
      // Issue 47: a body below Box2D's skin (1e-20 m turned every position into NaN), and the
      // existence thresholds that delete every track as it is born or confirmed.
      {"AgentRadiusBelowBox2dSkin",
       base(R"([{"start": [10, 10], "radius": 1e-20}])"),
       {"uavs[0].radius: expected 0 (no body) or at least 0.01 m", "got the number 1e-20"}},
      {"AgentRadiusDenormal",
       base(R"([{"start": [10, 10], "radius": 4.9e-324}])"),
       {"uavs[0].radius: expected 0 (no body) or at least 0.01 m"}},
      {"ConfirmBelowDelete",
       base("[{\"start\": [10, 10]}]", "[]",
            R"(, "tracking": {"confirm_existence": 0.3, "delete_existence": 0.5, "birth_existence": 0.6})"),
       {"tracking.delete_existence: expected delete_existence (0.5) at most confirm_existence (0.3)"}},
      {"BirthBelowDelete",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "tracking": {"birth_existence": 0.01})"),
       {"tracking.birth_existence: expected delete_existence (0.05) at most birth_existence (0.01)",
        "dropped at birth"}},
      {"UnknownFusionMethod",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "fusion": {"method": "kalman"})"),
       {"fusion.method: expected one of \"ci\", \"hcmci\", \"observer_average\""}},
      {"CommDropAboveOne",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "fusion": {"comm_drop": 1.5})"),
       {"fusion.comm_drop: expected a probability in [0, 1]"}},
      {"CommLatencyNegative",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "fusion": {"comm_latency": -1})"),
       {"fusion.comm_latency: expected an integer in [0, 1000]"}},
      {"OwnershipNamesUnknownTarget",
       base("[{\"start\": [10, 10]}]", "[]",
            R"(, "analysis": {"states": [{"name": "M0", "sets": [["ghost"]]}]})"),
       {"analysis.states[0].sets[0][0]: expected the name of a target, got \"ghost\""}},
      {"NegativeSeed",
       base("[{\"start\": [10, 10]}]", "[]", R"(, "seed": -3)"),
       {"seed: expected a non-negative integer, got the number -3"}},
      {"BadOverridePath",
       base(),
       {"--set: uavs.5.v_max: 'uavs' is an array of 1 elements"},
       {},
       "--set uavs.5.v_max=3",
       false},
      {"OverrideMakesValueInvalid",
       base(),
       {"planner.horizon: expected an integer in [1, 50], got the string \"abc\""},
       {},
       "--set planner.horizon=abc"},
      {"ControlCharactersInAName",
       base(R"([{"name": "\u001b[2J", "start": [1, 1]}, {"name": "\u001b[2J", "start": [2, 2]}])"),
       {"uavs[1].name: expected a unique UAV name, got \"\\x1B[2J\" twice"}},
      {"InvalidUtf8InAName",
       base(std::string(R"([{"name": "bad)") + "\xFF" + R"(", "start": [1, 1]}])"),
       {"invalid JSON", "ill-formed UTF-8"}},
      {"OverrideIndexBeyondEveryInteger",
       base(),
       {"--set: uavs.99999999999999999999999.v_max: 'uavs' is an array of 1 elements; expected an "
        "index below that, got '99999999999999999999999'"},
       {},
       "--set uavs.99999999999999999999999.v_max=3",
       false},
      {"OverrideNotUtf8",
       base(),
       {"--set: name=bad\\xFF: expected UTF-8 text"},
       {},
       "--set 'name=bad\xFF'",
       false},
      {"WaypointAltitudeOutsideLimits",
       base(R"([{"z": 20, "z_max": 30, "path": {"waypoints": [{"t": 0, "p": [10, 10]}, {"t": 5, "p": [20, 10], "z": 35}]}}])"),
       {"uavs[0].path.waypoints[1].z: expected an altitude within the UAV's [z_min, z_max] = [20, 30] m, got 35"}},
      {"TargetWaypointAltitude",
       base("[{\"start\": [10, 10]}]", R"([{"path": {"waypoints": [{"t": 0, "p": [20, 20], "z": 5}]}}])"),
       {"targets[0].path.waypoints[0].z: unknown field"}},
      {"OverrideNumberOverflow",
       base(),
       {"--set: uavs.0.v_max: expected a finite value, got '1e999'"},
       {},
       "--set uavs.0.v_max=1e999",
       false},
      {"OverrideNestedTooDeep",
       base(),
       {"--set: description: expected a value nested at most 64 levels deep"},
       {},
       "--set 'description=" + std::string(100, '[') + std::string(100, ']') + "'",
       false},
  };
  return table;
}
// clang-format on

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

struct Outcome {
  int exit_code = -1;
  std::string output;
};

Outcome runCanopy(const std::string& arguments) {
  Outcome outcome;
  const std::string command = std::string(CANOPY_BINARY) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

class MalformedScenario : public ::testing::TestWithParam<Case> {};

TEST_P(MalformedScenario, ExitsWithCode2AndNamesFileFieldAndExpectation) {
  const Case& c = GetParam();
  const fs::path dir = fs::temp_directory_path() / ("canopy_malformed_" + c.name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "scenario.json";
  std::ofstream(file) << c.scenario;
  for (const auto& [name, text] : c.extra_files) std::ofstream(dir / name) << text;

  const Outcome outcome = runCanopy("validate " + file.string() + " " + c.extra_args);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
  if (c.names_file) {
    EXPECT_NE(outcome.output.find(dir.string()), std::string::npos)
        << "file not named: " << outcome.output;
  }
  for (const std::string& fragment : c.expected) {
    EXPECT_NE(outcome.output.find(fragment), std::string::npos)
        << "missing \"" << fragment << "\" in: " << outcome.output;
  }
  // In the program's own words, and every byte of it safe for a terminal.
  for (const char* library : {"json.exception", "stoull", "filesystem error"}) {
    EXPECT_EQ(outcome.output.find(library), std::string::npos) << outcome.output;
  }
  for (const char ch : outcome.output) {
    const auto byte = static_cast<unsigned char>(ch);
    EXPECT_TRUE((byte >= 0x20 && byte != 0x7F) || byte == '\n') << "raw byte " << int(byte);
  }
}

INSTANTIATE_TEST_SUITE_P(Table, MalformedScenario, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return param.param.name;
                         });

TEST(MalformedScenarioTable, HoldsAtLeast25Cases) {
  EXPECT_GE(cases().size(), 25u);
}

TEST(CommandLine, MissingScenarioAndBadOptionsExitWith2) {
  EXPECT_EQ(runCanopy("validate /nonexistent/file.json").exit_code, 2);
  EXPECT_EQ(runCanopy("run demo --seed minus-one").exit_code, 2);
  EXPECT_EQ(runCanopy("run demo --frobnicate").exit_code, 2);
  EXPECT_EQ(runCanopy("forest --aoi 0,0,10 --lambda 1 --radius 1").exit_code, 2);
  EXPECT_EQ(runCanopy("frobnicate").exit_code, 2);
  const Outcome valid = runCanopy("validate demo");
  EXPECT_EQ(valid.exit_code, 0) << valid.output;
}

}  // namespace
