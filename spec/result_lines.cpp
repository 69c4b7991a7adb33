#include "spec/result_lines.h"

#include <cstdlib>
#include <new>

namespace canopy::spec {
namespace {

// Counts the values of a text as the parser reads them; builds nothing (the lexer's token buffer,
// at most one token long, is the only allocation). Stops as deep as the real parse does.
class CountingSax {
 public:
  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(Json::number_integer_t) { return value(); }
  bool number_unsigned(Json::number_unsigned_t) { return value(); }
  bool number_float(Json::number_float_t, const Json::string_t&) { return value(); }
  bool string(Json::string_t& s) {
    bytes_ += s.size();
    return value();
  }
  bool binary(Json::binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(); }
  bool key(Json::string_t& k) {
    bytes_ += k.size();
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(); }
  bool end_array() { return close(); }
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception&) {
    return false;
  }

  std::size_t values() const { return values_; }
  std::size_t bytes() const { return bytes_; }

 private:
  bool value() {
    ++values_;
    return true;
  }
  bool open() {
    ++values_;
    return ++depth_ <= kMaxJsonDepth + 1;  // as parseBoundedJson: the 66th is refused
  }
  bool close() {
    --depth_;
    return true;
  }
  std::size_t values_ = 0, bytes_ = 0;
  int depth_ = 0;
};

// Whether `bytes` can be allocated now (under a limit on the address space, `ulimit -v`, a block
// past it is refused at once). The block is released again: it is a probe, not a reservation.
bool canAllocate(std::size_t bytes) {
  void* block = std::malloc(bytes);
  if (block == nullptr) return false;
  std::free(block);
  return true;
}

}  // namespace

std::optional<Json> parseResultLine(const std::string& line) {
  if (line.size() >= kCountedLineBytes) {
    CountingSax counter;
    if (!Json::sax_parse(line, &counter, Json::input_format_t::json, /*strict=*/true,
                         /*ignore_comments=*/true))
      return std::nullopt;
    const double need = static_cast<double>(counter.values()) * kJsonBytesPerValue +
                        static_cast<double>(counter.bytes()) + static_cast<double>(line.size());
    if (need > static_cast<double>(SIZE_MAX / 2) || !canAllocate(static_cast<std::size_t>(need)))
      throw std::bad_alloc();
  }
  try {
    return parseBoundedJson(line);
  } catch (const Json::exception&) {
    return std::nullopt;
  } catch (const JsonTooDeep&) {
    return std::nullopt;
  } catch (const JsonDuplicateKey&) {
    return std::nullopt;
  }
}

std::optional<std::int64_t> integerWithin(const Json& value, std::int64_t lo, std::int64_t hi) {
  if (value.is_number_unsigned()) {
    const std::uint64_t x = value.get<std::uint64_t>();
    if (hi < 0 || x > static_cast<std::uint64_t>(hi)) return std::nullopt;
    return static_cast<std::int64_t>(x);
  }
  if (!value.is_number_integer()) return std::nullopt;
  const std::int64_t x = value.get<std::int64_t>();
  if (x < lo || x > hi) return std::nullopt;
  return x;
}

}  // namespace canopy::spec
