#pragma once
// The content of a compact record block (index version 2, compact_record.h): the block's steps as
// binary columns, each step coded against the step before it in the same block (the first step of
// a block is coded whole, so a block decodes on its own). What a step's JSON line holds
// (record_line.h) and nothing else; decoding rebuilds those fields of a StepRecord and the same
// line writer prints them, so the decoded lines are byte-identical to `--record jsonl`'s.
//
// The rule for what is not repeated: an occlusion-map entry or track of agent i whose key equals
// an entry of agent i's list at the step before (same block) is written as a reference to that
// entry, and nothing more when every value it records (key, label, mean, covariance's upper
// triangle, existence, outline) has the same bits; otherwise its values follow XORed with that
// entry's (equal leading bits become zero bytes). UAV and target truth is XORed with the same
// UAV's or target's at the step before. Everything else is written whole. A field of the record's
// tables (record_fields.h) with no packing of its own follows its object's values as its JSON
// text (record_extras.h), and counts in "the same bits" as that text.
//
// Block bytes: u labels, each (u length, bytes); u columns (= kColumnCount), each u size; then the
// columns. Integers and counts go to the structure column (varints), doubles to the column of
// their part, each double column stored byte-plane by byte-plane (all first bytes, then all
// second bytes, …: zstd then sees the zero and slowly changing high bytes together).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/column_bytes.h"
#include "sim/record_extras.h"
#include "sim/step_record.h"

namespace canopy::sim {

enum StepColumn : int {
  kStructureColumn,  // counts, keys, labels, indices, references
  kTruthColumn,      // t, UAVs' and targets' truth
  kMapColumn,        // occlusion-map entries
  kTrackColumn,      // fused tracks
  kScanColumn,       // observations
  kPlanColumn,       // planned paths and plans
  kColumnCount
};

class StepColumnEncoder {
 public:
  /// schema: the record's (a table's fields without a packing of their own go as
  /// record_extras.h says).
  explicit StepColumnEncoder(std::vector<std::string> labels,
                             const RecordSchema& schema = recordSchema())
      : labels_(std::move(labels)), written_(labels_.size(), false), extras_(schema, labels_) {}
  /// Appends `record` to the open block.
  void add(const StepRecord& record);
  std::uint32_t steps() const { return steps_; }
  std::size_t bytes() const;
  /// The open block's bytes in column c so far (before byte planes).
  std::size_t columnBytes(StepColumn c) const { return columns_[c].size(); }
  /// Appends the open block's bytes to `out` and opens a new, empty block.
  void take(std::string& out);

 private:
  void belief(int agent, const agents::AgentBelief& b);
  void truth(const StepRecord& record);
  void scans(const StepRecord& record);
  void plans(const StepRecord& record);
  void label(sensing::LabelId id);

  std::vector<std::string> labels_;
  std::vector<bool> written_;  // by LabelId: checked as dump() would (the first time written)
  RecordExtras extras_;
  std::array<ColumnOut, kColumnCount> columns_;
  std::uint32_t steps_ = 0;
  // The step before, in this block: its first previous_agents_ beliefs (none at a block's start;
  // the vectors keep their capacity from block to block, so that a swarm's beliefs, tens of MB,
  // are not allocated and faulted in again at every block).
  std::vector<agents::AgentBelief> previous_;
  std::size_t previous_agents_ = 0;
  std::vector<std::array<double, 8>> uavs_;
  std::vector<std::array<double, 4>> targets_;
};

/// Reads a block's steps. Every malformed byte is a std::runtime_error naming what is wrong.
class StepColumnDecoder {
 public:
  explicit StepColumnDecoder(std::string_view block, const RecordSchema& schema = recordSchema());
  const std::vector<std::string>& labels() const { return labels_; }
  /// True while a step remains: rebuilds its recorded fields into `record`.
  bool next(StepRecord& record);

 private:
  void belief(int agent, agents::AgentBelief& b);
  void truth(StepRecord& record);
  void scans(StepRecord& record);
  void plans(StepRecord& record);
  template <typename T>
  void extra(const Table<T>& table, T& t) {
    if (!table.generic().empty())
      extras_->decode(table, t, columns_[kStructureColumn], uavs_.size(), targets_.size());
  }

  const RecordSchema& schema_;
  std::vector<std::string> labels_;
  std::optional<RecordExtras> extras_;            // once the labels are read
  std::array<std::string, kColumnCount> planes_;  // double columns back in value order
  std::array<ColumnIn, kColumnCount> columns_;
  std::vector<agents::AgentBelief> previous_;
  std::vector<std::array<double, 8>> uavs_;
  std::vector<std::array<double, 4>> targets_;
};

/// Byte planes of 8-byte values and back (the tail that is not a whole value stays as it is).
void toPlanes(std::string_view values, std::string& out);
void fromPlanes(std::string_view planes, std::string& out);

}  // namespace canopy::sim
