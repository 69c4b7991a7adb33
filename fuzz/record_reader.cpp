// libFuzzer target: a record.jsonl read back by the truth reader against the demo's scenario
// (fuzz/inputs.h says what the bytes mean).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  canopy::fuzz::readRecordInput(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
