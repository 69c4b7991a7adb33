#include "replay/replay_changes.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "replay/replay_data.h"

namespace canopy::replay {
namespace {

void writePoints(const std::vector<Vec2>& points, Writer& w) {
  w.raw("[");
  bool first = true;
  for (const Vec2& p : points) {
    w.comma(first);
    w.position(p.x());
    w.raw(",");
    w.position(p.y());
  }
  w.raw("]");
}

}  // namespace

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

// Planned paths per agent and step (0: the same as the step before), then the planning epochs.
void writePlans(const RunFolder& run, Writer& w) {
  w.raw(",\"paths\":[");
  bool first_agent = true;
  for (std::size_t i = 0; i < run.spec.uavs.size(); ++i) {
    w.comma(first_agent);
    w.raw("[");
    bool first_step = true;
    const std::vector<Vec2>* before = nullptr;
    for (const RecordedStep& s : run.steps) {
      const std::vector<Vec2>& path = s.agents[i].planned_path;
      w.comma(first_step);
      if (before && *before == path) {
        w.raw("0");
      } else {
        writePoints(path, w);
      }
      before = &path;
    }
    w.raw("]");
  }
  w.raw("],\"epochs\":[");
  bool first = true;
  for (const RecordedStep& s : run.steps) {
    if (!s.plan) continue;
    w.comma(first);
    w.raw("{\"k\":");
    w.integer(s.k);
    w.raw(",\"epoch\":");
    w.integer(s.plan->epoch);
    w.raw(",\"agents\":[");
    bool first_part = true;
    for (const RecordedPlan::Part& part : s.plan->agents) {
      w.comma(first_part);
      w.raw("[");
      w.integer(part.agent);
      w.raw(",");
      w.significant(part.cost);
      w.raw(",");
      writePoints(part.velocities, w);
      w.raw(",[");
      bool first_epoch = true;
      for (int e : part.joint_epoch) {
        w.comma(first_epoch);
        w.integer(e);
      }
      w.raw("]]");
    }
    w.raw("],\"messages\":[");
    bool first_message = true;
    for (const RecordedPlan::Message& m : s.plan->messages) {
      w.comma(first_message);
      w.raw("[");
      w.integer(m.agent);
      w.raw(",");
      w.integer(m.from);
      w.raw(",");
      w.integer(m.epoch);
      w.raw(",");
      writePoints(m.velocities, w);
      w.raw("]");
    }
    w.raw("]}");
  }
  w.raw("]");
}

}  // namespace canopy::replay
