#include "sim/record_fields.h"

namespace canopy::sim {

const std::vector<RecordField>& recordFields() {
  static const std::vector<RecordField> fields = {
      {"k", "integer", "", "structure: signed varint", "step index k (0 …)"},
      {"t", "number", "s", "truth: double", "time t = k·dt (s)"},
      {"targets", "list", "", "structure: count", "per target, in scenario order"},
      {"targets[].p", "[number, number]", "m",
       "truth: 2 doubles XOR the same target's at the step before", "true position [x, y] (m)"},
      {"targets[].v", "[number, number]", "m/s", "truth: 2 doubles XOR the step before's",
       "velocity applied over the last step [vx, vy] (m/s)"},
      {"uavs", "list", "", "structure: count", "per UAV, in scenario order"},
      {"uavs[].p", "[number, number]", "m",
       "truth: 2 doubles XOR the same UAV's at the step before", "true position [x, y] (m)"},
      {"uavs[].v", "[number, number]", "m/s", "truth: 2 doubles XOR the step before's",
       "velocity flown over the last step (m/s)"},
      {"uavs[].yaw", "number", "rad", "truth: double XOR the step before's", "heading ψ (rad)"},
      {"uavs[].z", "number", "m", "structure: a flag; truth: double XOR its last",
       "only for a UAV whose scenario gives an altitude (`z`, `z_min`, `z_max`, `climb_rate` or "
       "`camera`): its altitude (m)"},
      {"uavs[].cmd", "[number, number]", "m/s", "truth: 2 doubles XOR the step before's",
       "the command given this step by the planner or the path (m/s); what was flown is `v` of "
       "step k + 1"},
      {"uavs[].contacts", "[string]", "", "structure: count, each (kind, index) signed varints",
       "only at a step during which the agent's body touched something: what, sorted: `\"wall:K\"` "
       "and `\"trunk:K\"` (K: the tree's index among the scenario's trees), `\"uav:J\"` (another "
       "agent); its `v` is then what it moved over the step"},
      {"scans", "list", "", "one per UAV (of `uavs`)",
       "per UAV, what its camera reported this step"},
      {"scans[].uav", "integer", "", "structure: signed varint", "the UAV's index"},
      {"scans[].in_footprint", "[integer]", "", "structure: count, differences as signed varints",
       "indices of the targets inside its footprint"},
      {"scans[].visible", "[integer]", "", "structure: count, differences as signed varints",
       "indices of the targets inside its footprint and not occluded"},
      {"scans[].obs", "list", "", "structure: count", "the noisy labelled observations"},
      {"scans[].obs[].z", "[number, number]", "m", "scans: 2 doubles",
       "measured position [x, y] (m)"},
      {"scans[].obs[].R", "[number × 3]", "m²", "scans: 3 doubles",
       "its noise covariance, 2 × 2 packed as 3 numbers (m²)"},
      {"scans[].obs[].label", "string", "",
       "structure: label index (the labels are in each block's header)",
       "class label (a target label, `tree`, or the clutter label)"},
      {"scans[].obs[].radius", "number", "m", "scans: double (label `tree` only)",
       "trees only: measured crown radius (m)"},
      {"scans[].obs[].truth", "integer", "", "structure: signed varint",
       "analysis only: the target's or tree's index, −1 for clutter"},
      {"agents", "list", "", "structure: count",
       "per agent (one per UAV), its fused belief after this step"},
      {"agents[].tracks", "list", "",
       "structure: count, then per track its reference (the rule above)", "its target tracks"},
      {"agents[].tracks[].key", "[integer, integer]", "",
       "structure: 2 signed varints (new tracks only)",
       "the track's global key [origin agent, serial]; −1 for origin: pre-seeded"},
      {"agents[].tracks[].label", "string", "", "structure: label index (new and changed tracks)",
       "class label"},
      {"agents[].tracks[].x", "[number × 4]", "m, m/s",
       "tracks: 4 doubles (changed: XOR, unchanged: none)", "state [px, py, vx, vy] (m, m/s)"},
      {"agents[].tracks[].P", "[number × 10]", "m², m²/s, m²/s²",
       "tracks: 10 doubles (changed: XOR, unchanged: none)",
       "covariance, 4 × 4 packed as 10 numbers"},
      {"agents[].tracks[].existence", "number", "",
       "tracks: double (changed: XOR, unchanged: none)",
       "probability of existence (JIPDA; after fusion)"},
      {"agents[].map", "list", "",
       "structure: count, then per entry its reference (the rule above)",
       "its dynamic occlusion map: tree tracks"},
      {"agents[].map[].key", "[integer, integer]", "",
       "structure: 2 signed varints (new entries only)", "the tree track's global key"},
      {"agents[].map[].x", "[number × 3]", "m", "map: 3 doubles (changed: XOR, unchanged: none)",
       "[cx, cy, r]: crown centre and radius (m)"},
      {"agents[].map[].P", "[number × 6]", "m²", "map: 6 doubles (changed: XOR, unchanged: none)",
       "covariance of x, 3 × 3 packed as 6 numbers"},
      {"agents[].map[].outline", "[[number, number]]", "m",
       "structure: vertex count (new entries); map: 2 doubles a vertex (changed: XOR, unchanged: "
       "none)",
       "polygonal crowns and walls only: the estimated vertices' offsets from [cx, cy], [[dx, dy], "
       "…] (m)"},
      {"agents[].planned_path", "[[number, number]]", "m",
       "structure: count; plans: 2 doubles a point",
       "the agent's planned positions p_{i,1..H} (m); empty without a plan"},
      {"plan", "object", "", "structure: a flag", "on planning epochs only"},
      {"plan.epoch", "integer", "", "structure: signed varint", "the planning epoch's index"},
      {"plan.agents", "list", "", "structure: count", "per planning agent"},
      {"plan.agents[].agent", "integer", "", "structure: signed varint", "the agent's index"},
      {"plan.agents[].cost", "number", "m²", "plans: double",
       "the plan's cost J (m², trace of covariances summed over the horizon)"},
      {"plan.agents[].evaluations", "integer", "", "structure: signed varint",
       "cost evaluations spent"},
      {"plan.agents[].iterations", "integer", "", "structure: signed varint",
       "swarm iterations spent"},
      {"plan.agents[].joint_epoch", "[integer]", "", "structure: count, signed varints",
       "per UAV, the epoch of the plan this agent planned against (SMA-NBO: the latest intention "
       "that had reached it, −1 none; Dec-POMDP and centralised: the joint plan's epoch)"},
      {"plan.agents[].velocities", "[[number, number]]", "m/s",
       "structure: count; plans: 2 doubles an action", "the planned actions a_{i,1..H} (m/s)"},
      {"plan.messages", "list", "", "structure: count",
       "intention messages sent this epoch, in the order sent (SMA-NBO: the planning order); what "
       "each agent held is `plan.agents[].joint_epoch`"},
      {"plan.messages[].agent", "integer", "", "structure: signed varint",
       "the UAV whose actions it holds (the sender, except for centralised orders)"},
      {"plan.messages[].from", "integer", "", "structure: signed varint", "the sender"},
      {"plan.messages[].epoch", "integer", "", "structure: signed varint",
       "the epoch at which the plan was made"},
      {"plan.messages[].velocities", "[[number, number]]", "m/s",
       "structure: count; plans: 2 doubles an action", "the sender's planned actions (m/s)"},
  };
  return fields;
}

std::string recordFieldsMarkdown() {
  std::string page = std::string(kRecordFieldsBegin) + "\n\n";
  page += "| key | type | unit | compact packing | meaning |\n|---|---|---|---|---|\n";
  for (const RecordField& f : recordFields()) {
    page += std::string("| `") + f.path + "` | " + f.type + " | " + f.unit + " | " + f.packing +
            " | " + f.meaning + " |\n";
  }
  page += std::string("\n") + kRecordFieldsEnd + "\n";
  return page;
}

}  // namespace canopy::sim
