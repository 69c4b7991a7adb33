// Reading the settings sections: sensing, tracking, fusion, planner, analysis.
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "spec/internal/referenced_file.h"
#include "spec/internal/sections.h"
#include "spec/loader.h"
#include "spec/policy_file.h"

namespace canopy::spec::internal {
namespace {

// A section that may be absent: read as an empty object, so every default is recorded.
// Existence confirmation drops a track once r < delete_existence (agents/tracking/tracker.cpp):
// a newborn track (r = birth_existence) below it is dropped at birth, so no track is ever made,
// and a track confirmed at r = confirm_existence below it is deleted at once. Hence
// delete_existence ≤ birth_existence and delete_existence ≤ confirm_existence. The field blamed
// is the one the file gives (delete_existence when both are given or neither).
void checkExistenceThresholds(ObjectReader& reader, const agents::TrackingConfig& t) {
  if (t.confirmation != agents::TrackConfirmation::existence) return;
  const auto text = [](double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  };
  const auto check = [&](const char* other, double value) {
    if (t.delete_existence <= value) return;
    const char* blamed =
        reader.optional("delete_existence") || !reader.optional(other) ? "delete_existence" : other;
    reader.required(blamed).fail(
        std::string("expected delete_existence (") + text(t.delete_existence) + ") at most " +
        other + " (" + text(value) + "): a track is dropped once its existence falls below " +
        "delete_existence, so " +
        (std::string(other) == "birth_existence"
             ? "every newborn track would be dropped at birth"
             : "every track would be deleted as it is confirmed"));
  };
  check("birth_existence", t.birth_existence);
  check("confirm_existence", t.confirm_existence);
}

ObjectReader section(ObjectReader& root, const std::string& key) {
  static const Json kEmpty = Json::object();
  if (auto field = root.optional(key)) return field->object();
  Json* slot = &(*root.field().out())[key];
  return Field(kEmpty, root.field().file(), key, slot, root.field().context()).object();
}

void readPso(ObjectReader& planner, agents::PsoConfig& pso) {
  ObjectReader reader = section(planner, "pso");
  pso.particles_per_step = reader.integer("particles_per_step", pso.particles_per_step, 1, 10000);
  pso.inertia = reader.number("inertia", pso.inertia, Bound::non_negative);
  pso.c1 = reader.number("c1", pso.c1, Bound::non_negative);
  pso.c2 = reader.number("c2", pso.c2, Bound::non_negative);
  pso.ftol = reader.number("ftol", pso.ftol, Bound::positive);
  pso.stall_iterations = reader.integer("stall_iterations", pso.stall_iterations, 1, 1000000);
  pso.max_iterations = reader.integer("max_iterations", pso.max_iterations, 1, 1000000);
  pso.warm_start = reader.boolean("warm_start", pso.warm_start);
  reader.finish();
}

}  // namespace

std::string readSensing(ObjectReader& root, ScenarioSpec& spec) {
  ObjectReader reader = section(root, "sensing");
  sensing::SensingConfig& s = spec.sensing;
  s.occlusion_model =
      reader.enumeration("occlusion_model", sensing::kOcclusionModelNames, s.occlusion_model);
  s.p_detect = reader.number("p_detect", s.p_detect, Bound::probability);
  s.clutter_rate = reader.number("clutter_rate", s.clutter_rate, Bound::non_negative);
  if (s.clutter_rate > 1000.0) {
    reader.required("clutter_rate").fail("expected at most 1000 clutter points per scan");
  }
  const std::string clutter_label = reader.string("clutter_label", "human");
  if (clutter_label == "tree" || clutter_label.empty()) {
    reader.required("clutter_label").fail("expected a target label other than \"tree\"");
  }
  s.truth_noise_scale =
      reader.number("truth_noise_scale", s.truth_noise_scale, Bound::non_negative);
  s.tree_radius_sigma =
      reader.number("tree_radius_sigma", s.tree_radius_sigma, Bound::non_negative);
  reader.finish();
  return clutter_label;
}

void readTracking(ObjectReader& root, ScenarioSpec& spec) {
  ObjectReader reader = section(root, "tracking");
  agents::TrackingConfig& t = spec.tracking;
  t.sigma_a = reader.number("sigma_a", t.sigma_a, Bound::positive);
  t.gate_probability =
      reader.number("gate_probability", t.gate_probability, Bound::open_probability);
  t.birth_gate_probability =
      reader.number("birth_gate_probability", t.birth_gate_probability, Bound::open_probability);
  t.p_detect = reader.number("p_detect", t.p_detect, Bound::unit_interval);
  t.clutter_density = reader.number("clutter_density", t.clutter_density, Bound::positive);
  t.max_hypotheses = reader.integer("max_hypotheses", t.max_hypotheses, 1, 10000000);
  t.birth_velocity_sigma =
      reader.number("birth_velocity_sigma", t.birth_velocity_sigma, Bound::positive);
  t.confirm_hits = reader.integer("confirm_hits", t.confirm_hits, 1, 100);
  t.confirm_window = reader.integer("confirm_window", std::max(t.confirm_window, t.confirm_hits),
                                    t.confirm_hits, 100);
  t.delete_trace = reader.number("delete_trace", t.delete_trace, Bound::positive);
  t.delete_misses = reader.integer("delete_misses", t.delete_misses, 0, 1000000);
  t.preseed = reader.boolean("preseed", t.preseed);
  if (auto variance = reader.optional("preseed_variance")) {
    const std::vector<Field> v = variance->elements(4, 4);
    for (int i = 0; i < 4; ++i) t.preseed_variance[i] = v[i].number(Bound::positive);
  } else {
    (*reader.field().out())["preseed_variance"] = Json{1.0, 1.0, 1.0, 1.0};
  }
  t.tree_min_radius = reader.number("tree_min_radius", t.tree_min_radius, Bound::non_negative);
  t.confirmation =
      reader.enumeration("confirmation", agents::kTrackConfirmationNames, t.confirmation);
  t.survival_probability =
      reader.number("survival_probability", t.survival_probability, Bound::unit_interval);
  t.birth_existence = reader.number("birth_existence", t.birth_existence, Bound::open_probability);
  t.confirm_existence =
      reader.number("confirm_existence", t.confirm_existence, Bound::unit_interval);
  t.delete_existence = reader.number("delete_existence", t.delete_existence, Bound::unit_interval);
  t.merge_gate = reader.number("merge_gate", t.merge_gate, Bound::non_negative);
  t.merge_scans = reader.integer("merge_scans", t.merge_scans, 0, 1000);
  t.merge_distance = reader.number("merge_distance", t.merge_distance, Bound::positive);
  t.walk_speed = reader.number("walk_speed", t.walk_speed, Bound::positive);
  t.negative_information = reader.boolean("negative_information", t.negative_information);
  checkExistenceThresholds(reader, t);
  reader.finish();
}

void readFusion(ObjectReader& root, ScenarioSpec& spec) {
  ObjectReader reader = section(root, "fusion");
  agents::FusionConfig& f = spec.fusion;
  f.method = reader.enumeration("method", agents::kFusionMethodNames, f.method);
  f.rounds = reader.integer("rounds", f.rounds, 0, 1000);
  if (auto range = reader.optional("comm_range"); range && !range->json().is_null()) {
    f.comm_range = range->number(Bound::positive);
  } else {
    (*reader.field().out())["comm_range"] = nullptr;  // null: every pair of UAVs can talk
  }
  if (auto range = reader.optional("interest_range"); range && !range->json().is_null())
    f.interest_range = range->number(Bound::positive);
  f.comm_drop = reader.number("comm_drop", f.comm_drop, Bound::probability);
  f.comm_latency = reader.integer("comm_latency", f.comm_latency, 0, 1000);
  f.association_gate = reader.number("association_gate", f.association_gate, Bound::positive);
  reader.finish();
}

void readPlanner(ObjectReader& root, ScenarioSpec& spec) {
  ObjectReader reader = section(root, "planner");
  agents::PlannerConfig& p = spec.planner;
  p.algorithm = reader.enumeration("algorithm", agents::kPlannerAlgorithmNames, p.algorithm);
  p.horizon = reader.integer("horizon", p.horizon, 1, 50);
  p.plan_period = reader.number("plan_period", p.plan_period, Bound::positive);
  const double ratio = p.plan_period / spec.dt;
  if (std::abs(ratio - std::round(ratio)) > 1e-6 * ratio) {
    std::ostringstream text;
    text << "expected a whole multiple of clock.dt (" << spec.dt << " s), got " << p.plan_period;
    reader.required("plan_period").fail(text.str());
  }
  p.replan_period = reader.number("replan_period", p.plan_period, Bound::positive);
  const double replans = p.replan_period / spec.dt;
  if (std::abs(replans - std::round(replans)) > 1e-6 * replans ||
      p.replan_period > p.plan_period * (1.0 + 1e-9)) {
    std::ostringstream text;
    text << "expected a whole multiple of clock.dt (" << spec.dt
         << " s) no longer than plan_period (" << p.plan_period << " s), got " << p.replan_period;
    reader.required("replan_period").fail(text.str());
  }
  p.occlusion_map =
      reader.enumeration("occlusion_map", agents::kOcclusionMapModeNames, p.occlusion_map);
  p.discount = reader.number("discount", p.discount, Bound::unit_interval);
  const int trace = reader.choice("cost_trace", {"position", "full", "custody"},
                                  p.custody ? 2 : (p.full_trace ? 1 : 0));
  p.full_trace = trace == 1;
  p.custody = trace == 2;
  p.custody_radius = reader.number("custody_radius", p.custody_radius, Bound::positive);
  p.terminal_penalty = reader.boolean("terminal_penalty", p.terminal_penalty);
  p.terminal_penalty_weight =
      reader.number("terminal_penalty_weight", p.terminal_penalty_weight, Bound::non_negative);
  p.cost_substeps = reader.integer("cost_substeps", p.cost_substeps, 1, 100);
  p.clearance = reader.number("clearance", p.clearance, Bound::non_negative);
  if (p.clearance > 100.0) reader.required("clearance").fail("expected at most 100 m");
  p.cost_scope = reader.enumeration("cost_scope", agents::kCostScopeNames, p.cost_scope);
  readPso(reader, p.pso);
  p.joint_search = reader.enumeration("joint_search", agents::kJointSearchNames, p.joint_search);
  p.joint_rounds = reader.integer("joint_rounds", p.joint_rounds, 1, 20);
  p.joint_blocks = reader.enumeration("joint_blocks", agents::kJointBlocksNames, p.joint_blocks);
  // The learned planner's network: planner.policy, or the shipped policy of the scenario's name
  // (policies/NAME.json in the scenario library), else the Trajectory Handover policy.
  p.policy = nullptr;
  if (auto policy = reader.optional("policy")) {
    const ReferencedFile file = readReferencedFile(*policy, "policy file", libraryDir());
    if (p.algorithm == agents::PlannerAlgorithm::learned)
      p.policy = parsePolicy(file.text, file.shown);
  } else if (p.algorithm == agents::PlannerAlgorithm::learned) {
    std::string name = "policies/" + spec.name + ".json";
    std::error_code error;
    if (spec.name.empty() || spec.name.find('/') != std::string::npos ||
        !std::filesystem::is_regular_file(libraryDir() / name, error))
      name = "policies/trajectory_handover.json";
    (*reader.field().out())["policy"] = name;
    const Json value = name;
    const Field field(value, reader.field().file(), reader.field().path() + ".policy", nullptr,
                      reader.field().context());
    const ReferencedFile file = readReferencedFile(field, "policy file", libraryDir());
    p.policy = parsePolicy(file.text, file.shown);
  }
  p.order.clear();
  if (auto order = reader.optional("order")) {
    const std::size_t n = spec.uavs.size();
    std::set<int> seen;
    for (const Field& entry : order->elements(n, n)) {
      const int i = uavIndex(entry, spec);
      if (!seen.insert(i).second) entry.fail("expected each UAV once in the planning order");
      p.order.push_back(i);
    }
  } else {
    Json names = Json::array();
    for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
      p.order.push_back(static_cast<int>(i));
      names.push_back(spec.uavs[i].name);
    }
    (*reader.field().out())["order"] = names;
  }
  reader.finish();
}

void readAnalysis(ObjectReader& root, ScenarioSpec& spec) {
  ObjectReader reader = section(root, "analysis");
  spec.analysis.m = reader.integer("m", spec.analysis.m, 1, 100000);
  spec.analysis.oa_margin =
      reader.number("oa_margin", spec.analysis.oa_margin, Bound::non_negative);
  if (auto states = reader.optional("states")) {
    std::set<std::string> names;
    for (const Field& element : states->elements()) {
      ObjectReader state = element.object();
      NamedOwnership named;
      named.name = state.required("name").string();
      if (named.name.empty() || !names.insert(named.name).second) {
        state.required("name").fail("expected a unique, non-empty state name");
      }
      const std::size_t n = spec.uavs.size();
      for (const Field& set_field : state.required("sets").elements(n, n)) {
        std::vector<int> set;
        for (const Field& target : set_field.elements()) set.push_back(targetIndex(target, spec));
        std::sort(set.begin(), set.end());
        if (std::adjacent_find(set.begin(), set.end()) != set.end()) {
          set_field.fail("expected each target at most once in a UAV's set");
        }
        named.sets.push_back(std::move(set));
      }
      named.any_permutation = state.boolean("any_permutation", false);
      state.finish();
      spec.analysis.states.push_back(std::move(named));
    }
  } else {
    (*reader.field().out())["states"] = Json::array();
  }
  reader.finish();
}

}  // namespace canopy::spec::internal
