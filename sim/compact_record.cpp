#include "sim/compact_record.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zstd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "core/printable.h"
#include "sim/record_line.h"
#include "sim/step_columns.h"
#include "spec/error.h"
#include "spec/result_lines.h"

namespace canopy::sim {
namespace {

constexpr std::uint32_t kSkippableMagic = 0x184D2A5C;
constexpr std::uint32_t kIndexMagic = 0x49524E43;  // "CNRI"
constexpr std::uint32_t kLinesVersion = 1;
constexpr std::uint32_t kStepsVersion = 2;
constexpr std::size_t kEntryBytes = 24;
constexpr std::size_t kTrailerBytes = 12;
constexpr std::size_t kHeaderBytes = 8;
// A block holds whole lines: at most one line (kMaxResultLineBytes) past the block size the
// writer closes at; the reader allocates no more than this for one block.
constexpr std::uint64_t kMaxBlockBytes = std::uint64_t{512} << 20;

void put32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFFu);
}
void put64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFFu);
}
std::uint64_t get(const std::string& in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(in[at + static_cast<std::size_t>(i)]);
  return v;
}
std::uint32_t get32(const std::string& in, std::size_t at) {
  return static_cast<std::uint32_t>(get(in, at, 4));
}

}  // namespace

struct CompactRecordWriter::Context {
  ZSTD_CCtx* cctx = ZSTD_createCCtx();
  ~Context() { ZSTD_freeCCtx(cctx); }
};

CompactRecordWriter::CompactRecordWriter(Sink sink, BlockSize block)
    : sink_(std::move(sink)), block_size_(block), zstd_(std::make_unique<Context>()) {
  if (zstd_->cctx == nullptr) throw std::bad_alloc();
  ZSTD_CCtx_setParameter(zstd_->cctx, ZSTD_c_compressionLevel, kRecordZstdLevel);
  ZSTD_CCtx_setParameter(zstd_->cctx, ZSTD_c_checksumFlag, 1);
  ZSTD_CCtx_setParameter(zstd_->cctx, ZSTD_c_windowLog, kRecordWindowLog);
  ZSTD_CCtx_setParameter(zstd_->cctx, ZSTD_c_enableLongDistanceMatching, 1);
}

CompactRecordWriter::CompactRecordWriter(Sink sink, BlockSize block,
                                         std::vector<std::string> labels)
    : CompactRecordWriter(std::move(sink), block) {
  steps_ = std::make_unique<StepColumnEncoder>(std::move(labels));
}

CompactRecordWriter::~CompactRecordWriter() = default;

void CompactRecordWriter::append(std::string_view line) {
  if (steps_) throw std::logic_error("a compact record of steps takes steps, not lines");
  text_.append(line);
  ++lines_;
  if (text_.size() >= block_size_.bytes || lines_ >= block_size_.lines) closeBlock();
}

void CompactRecordWriter::append(const StepRecord& step) {
  if (!steps_) throw std::logic_error("a compact record of lines takes lines, not steps");
  steps_->add(step);
  ++lines_;
  if (steps_->bytes() >= block_size_.bytes || lines_ >= block_size_.lines) closeBlock();
}

void CompactRecordWriter::closeBlock() {
  if (lines_ == 0) return;
  if (steps_) steps_->take(text_);
  if (text_.size() > kMaxBlockBytes) throw std::length_error("a record block over 512 MiB");
  compressed_.resize(ZSTD_compressBound(text_.size()));
  const std::size_t n = ZSTD_compress2(zstd_->cctx, compressed_.data(), compressed_.size(),
                                       text_.data(), text_.size());
  if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
  sink_(std::string_view(compressed_.data(), n));
  index_.push_back({offset_, static_cast<std::uint32_t>(n),
                    static_cast<std::uint32_t>(text_.size()), next_line_, lines_});
  offset_ += n;
  next_line_ += lines_;
  text_.clear();
  lines_ = 0;
}

void CompactRecordWriter::finish() {
  closeBlock();
  std::string footer;
  put32(footer, kSkippableMagic);
  put32(footer, static_cast<std::uint32_t>(kEntryBytes * index_.size() + kTrailerBytes));
  for (const RecordBlock& b : index_) {
    put64(footer, b.offset);
    put32(footer, b.compressed);
    put32(footer, b.decoded);
    put32(footer, b.first_line);
    put32(footer, b.lines);
  }
  put32(footer, static_cast<std::uint32_t>(index_.size()));
  put32(footer, kIndexMagic);
  put32(footer, steps_ ? kStepsVersion : kLinesVersion);
  sink_(footer);
}

std::string compactRecordOf(std::string_view jsonl, BlockSize block) {
  std::string out;
  CompactRecordWriter writer([&](std::string_view bytes) { out.append(bytes); }, block);
  std::size_t next = 0;
  while (next < jsonl.size()) {
    const std::size_t end = std::min(jsonl.find('\n', next), jsonl.size() - 1);
    writer.append(jsonl.substr(next, end + 1 - next));
    next = end + 1;
  }
  writer.finish();
  return out;
}

CompactRecordReader::CompactRecordReader(const std::filesystem::path& path) : path_(path) {
  file_.fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (file_.fd < 0) {
    const int error = errno;
    fail("", error == ELOOP    ? "a regular file, not a symbolic link"
             : error == ENOENT ? "the compact record of `canopy run` (missing)"
                               : std::string("a readable file (") + std::strerror(error) + ")");
  }
  struct stat st {};
  if (::fstat(file_.fd, &st) != 0 || !S_ISREG(st.st_mode))
    fail("", "a regular file (not a FIFO, device or directory)");
  size_ = static_cast<std::uint64_t>(st.st_size);
  if (size_ < kHeaderBytes + kTrailerBytes) fail("", "a step index at its end (too short)");
  const std::string trailer = readAt(size_ - kTrailerBytes, kTrailerBytes);
  version_ = get32(trailer, 8);
  if (get32(trailer, 4) != kIndexMagic || (version_ != kLinesVersion && version_ != kStepsVersion))
    fail("index", "canopy's step index (version 1 or 2) as its last 12 bytes");
  const std::uint64_t count = get32(trailer, 0);
  const std::uint64_t index_bytes = kHeaderBytes + kEntryBytes * count + kTrailerBytes;
  if (index_bytes > size_) fail("index", "at most as many entries as the file has room for");
  const std::uint64_t frames_end = size_ - index_bytes;
  const std::string index = readAt(frames_end, static_cast<std::size_t>(index_bytes));
  if (get32(index, 0) != kSkippableMagic || get32(index, 4) != index_bytes - kHeaderBytes)
    fail("index", "a zstd skippable frame holding the index");
  std::uint64_t offset = 0, line = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = kHeaderBytes + kEntryBytes * i;
    const RecordBlock b{get(index, at, 8), get32(index, at + 8), get32(index, at + 12),
                        get32(index, at + 16), get32(index, at + 20)};
    const std::string where = "index entry " + std::to_string(i);
    if (b.offset != offset) fail(where, "offset " + std::to_string(offset) + " (frames in order)");
    if (b.first_line != line) fail(where, "first line " + std::to_string(line));
    if (b.lines == 0 || b.decoded < b.lines || b.decoded > kMaxBlockBytes)
      fail(where, "at least one line and at most 512 MiB decoded");
    offset += b.compressed;
    line += b.lines;
    if (offset > frames_end) fail(where, "a frame that ends before the index");
    blocks_.push_back(b);
  }
  if (offset != frames_end) fail("index", "frames that fill the file up to the index");
}

CompactRecordReader::~CompactRecordReader() = default;

CompactRecordReader::Descriptor::~Descriptor() {
  if (fd >= 0) ::close(fd);
}

std::uint64_t CompactRecordReader::lines() const {
  return blocks_.empty() ? 0 : blocks_.back().first_line + std::uint64_t{blocks_.back().lines};
}

void CompactRecordReader::fail(const std::string& where, const std::string& expected) const {
  throw spec::ScenarioError(printable(path_.string(), 200), where, "expected " + expected);
}

std::string CompactRecordReader::readAt(std::uint64_t offset, std::size_t bytes) const {
  std::string out(bytes, '\0');
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t n =
        ::pread(file_.fd, out.data() + done, bytes - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      fail("", "bytes up to " + std::to_string(offset + bytes) + " (the file is shorter)");
    done += static_cast<std::size_t>(n);
  }
  return out;
}

std::string CompactRecordReader::inflate(std::size_t i) const {
  const RecordBlock& b = blocks_.at(i);
  const std::string where = "frame " + std::to_string(i);
  const std::string frame = readAt(b.offset, b.compressed);
  const unsigned long long size = ZSTD_getFrameContentSize(frame.data(), frame.size());
  if (size != b.decoded) fail(where, "a zstd frame of " + std::to_string(b.decoded) + " bytes");
  if (ZSTD_findFrameCompressedSize(frame.data(), frame.size()) != frame.size())
    fail(where, "one zstd frame of " + std::to_string(b.compressed) + " bytes");
  std::string bytes(b.decoded, '\0');
  const std::size_t n = ZSTD_decompress(bytes.data(), bytes.size(), frame.data(), frame.size());
  if (ZSTD_isError(n))
    fail(where, std::string("a valid zstd frame (") + ZSTD_getErrorName(n) + ")");
  if (n != bytes.size()) fail(where, std::to_string(b.decoded) + " bytes");
  return bytes;
}

void CompactRecordReader::eachStepLine(
    std::size_t i, std::uint32_t from,
    const std::function<bool(const std::string&)>& line_fn) const {
  if (version_ != kStepsVersion) throw std::logic_error("eachStepLine: a record of lines");
  const std::string where = "frame " + std::to_string(i);
  const std::string columns = inflate(i);
  std::uint32_t steps = 0;
  std::optional<StepColumnDecoder> decoder;
  std::optional<RecordLineWriter> writer;
  StepRecord step;
  std::string line;
  // What the block's bytes make of a step: a malformed block names the frame. line_fn's own
  // exceptions pass through as they are.
  auto nextLine = [&]() {
    try {
      if (!decoder) {
        decoder.emplace(columns);
        writer.emplace(decoder->labels());
      }
      while (decoder->next(step)) {
        if (steps++ < from) continue;  // decoded (the next step is coded against it), not printed
        line.clear();
        writer->write(step, line);
        return true;
      }
      return false;
    } catch (const std::exception& e) {
      fail(where, std::string("a block of steps (") + e.what() + ")");
    }
  };
  while (nextLine()) {
    if (!line_fn(line)) return;
  }
  if (steps != blocks_[i].lines)
    fail(where, std::to_string(blocks_[i].lines) + " steps, as its index says");
}

std::string CompactRecordReader::decode(std::size_t i) const {
  const RecordBlock& b = blocks_.at(i);
  const std::string where = "frame " + std::to_string(i);
  std::string text;
  if (version_ == kStepsVersion) {
    eachStepLine(i, 0, [&text](const std::string& line) {
      text += line;
      text += '\n';
      return true;
    });
    return text;
  }
  text = inflate(i);
  if (text.empty() || text.back() != '\n') fail(where, "whole lines");
  std::size_t newlines = 0;
  for (const char c : text) newlines += c == '\n' ? 1 : 0;
  if (newlines != b.lines) fail(where, std::to_string(b.lines) + " lines, as its index says");
  return text;
}

}  // namespace canopy::sim
