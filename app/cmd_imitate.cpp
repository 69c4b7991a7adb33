// `canopy imitate`: demonstrations for the learned planner (issue 54, docs/imitation.md).
//   collect SCENARIO: runs trials and writes every agent's decision as (observation, expert action)
//   eval POLICY FILE: the policy network's output u for each observation line of FILE
#include <cstdio>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "agents/planning/policy_network.h"
#include "app/commands.h"
#include "core/output_file.h"
#include "core/task_pool.h"
#include "sim/simulation.h"
#include "sim/step_observer.h"
#include "spec/error.h"
#include "spec/json_text.h"
#include "spec/loader.h"
#include "spec/policy_file.h"

namespace canopy::app {
namespace {

using Json = nlohmann::json;
using agents::planning::Decision;
using agents::planning::kMateFeatures;
using agents::planning::kSelfFeatures;
using agents::planning::kTrackFeatures;
using agents::planning::Observation;

Json rows(const std::vector<double>& flat, int width) {
  Json out = Json::array();
  for (std::size_t r = 0; r + static_cast<std::size_t>(width) <= flat.size(); r += width)
    out.push_back(std::vector<double>(flat.begin() + static_cast<std::ptrdiff_t>(r),
                                      flat.begin() + static_cast<std::ptrdiff_t>(r + width)));
  return out;
}

// One trial's decisions as JSON lines.
std::string collectTrial(spec::ScenarioSpec spec, int trial, bool label) {
  sim::Simulation sim(spec);
  std::string lines;
  sim.observeDecisions(
      [&](const Decision& d) {
        Json line = {{"trial", trial},
                     {"seed", spec.seed},
                     {"epoch", d.epoch},
                     {"agent", d.agent},
                     {"v_max", d.v_max},
                     {"self", d.observation.self},
                     {"tracks", rows(d.observation.tracks, kTrackFeatures)},
                     {"mates", rows(d.observation.mates, kMateFeatures)},
                     {"expert", {d.expert.x(), d.expert.y()}},
                     {"flown", {d.flown.x(), d.flown.y()}}};
        lines += line.dump() + "\n";
      },
      label);
  sim::runToEnd(sim, {});
  return lines;
}

// The flat features of one observation line; errors name `file`, the line and the field.
Observation readObservation(const Json& line, const std::string& file, const std::string& where) {
  auto fail = [&](const std::string& field, const std::string& message) {
    throw spec::ScenarioError(file, where + field, message);
  };
  auto numbers = [&](const Json& array, std::size_t size, const std::string& field,
                     std::vector<double>& out) {
    if (!array.is_array() || array.size() != size)
      fail(field, "expected an array of " + std::to_string(size) + " numbers");
    for (const Json& x : array) {
      if (!x.is_number()) fail(field, "expected numbers");
      out.push_back(x.get<double>());
    }
  };
  Observation o;
  if (!line.is_object()) fail("", "expected an object");
  auto get = [&](const char* key) -> const Json& {
    if (!line.contains(key)) fail(key, "missing");
    return line.at(key);
  };
  numbers(get("self"), kSelfFeatures, "self", o.self);
  for (const char* key : {"tracks", "mates"}) {
    const Json& set = get(key);
    if (!set.is_array()) fail(key, "expected an array of rows");
    const bool tracks = std::string(key) == "tracks";
    for (std::size_t r = 0; r < set.size(); ++r) {
      numbers(set[r], tracks ? kTrackFeatures : kMateFeatures,
              std::string(key) + "[" + std::to_string(r) + "]", tracks ? o.tracks : o.mates);
    }
  }
  return o;
}

class Imitate : public Command {
 public:
  explicit Imitate(CLI::App& canopy)
      : Command(canopy, "imitate", "canopy imitate collect SCENARIO --out FILE [options] | "
                                   "canopy imitate eval POLICY OBSERVATIONS",
                "Demonstrations for the learned planner (docs/imitation.md). collect: runs "
                "--trials trials of SCENARIO (seeds --seed, --seed + 1, …) and writes every "
                "agent's decision at every planning epoch as a JSON line (its observation, the "
                "expert's action, the action flown): with planner.algorithm sma or dec_pomdp the "
                "expert flies; with learned the policy flies and SMA-NBO labels each state "
                "(DAgger). eval: the policy's output u = tanh(ρ) for each observation line of a "
                "file (a demonstration file or lines {\"self\", \"tracks\", \"mates\"}), one "
                "[ux, uy] line each.") {
    CLI::App& o = options();
    o.add_option("ACTION", action_, "collect or eval")->required();
    o.add_option("ARGS", args_, "collect: SCENARIO; eval: POLICY OBSERVATIONS");
    o.add_option("--out", out_, "collect: the demonstration file to write (JSON lines)");
    addValue(o, "--trials", "N", trials_, integerIn(1, 100000), "collect: trials (default 1)");
    addValue(o, "--seed", "S", seed_, nonNegativeInteger(),
             "collect: the first trial's seed (default: the scenario's)");
    addValue(o, "--jobs", "N", jobs_, integerIn(1, 256), "collect: trials run at once (default 1)");
    o.add_option("--set", load_.overrides, "override a field by its dotted path (repeatable)")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    addLoadOptions(o, load_);
  }
  int run() override;

 private:
  int collect();
  int eval();
  std::string action_, out_;
  std::vector<std::string> args_;
  int trials_ = 1, jobs_ = 1;
  std::optional<std::uint64_t> seed_;
  spec::LoadOptions load_;
};

int Imitate::run() {
  if (action_ == "collect") return collect();
  if (action_ == "eval") return eval();
  usageError("imitate", "expected the action collect or eval, got '" + action_ + "'");
}

int Imitate::collect() {
  if (args_.size() != 1) usageError("imitate collect", "expected one SCENARIO");
  if (out_.empty()) usageError("imitate collect", "expected --out FILE");
  const spec::ScenarioSpec base = spec::loadScenario(args_[0], load_);
  const agents::PlannerAlgorithm algorithm = base.planner.algorithm;
  if (algorithm != agents::PlannerAlgorithm::sma &&
      algorithm != agents::PlannerAlgorithm::dec_pomdp &&
      algorithm != agents::PlannerAlgorithm::learned) {
    usageError("imitate collect", "expected planner.algorithm sma, dec_pomdp or learned, got " +
                                      std::string(nameOf(agents::kPlannerAlgorithmNames, algorithm)));
  }
  checkOutputFile(out_);
  const bool learned = algorithm == agents::PlannerAlgorithm::learned;
  const std::uint64_t first = seed_.value_or(base.seed);
  std::vector<std::string> trials(static_cast<std::size_t>(trials_));
  TaskPool pool(jobs_);
  std::mutex progress;
  int done = 0;
  forEachTask(jobs_ > 1 ? &pool : nullptr, trials.size(), [&](std::size_t k) {
    spec::ScenarioSpec spec = base;
    spec.seed = first + k;
    trials[k] = collectTrial(spec, static_cast<int>(k), learned);
    const std::lock_guard<std::mutex> lock(progress);
    std::fprintf(stderr, "\rcanopy imitate collect: %d/%d trials", ++done, trials_);
  });
  std::fprintf(stderr, "\n");
  const Json header = {
      {"format", "canopy-demonstrations"},
      {"version", 1},
      {"features", {{"self", kSelfFeatures}, {"track", kTrackFeatures}, {"mate", kMateFeatures}}},
      {"scenario", base.name},
      {"flown", nameOf(agents::kPlannerAlgorithmNames, algorithm)},
      {"expert", learned ? "sma" : nameOf(agents::kPlannerAlgorithmNames, algorithm)},
      {"horizon", base.planner.horizon},
      {"trials", trials_},
      {"seed", first}};
  AtomicFile file(out_);
  file.write(header.dump() + "\n");
  for (const std::string& lines : trials) file.write(lines);
  file.commit();
  return kExitOk;
}

int Imitate::eval() {
  if (args_.size() != 2) usageError("imitate eval", "expected POLICY OBSERVATIONS");
  const auto policy = spec::readPolicyFile(args_[0]);
  const std::string text = spec::readResultText(args_[1], "observation lines (JSON)",
                                                spec::kMaxResultBytes, true);
  std::size_t start = 0;
  int number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "line " + std::to_string(number) + ": ";
    Json value;
    try {
      value = spec::parseBoundedJson(line);
    } catch (const std::exception&) {
      throw spec::ScenarioError(args_[1], where, "expected a JSON object");
    }
    if (value.is_object() && value.contains("format")) continue;  // a demonstration header
    const Vec2 u = policy->output(readObservation(value, args_[1], where));
    std::printf("[%.17g, %.17g]\n", u.x(), u.y());
  }
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeImitate(CLI::App& canopy) {
  return std::make_unique<Imitate>(canopy);
}

}  // namespace canopy::app
