#include "replay/replay_changes.h"

#include <cmath>
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

// Occlusion maps as changes: per agent and step, 0 when nothing changed, else [[entries set],
// [keys removed]], an entry being [key, cx, cy, r] or [key, cx, cy, r, [dx, dy, …]]. An entry is
// sent again only when one of its numbers moved by kMapResend or more since it was last sent
// (a tree estimate moves a little at every observation; 5 cm is below a pixel at any zoom the
// page starts with), so the page's map is within kMapResend of the record's.
void writeMaps(const RunFolder& run, Table& keys, Writer& w) {
  w.raw(",\"maps\":[");
  bool first_agent = true;
  for (std::size_t i = 0; i < run.spec.uavs.size(); ++i) {
    w.comma(first_agent);
    w.raw("[");
    std::map<int, std::vector<double>> sent;  // key → the numbers last sent
    bool first_step = true;
    for (const RecordedStep& s : run.steps) {
      std::map<int, std::vector<double>> now;
      for (const RecordedMapEntry& e : s.agents[i].map) {
        std::vector<double>& numbers = now[keys.index(e.key)];
        numbers = {e.crown[0], e.crown[1], e.crown[2]};
        for (const Vec2& v : e.outline) numbers.insert(numbers.end(), {v.x(), v.y()});
      }
      Writer set, removed;
      bool first_set = true, first_removed = true;
      for (auto& [key, numbers] : now) {
        const auto it = sent.find(key);
        bool moved = it == sent.end() || it->second.size() != numbers.size();
        for (std::size_t n = 0; !moved && n < numbers.size(); ++n)
          moved = std::abs(numbers[n] - it->second[n]) >= kMapResend;
        if (!moved) {
          numbers = it->second;  // what the page holds
          continue;
        }
        set.comma(first_set);
        set.raw("[");
        set.integer(key);
        for (std::size_t n = 0; n < 3; ++n) {
          set.raw(",");
          set.position(numbers[n]);
        }
        if (numbers.size() > 3) {
          set.raw(",[");
          for (std::size_t n = 3; n < numbers.size(); ++n) {
            if (n > 3) set.raw(",");
            set.position(numbers[n]);
          }
          set.raw("]");
        }
        set.raw("]");
      }
      for (const auto& [key, numbers] : sent) {
        if (now.count(key)) continue;
        removed.comma(first_removed);
        removed.integer(key);
      }
      w.comma(first_step);
      if (set.text.empty() && removed.text.empty()) {
        w.raw("0");
      } else {
        w.raw("[[");
        w.text += set.text;
        w.raw("],[");
        w.text += removed.text;
        w.raw("]]");
      }
      sent = std::move(now);
    }
    w.raw("]");
  }
  w.raw("]");
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
