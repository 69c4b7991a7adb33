#include "replay/replay_changes.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "replay/replay_data.h"

namespace canopy::replay {

// Occlusion maps as changes, in Int32 columns (positions in cm): per agent a and step k (at
// a * S + k) how many entries are set (map_set_count) and how many keys removed
// (map_removed_count); per entry set, in that order, its key (map_set_key, an index into the
// keys table), centre and radius (map_set_x, _y, _r) and how many outline vertices it has
// (map_outline_count, 0 for a disc), whose offsets from the centre follow in map_outline_x, _y;
// the removed keys in map_removed_key. An entry is sent again only when one of its numbers
// moved by kMapResend or more since it was last sent (a tree estimate moves a little at every
// observation; 5 cm is below a pixel at any zoom the page starts with), so the page's map is
// within kMapResend of the record's.
void writeMaps(const RunFolder& run, Table& keys, Columns& c) {
  std::vector<std::int32_t> set_count, removed_count, set_key, set_x, set_y, set_r, outline_count,
      outline_x, outline_y, removed_key;
  for (std::size_t i = 0; i < run.spec.uavs.size(); ++i) {
    std::map<int, std::vector<double>> sent;  // key → the numbers last sent
    for (const RecordedStep& s : run.steps) {
      std::map<int, std::vector<double>> now;
      for (const RecordedMapEntry& e : s.agents[i].map) {
        std::vector<double>& numbers = now[keys.index(e.key)];
        numbers = {e.crown[0], e.crown[1], e.crown[2]};
        for (const Vec2& v : e.outline) numbers.insert(numbers.end(), {v.x(), v.y()});
      }
      std::int32_t set = 0, removed = 0;
      for (auto& [key, numbers] : now) {
        const auto it = sent.find(key);
        bool moved = it == sent.end() || it->second.size() != numbers.size();
        for (std::size_t n = 0; !moved && n < numbers.size(); ++n)
          moved = std::abs(numbers[n] - it->second[n]) >= kMapResend;
        if (!moved) {
          numbers = it->second;  // what the page holds
          continue;
        }
        ++set;
        set_key.push_back(key);
        set_x.push_back(fixedPoint(numbers[0], 100.0));
        set_y.push_back(fixedPoint(numbers[1], 100.0));
        set_r.push_back(fixedPoint(numbers[2], 100.0));
        outline_count.push_back(static_cast<std::int32_t>((numbers.size() - 3) / 2));
        for (std::size_t n = 3; n + 1 < numbers.size(); n += 2) {
          outline_x.push_back(fixedPoint(numbers[n], 100.0));
          outline_y.push_back(fixedPoint(numbers[n + 1], 100.0));
        }
      }
      for (const auto& [key, numbers] : sent) {
        if (now.count(key)) continue;
        ++removed;
        removed_key.push_back(key);
      }
      set_count.push_back(set);
      removed_count.push_back(removed);
      sent = std::move(now);
    }
  }
  c.int32("map_set_count", set_count);
  c.int32("map_removed_count", removed_count);
  c.int32("map_set_key", set_key);
  c.int32("map_set_x", set_x);
  c.int32("map_set_y", set_y);
  c.int32("map_set_r", set_r);
  c.int32("map_outline_count", outline_count);
  c.int32("map_outline_x", outline_x);
  c.int32("map_outline_y", outline_y);
  c.int32("map_removed_key", removed_key);
}

// Planned paths and planning epochs, in columns (positions in cm, velocities in cm/s, costs to
// kSignificantDigits as Float32):
// - per agent i and step k (at i * S + k) plan_path_count, the number of points of its planned
//   path, or -1 when it is the same as the step before; the points in plan_path_x, _y;
// - per planning epoch (in step order) epoch_k, epoch_epoch, epoch_part_count and
//   epoch_message_count;
// - per part (each agent's plan at an epoch, in order) part_agent, part_cost, part_action_count
//   (its velocities in part_vx, _vy) and part_joint_count (the epochs of the teammates' plans it
//   planned against in part_joint);
// - per message sent (in the order sent) message_agent (whose actions), message_from,
//   message_epoch and message_action_count (its velocities in message_vx, _vy).
void writePlans(const RunFolder& run, Columns& c) {
  const auto fixed = [](std::vector<std::int32_t>& x, std::vector<std::int32_t>& y,
                        const std::vector<Vec2>& points) {
    for (const Vec2& p : points) {
      x.push_back(fixedPoint(p.x(), 100.0));
      y.push_back(fixedPoint(p.y(), 100.0));
    }
  };
  const auto count = [](std::size_t n) { return static_cast<std::int32_t>(n); };
  std::vector<std::int32_t> path_count, path_x, path_y;
  for (std::size_t i = 0; i < run.spec.uavs.size(); ++i) {
    const std::vector<Vec2>* before = nullptr;
    for (const RecordedStep& s : run.steps) {
      const std::vector<Vec2>& path = s.agents[i].planned_path;
      if (before && *before == path) {
        path_count.push_back(-1);
      } else {
        path_count.push_back(count(path.size()));
        fixed(path_x, path_y, path);
      }
      before = &path;
    }
  }
  c.int32("plan_path_count", path_count);
  c.int32("plan_path_x", path_x);
  c.int32("plan_path_y", path_y);

  std::vector<std::int32_t> epoch_k, epoch_epoch, part_count, message_count, part_agent,
      part_actions, part_vx, part_vy, part_joints, part_joint, message_agent, message_from,
      message_epoch, message_actions, message_vx, message_vy;
  std::vector<float> part_cost;
  for (const RecordedStep& s : run.steps) {
    if (!s.plan) continue;
    epoch_k.push_back(s.k);
    epoch_epoch.push_back(s.plan->epoch);
    part_count.push_back(count(s.plan->agents.size()));
    message_count.push_back(count(s.plan->messages.size()));
    for (const RecordedPlan::Part& part : s.plan->agents) {
      part_agent.push_back(part.agent);
      part_cost.push_back(significantFloat(part.cost));
      part_actions.push_back(count(part.velocities.size()));
      fixed(part_vx, part_vy, part.velocities);
      part_joints.push_back(count(part.joint_epoch.size()));
      part_joint.insert(part_joint.end(), part.joint_epoch.begin(), part.joint_epoch.end());
    }
    for (const RecordedPlan::Message& m : s.plan->messages) {
      message_agent.push_back(m.agent);
      message_from.push_back(m.from);
      message_epoch.push_back(m.epoch);
      message_actions.push_back(count(m.velocities.size()));
      fixed(message_vx, message_vy, m.velocities);
    }
  }
  c.int32("epoch_k", epoch_k);
  c.int32("epoch_epoch", epoch_epoch);
  c.int32("epoch_part_count", part_count);
  c.int32("epoch_message_count", message_count);
  c.int32("part_agent", part_agent);
  c.float32("part_cost", part_cost);
  c.int32("part_action_count", part_actions);
  c.int32("part_vx", part_vx);
  c.int32("part_vy", part_vy);
  c.int32("part_joint_count", part_joints);
  c.int32("part_joint", part_joint);
  c.int32("message_agent", message_agent);
  c.int32("message_from", message_from);
  c.int32("message_epoch", message_epoch);
  c.int32("message_action_count", message_actions);
  c.int32("message_vx", message_vx);
  c.int32("message_vy", message_vy);
}

}  // namespace canopy::replay
