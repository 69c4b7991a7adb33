#pragma once
// record.jsonl.zst: the record's steps in blocks of whole steps, each block one zstd frame, then a
// step index in a zstd skippable frame at the end; canopy's readers use the index to decode only
// the blocks of the steps they ask for. What a block holds is told by the index's version:
//   1: the steps' JSON lines, byte for byte (`zstd -dc` prints them; compactRecordOf writes it);
//   2: the steps as binary columns, each coded against the step before (step_columns.h), what
//      `canopy run` writes: decode() prints them as the same JSON lines `--record jsonl` writes.
//
// The index frame (all integers little-endian):
//   u32 magic 0x184D2A5C (zstd skippable), u32 content size = 24·N + 12,
//   N entries { u64 offset of the frame, u32 compressed bytes, u32 decoded bytes,
//               u32 first line (0-based), u32 lines },
//   u32 N, u32 'CNRI' (0x49524E43), u32 version (1 or 2). A version-2 entry's decoded bytes are
//   the block's binary size and its lines the block's steps.
// Frames are contiguous from offset 0; entry i + 1 starts where entry i ends; the index frame
// starts where the last ends and is the end of the file.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sim/step_record.h"

namespace canopy::sim {

class StepColumnEncoder;

/// One block of the compact record, as its index states it.
struct RecordBlock {
  std::uint64_t offset = 0;
  std::uint32_t compressed = 0;
  std::uint32_t decoded = 0;
  std::uint32_t first_line = 0;
  std::uint32_t lines = 0;
};

/// When a block is closed: once it holds `bytes` of text or `lines` lines, whichever comes first.
struct BlockSize {
  std::size_t bytes = std::size_t{32} << 20;
  std::uint32_t lines = 256;
};

/// zstd's settings for the record (bench/RESULTS.md, "Records at city scale", measured on
/// city_swarm's lines): a window of 2^25 bytes (a whole block) with long distance matching, so a
/// map entry or track that did not change since the step before, about 0.8 MB earlier at city
/// scale, is stored as a reference to it; with that, level 1 writes a smaller file than level 3
/// (48.3 against 50.9 MB) in about half the time.
inline constexpr int kRecordZstdLevel = 1;
inline constexpr int kRecordWindowLog = 25;

/// Writes the compact form through `sink` (e.g. an AtomicFile's write, committed after finish()).
class CompactRecordWriter {
 public:
  using Sink = std::function<void(std::string_view)>;
  /// Version 1: lines, through append().
  explicit CompactRecordWriter(Sink sink, BlockSize block = {});
  /// Version 2: steps, through append(StepRecord); `labels`: the scenario's, by LabelId. A block
  /// closes at `block.bytes` of columns.
  CompactRecordWriter(Sink sink, BlockSize block, std::vector<std::string> labels);
  ~CompactRecordWriter();
  CompactRecordWriter(const CompactRecordWriter&) = delete;
  CompactRecordWriter& operator=(const CompactRecordWriter&) = delete;
  /// One step's line, with its '\n'.
  void append(std::string_view line);
  /// One step (version 2).
  void append(const StepRecord& step);
  /// Compresses the open block and writes the index. Call once, after the last line.
  void finish();

 private:
  void closeBlock();

  Sink sink_;
  BlockSize block_size_;
  struct Context;
  std::unique_ptr<Context> zstd_;
  std::unique_ptr<StepColumnEncoder> steps_;  // version 2's, else none
  std::string text_;         // the open block's lines (version 2: its bytes, once closed)
  std::uint32_t lines_ = 0;  // in text_
  std::string compressed_;   // reused
  std::vector<RecordBlock> index_;
  std::uint64_t offset_ = 0;
  std::uint32_t next_line_ = 0;
};

/// The compact record at `path`, opened and its index checked: a regular file (never through a
/// link, never waiting on a FIFO). Every error is a ScenarioError naming the file and what is
/// wrong (the frame, the index field).
class CompactRecordReader {
 public:
  explicit CompactRecordReader(const std::filesystem::path& path);
  ~CompactRecordReader();
  CompactRecordReader(const CompactRecordReader&) = delete;
  CompactRecordReader& operator=(const CompactRecordReader&) = delete;

  const std::vector<RecordBlock>& blocks() const { return blocks_; }
  std::uint64_t lines() const;
  std::uint32_t version() const { return version_; }
  /// The text of block `i` (its whole lines, each ending in '\n'), checked against the index.
  std::string decode(std::size_t i) const;
  /// Version 2: line_fn(line) (without '\n') for each step of block i from its step `from`
  /// (0-based in the block) on, until it returns false; each step is formatted only when asked
  /// for and the block is never held as text.
  void eachStepLine(std::size_t i, std::uint32_t from,
                    const std::function<bool(const std::string&)>& line_fn) const;

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& expected) const;
  std::string readAt(std::uint64_t offset, std::size_t bytes) const;
  std::string inflate(std::size_t i) const;  // block i's bytes, checked against the index

  // Closed by its own destructor, so also when the constructor throws (a member is destroyed
  // then, the reader is not).
  struct Descriptor {
    int fd = -1;
    Descriptor() = default;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor();
  };

  std::filesystem::path path_;
  Descriptor file_;
  std::uint64_t size_ = 0;
  std::uint32_t version_ = 1;
  std::vector<RecordBlock> blocks_;
};

/// The whole compact text of `jsonl` (lines, each ending in '\n'), as the writer makes it: for
/// tests and the fuzz target.
std::string compactRecordOf(std::string_view jsonl, BlockSize block = {});

}  // namespace canopy::sim
