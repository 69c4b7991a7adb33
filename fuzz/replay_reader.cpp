// libFuzzer target: a run folder read back by the replay's reader (record.jsonl, and after a NUL
// summary.json; fuzz/inputs.h says what the bytes mean).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  canopy::fuzz::readReplayInput(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
