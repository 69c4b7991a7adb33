#include "spec/json_lines.h"

#include <cctype>
#include <cstddef>
#include <vector>

namespace canopy::spec {
namespace {

// A recursive-descent walk of the text that only tracks positions: values are skipped, never
// built. Depth is bounded like the parse (deeper text is refused there before this runs).
class LineScanner {
 public:
  explicit LineScanner(const std::string& text, const std::set<std::string>* wanted = nullptr)
      : text_(text), wanted_(wanted) {
    // Every path that holds a wanted one ("uavs", "uavs[3]" for "uavs[3].v_max"): the scan
    // descends into these only.
    if (wanted_) {
      for (const std::string& w : *wanted_) {
        for (std::size_t i = 1; i < w.size(); ++i)
          if (w[i] == '.' || w[i] == '[') holders_.insert(w.substr(0, i));
        holders_.insert(w);
      }
    }
  }

  std::map<std::string, int> scan() {
    skipBlank();
    value("", 0);
    return lines_;
  }

 private:
  static constexpr int kMaxDepth = 1000;

  bool atEnd() const { return at_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[at_]; }
  void advance() {
    if (text_[at_] == '\n') ++line_;
    ++at_;
  }

  void skipBlank() {
    while (!atEnd()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        advance();
      } else if (c == '/' && at_ + 1 < text_.size() && text_[at_ + 1] == '/') {
        while (!atEnd() && peek() != '\n') advance();
      } else if (c == '/' && at_ + 1 < text_.size() && text_[at_ + 1] == '*') {
        advance();
        advance();
        while (!atEnd() && !(peek() == '*' && at_ + 1 < text_.size() && text_[at_ + 1] == '/'))
          advance();
        if (!atEnd()) {
          advance();
          advance();
        }
      } else {
        return;
      }
    }
  }

  // A string's content (without the quotes), at a '"'.
  std::string string() {
    std::string out;
    advance();  // "
    while (!atEnd() && peek() != '"') {
      if (peek() == '\\') {
        advance();
        if (atEnd()) break;
      }
      out += peek();
      advance();
    }
    if (!atEnd()) advance();  // "
    return out;
  }

  // Whether `path` or a path inside it is wanted (always, without a wanted set).
  bool wantedUnder(const std::string& path) const {
    return !wanted_ || path.empty() || holders_.count(path) > 0;
  }
  void record(const std::string& path, int line) {
    if (!wanted_ || wanted_->count(path)) lines_.emplace(path, line);
  }

  // Steps over one value, building nothing (strings, brackets and comments respected).
  void skipValue() {
    int open = 0;
    while (!atEnd()) {
      const char c = peek();
      if (c == '"') {
        advance();
        while (!atEnd() && peek() != '"') {
          if (peek() == '\\') advance();
          if (!atEnd()) advance();
        }
        if (!atEnd()) advance();
        if (open == 0) return;
      } else if (c == '{' || c == '[') {
        ++open;
        advance();
      } else if (c == '}' || c == ']') {
        if (open == 0) return;  // the enclosing container's end
        advance();
        if (--open == 0) return;
      } else if (c == '/') {
        const std::size_t before = at_;
        skipBlank();
        if (at_ == before) advance();  // a lone '/': not JSON, the parse says where
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',') {
        if (open == 0) return;
        advance();
      } else {
        advance();  // a number's or a literal's characters
      }
    }
  }

  void value(const std::string& path, int depth) {
    if (atEnd() || depth > kMaxDepth) return;
    if (!wantedUnder(path)) {
      skipValue();
      return;
    }
    if (!path.empty()) record(path, line_);
    const char c = peek();
    if (c == '{') {
      advance();
      skipBlank();
      while (!atEnd() && peek() != '}') {
        if (peek() != '"') return;  // not JSON: the parse says where
        const int key_line = line_;
        const std::string key = string();
        const std::string child = path.empty() ? key : path + "." + key;
        record(child, key_line);
        skipBlank();
        if (peek() != ':') return;
        advance();
        skipBlank();
        value(child, depth + 1);
        skipBlank();
        if (peek() == ',') {
          advance();
          skipBlank();
        }
      }
      if (!atEnd()) advance();
    } else if (c == '[') {
      advance();
      skipBlank();
      for (std::size_t i = 0; !atEnd() && peek() != ']'; ++i) {
        value(path + "[" + std::to_string(i) + "]", depth + 1);
        skipBlank();
        if (peek() == ',') {
          advance();
          skipBlank();
        } else if (peek() != ']') {
          return;
        }
      }
      if (!atEnd()) advance();
    } else if (c == '"') {
      string();
    } else {
      // A number or a literal: up to the next delimiter.
      const std::size_t start = at_;
      while (!atEnd() && std::string(",]} \t\r\n/").find(peek()) == std::string::npos) advance();
      if (at_ == start) advance();  // a stray character: step over it
    }
  }

  const std::string& text_;
  const std::set<std::string>* wanted_;
  std::set<std::string> holders_;
  std::size_t at_ = 0;
  int line_ = 1;
  std::map<std::string, int> lines_;
};

}  // namespace

std::map<std::string, int> jsonValueLines(const std::string& text) {
  return LineScanner(text).scan();
}

std::map<std::string, int> jsonValueLines(const std::string& text,
                                          const std::set<std::string>& wanted) {
  return LineScanner(text, &wanted).scan();
}

}  // namespace canopy::spec
