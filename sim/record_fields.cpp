#include "sim/record_fields.h"

namespace canopy::sim {
namespace record_tables {  // named, and holding its using-directive: unity builds merge files

using namespace codec;
using agents::AgentBelief;
using agents::TrackEstimate;
using agents::TreeEstimate;
using agents::planning::AgentPlanReport;
using agents::planning::IntentionMessage;
using agents::planning::TeamPlan;
using sensing::Observation;
using sensing::Scan;

struct ScanOf {  // the scans are a list of their own, one per UAV
  template <typename U>
  auto& operator()(U& uav) const {
    return uav.scan;
  }
};

// Each field: key, where its value lives, its codec (JSON type, how it is read), unit, compact
// packing, meaning. Tables list their fields in the order they are read and documented.
RecordSchema makeSchema() {
  return RecordSchema{
      .step = {field<StepRecord>(
                   "k", [](auto& s) -> auto& { return s.step; }, Int<Range::step>{}, "",
                   "structure: signed varint", "step index k (0 …)"),
               field<StepRecord>(
                   "t", [](auto& s) -> auto& { return s.time; }, Number{}, "s", "truth: double",
                   "time t = k·dt (s)"),
               field<StepRecord>(
                   "uavs", [](auto& s) -> auto& { return s.uavs; },
                   Objects<UavRecord, &RecordSchema::uavs, Count::uavs>{}, "", "structure: count",
                   "per UAV, in scenario order"),
               field<StepRecord>(
                   "targets", [](auto& s) -> auto& { return s.targets; },
                   Objects<TargetRecord, &RecordSchema::targets, Count::targets>{}, "",
                   "structure: count", "per target, in scenario order"),
               field<StepRecord>(
                   "scans", [](auto& s) -> auto& { return s.uavs; },
                   Objects<Scan, &RecordSchema::scans, Count::uavs, ScanOf>{}, "",
                   "one per UAV (of `uavs`)", "per UAV, what its camera reported this step")
                   .perAgent(),
               field<StepRecord>(
                   "agents", [](auto& s) -> auto& { return s.beliefs; },
                   Objects<AgentBelief, &RecordSchema::agents, Count::uavs>{}, "",
                   "structure: count", "per agent (one per UAV), its fused belief after this step")
                   .perAgent(),
               field<StepRecord>(
                   "plan", [](auto& s) -> auto& { return s.plan; },
                   Optional<TeamPlan, &RecordSchema::plan>{}, "", "structure: a flag",
                   "on planning epochs only")
                   .when([](const StepRecord& s) { return s.plan.has_value(); })},
      .targets = {field<TargetRecord>(
                      "p", [](auto& t) -> auto& { return t.position; }, Point{}, "m",
                      "truth: 2 doubles XOR the same target's at the step before",
                      "true position [x, y] (m)"),
                  field<TargetRecord>(
                      "v", [](auto& t) -> auto& { return t.velocity; }, Point{}, "m/s",
                      "truth: 2 doubles XOR the step before's",
                      "velocity applied over the last step [vx, vy] (m/s)")},
      .uavs =
          {field<UavRecord>(
               "p", [](auto& u) -> auto& { return u.position; }, Point{}, "m",
               "truth: 2 doubles XOR the same UAV's at the step before",
               "true position [x, y] (m)"),
           field<UavRecord>(
               "v", [](auto& u) -> auto& { return u.velocity; }, Point{}, "m/s",
               "truth: 2 doubles XOR the step before's", "velocity flown over the last step (m/s)"),
           field<UavRecord>(
               "yaw", [](auto& u) -> auto& { return u.yaw; }, Number{}, "rad",
               "truth: double XOR the step before's", "heading ψ (rad)"),
           field<UavRecord>(
               "z", [](auto& u) -> auto& { return u.z; }, Number{}, "m",
               "structure: a flag; truth: double XOR its last",
               "only for a UAV whose scenario gives an altitude (`z`, `z_min`, "
               "`z_max`, `climb_rate` or `camera`): its altitude (m)")
               .when([](const UavRecord& u) { return u.altitude; },
                     [](UavRecord& u) { u.altitude = true; }),
           field<UavRecord>(
               "cmd", [](auto& u) -> auto& { return u.command; }, Point{}, "m/s",
               "truth: 2 doubles XOR the step before's",
               "the command given this step by the planner or the path (m/s); what "
               "was flown is `v` of step k + 1"),
           field<UavRecord>(
               "contacts", [](auto& u) -> auto& { return u.contacts; }, Contacts{}, "",
               "structure: count, each (kind, index) signed varints",
               "only at a step during which the agent's body touched something: what, sorted: "
               "`\"wall:K\"` and `\"trunk:K\"` (K: the tree's index among the scenario's trees), "
               "`\"uav:J\"` (another agent); its `v` is then what it moved over the step")
               .when([](const UavRecord& u) { return !u.contacts.empty(); })},
      .scans = {field<Scan>(
                    "uav", [](auto& s) -> auto& { return s.uav; }, Int<Range::agent>{}, "",
                    "structure: signed varint", "the UAV's index"),
                field<Scan>(
                    "in_footprint", [](auto& s) -> auto& { return s.in_footprint; },
                    Ints<Range::target>{}, "", "structure: count, differences as signed varints",
                    "indices of the targets inside its footprint"),
                field<Scan>(
                    "visible", [](auto& s) -> auto& { return s.visible; }, Ints<Range::target>{},
                    "", "structure: count, differences as signed varints",
                    "indices of the targets inside its footprint and not occluded"),
                field<Scan>(
                    "obs", [](auto& s) -> auto& { return s.observations; },
                    Objects<Observation, &RecordSchema::observations>{}, "", "structure: count",
                    "the noisy labelled observations")},
      .observations =
          {field<Observation>(
               "z", [](auto& o) -> auto& { return o.z; }, Point{}, "m", "scans: 2 doubles",
               "measured position [x, y] (m)"),
           field<Observation>(
               "R", [](auto& o) -> auto& { return o.R; }, Upper<2>{}, "m²", "scans: 3 doubles",
               "its noise covariance, 2 × 2 packed as 3 numbers (m²)"),
           field<Observation>(
               "label", [](auto& o) -> auto& { return o.label; }, Label{}, "",
               "structure: label index (the labels are in each block's header)",
               "class label (a target label, `tree`, or the clutter label)"),
           field<Observation>(
               "radius", [](auto& o) -> auto& { return o.radius; }, Number{}, "m",
               "scans: double (label `tree` only)", "trees only: measured crown radius (m)")
               .when([](const Observation& o) { return o.label == sensing::kTreeLabel; }),
           field<Observation>(
               "truth", [](auto& o) -> auto& { return o.truth; }, Int<>{}, "",
               "structure: signed varint",
               "analysis only: the target's or tree's index, −1 for clutter")},
      .agents = {field<AgentBelief>(
                     "tracks", [](auto& b) -> auto& { return b.tracks; },
                     Objects<TrackEstimate, &RecordSchema::tracks>{}, "",
                     "structure: count, then per track its reference (the rule above)",
                     "its target tracks"),
                 field<AgentBelief>(
                     "map", [](auto& b) -> auto& { return b.trees; },
                     Objects<TreeEstimate, &RecordSchema::map>{}, "",
                     "structure: count, then per entry its reference (the rule above)",
                     "its dynamic occlusion map: tree tracks"),
                 field<AgentBelief>(
                     "planned_path", [](auto& b) -> auto& { return b.planned_path; }, Points{}, "m",
                     "structure: count; plans: 2 doubles a point",
                     "the agent's planned positions p_{i,1..H} (m); empty without a "
                     "plan")},
      .tracks = {field<TrackEstimate>(
                     "key", [](auto& t) -> auto& { return t.key; }, Key{}, "",
                     "structure: 2 signed varints (new tracks only)",
                     "the track's global key [origin agent, serial]; −1 for origin: "
                     "pre-seeded"),
                 field<TrackEstimate>(
                     "label", [](auto& t) -> auto& { return t.label; }, Label{}, "",
                     "structure: label index (new and changed tracks)", "class label"),
                 field<TrackEstimate>(
                     "x", [](auto& t) -> auto& { return t.belief.x; }, Mean<4>{}, "m, m/s",
                     "tracks: 4 doubles (changed: XOR, unchanged: none)",
                     "state [px, py, vx, vy] (m, m/s)"),
                 field<TrackEstimate>(
                     "P", [](auto& t) -> auto& { return t.belief.P; }, Upper<4>{},
                     "m², m²/s, m²/s²", "tracks: 10 doubles (changed: XOR, unchanged: none)",
                     "covariance, 4 × 4 packed as 10 numbers"),
                 field<TrackEstimate>(
                     "existence", [](auto& t) -> auto& { return t.existence; }, Number{}, "",
                     "tracks: double (changed: XOR, unchanged: none)",
                     "probability of existence (JIPDA; after fusion)")},
      .map = {field<TreeEstimate>(
                  "key", [](auto& t) -> auto& { return t.key; }, Key{}, "",
                  "structure: 2 signed varints (new entries only)", "the tree track's global key"),
              field<TreeEstimate>(
                  "x", [](auto& t) -> auto& { return t.belief.x; }, Mean<3>{}, "m",
                  "map: 3 doubles (changed: XOR, unchanged: none)",
                  "[cx, cy, r]: crown centre and radius (m)"),
              field<TreeEstimate>(
                  "P", [](auto& t) -> auto& { return t.belief.P; }, Upper<3>{}, "m²",
                  "map: 6 doubles (changed: XOR, unchanged: none)",
                  "covariance of x, 3 × 3 packed as 6 numbers"),
              field<TreeEstimate>(
                  "outline", [](auto& t) -> auto& { return t.outline; }, OutlinePoints{}, "m",
                  "structure: vertex count (new entries); map: 2 doubles a vertex "
                  "(changed: XOR, unchanged: none)",
                  "polygonal crowns and walls only: the estimated vertices' offsets "
                  "from [cx, cy], [[dx, dy], …] (m)")
                  .when([](const TreeEstimate& t) { return t.outline.vertices > 0; })},
      .plan = {field<TeamPlan>(
                   "epoch", [](auto& p) -> auto& { return p.epoch; }, Int<>{}, "",
                   "structure: signed varint", "the planning epoch's index"),
               field<TeamPlan>(
                   "agents", [](auto& p) -> auto& { return p.reports; },
                   Objects<AgentPlanReport, &RecordSchema::plan_agents>{}, "", "structure: count",
                   "per planning agent"),
               field<TeamPlan>(
                   "messages", [](auto& p) -> auto& { return p.messages; },
                   Objects<IntentionMessage, &RecordSchema::messages>{}, "", "structure: count",
                   "intention messages sent this epoch, in the order sent (SMA-NBO: "
                   "the planning order); what each agent held is "
                   "`plan.agents[].joint_epoch`")},
      .plan_agents = {field<AgentPlanReport>(
                          "agent", [](auto& r) -> auto& { return r.agent; }, Int<Range::agent>{},
                          "", "structure: signed varint", "the agent's index"),
                      field<AgentPlanReport>(
                          "cost", [](auto& r) -> auto& { return r.cost; }, Number{}, "m²",
                          "plans: double",
                          "the plan's cost J (m², trace of covariances summed over the "
                          "horizon)"),
                      field<AgentPlanReport>(
                          "evaluations", [](auto& r) -> auto& { return r.evaluations; }, Long{}, "",
                          "structure: signed varint", "cost evaluations spent"),
                      field<AgentPlanReport>(
                          "iterations", [](auto& r) -> auto& { return r.iterations; }, Int<>{}, "",
                          "structure: signed varint", "swarm iterations spent"),
                      field<AgentPlanReport>(
                          "joint_epoch", [](auto& r) -> auto& { return r.joint_epoch; },
                          Ints<Range::any, Count::uavs>{}, "", "structure: count, signed varints",
                          "per UAV, the epoch of the plan this agent planned against "
                          "(SMA-NBO: the latest intention that had reached it, −1 none; "
                          "Dec-POMDP and centralised: the joint plan's epoch)"),
                      field<AgentPlanReport>(
                          "velocities", [](auto& r) -> auto& { return r.plan.velocities; },
                          Points{}, "m/s", "structure: count; plans: 2 doubles an action",
                          "the planned actions a_{i,1..H} (m/s)")},
      .messages = {field<IntentionMessage>(
                       "agent", [](auto& m) -> auto& { return m.agent; }, Int<Range::agent>{}, "",
                       "structure: signed varint",
                       "the UAV whose actions it holds (the sender, except for "
                       "centralised orders)"),
                   field<IntentionMessage>(
                       "from", [](auto& m) -> auto& { return m.from; }, Int<Range::agent>{}, "",
                       "structure: signed varint", "the sender"),
                   field<IntentionMessage>(
                       "epoch", [](auto& m) -> auto& { return m.epoch; }, Int<>{}, "",
                       "structure: signed varint", "the epoch at which the plan was made"),
                   field<IntentionMessage>(
                       "velocities", [](auto& m) -> auto& { return m.plan.velocities; }, Points{},
                       "m/s", "structure: count; plans: 2 doubles an action",
                       "the sender's planned actions (m/s)")},
  };
}

}  // namespace record_tables

const RecordSchema& recordSchema() {
  static const RecordSchema schema = record_tables::makeSchema();
  return schema;
}

std::vector<RecordField> recordFields(const RecordSchema& schema) {
  std::vector<RecordField> rows;
  documentRows(schema, schema.step, "", rows);
  return rows;
}

std::string recordFieldsMarkdown(const RecordSchema& schema) {
  std::string page = std::string(kRecordFieldsBegin) + "\n\n";
  page += "| key | type | unit | compact packing | meaning |\n|---|---|---|---|---|\n";
  for (const RecordField& f : recordFields(schema)) {
    page += "| `" + f.path + "` | " + f.type + " | " + f.unit + " | " + f.packing + " | " +
            f.meaning + " |\n";
  }
  page += std::string("\n") + kRecordFieldsEnd + "\n";
  return page;
}

namespace codec {

const char* Contacts::kindName(world::BodyKind kind) {
  return kind == world::BodyKind::trunk  ? "trunk"
         : kind == world::BodyKind::wall ? "wall"
         : kind == world::BodyKind::uav  ? "uav"
         : kind == world::BodyKind::tree ? "tree"
                                         : "target";
}

void Contacts::write(LineOut& out, const std::vector<world::BodyRef>& list) {
  out.j.beginArray();
  for (const world::BodyRef& c : list) out.j.escapedString("\"" + name(c) + "\"");
  out.j.endArray();
}

void Contacts::read(const LineIn& in, const Json& v, std::vector<world::BodyRef>& list,
                    const At& at) {
  if (!v.is_array()) in.fail(at, "a list of \"kind:index\" strings");
  list.clear();
  for (const Json& c : v) {
    world::BodyRef& r = list.emplace_back();
    bool known = false;
    if (c.is_string()) {
      const std::string& text = c.get_ref<const std::string&>();
      for (const world::BodyKind kind :
           {world::BodyKind::wall, world::BodyKind::trunk, world::BodyKind::uav,
            world::BodyKind::tree, world::BodyKind::target}) {
        const std::string prefix = std::string(kindName(kind)) + ":";
        const std::size_t n = prefix.size();
        if (text.compare(0, n, prefix) != 0 || text.size() == n || text.size() > n + 9) continue;
        if (text.find_first_not_of("0123456789", n) != std::string::npos) continue;
        r = {kind, std::stoi(text.substr(n))};
        known = true;
      }
    }
    if (!known) in.fail(at, "\"wall:K\", \"trunk:K\" or \"uav:J\"");
  }
}

}  // namespace codec

}  // namespace canopy::sim
