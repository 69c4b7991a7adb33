#pragma once
// How each kind of value of the record is written into a JSON line and read back (the codecs of
// record_schema.h's fields): numbers, integers with the range a reader accepts, points, packed
// covariances, keys, labels, contacts, lists of objects. Each names its JSON type for the docs.
#include <climits>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "sim/record_schema.h"
#include "spec/result_lines.h"

namespace canopy::sim::codec {

using spec::Json;

/// The sizes a reader requires of a list: any, one entry per UAV or one per target.
enum class Count { any, uavs, targets };
/// The values a reader accepts of an integer: any int, a step index (≥ 0), an agent's or a
/// target's index of the scenario.
enum class Range { any, step, agent, target };

inline void checkCount(const LineIn& in, const Json& v, Count count, const At& at) {
  if (!v.is_array()) in.fail(at, "a list");
  const std::size_t n = count == Count::uavs ? in.uavs : in.targets;
  if (count != Count::any && v.size() != n)
    in.fail(at, "a list of " + std::to_string(n) + " entries (as in the manifest's scenario)");
}

// Read as 64 bits, then narrowed: 2³² + 1 is refused, not read as 1.
inline int readInt(const LineIn& in, const Json& v, Range range, const At& at) {
  const auto agents = static_cast<std::int64_t>(in.uavs);
  const auto targets = static_cast<std::int64_t>(in.targets);
  switch (range) {
    case Range::any:
      if (const auto x = spec::integerWithin(v, INT_MIN, INT_MAX)) return static_cast<int>(*x);
      in.fail(at, "an integer");
    case Range::step:
      if (const auto x = spec::integerWithin(v, 0, INT_MAX)) return static_cast<int>(*x);
      in.fail(at, "a step index from 0 to 2³¹ − 1");
    case Range::agent:
      if (const auto x = spec::integerWithin(v, 0, agents - 1)) return static_cast<int>(*x);
      in.fail(at, "an agent index below " + std::to_string(agents));
    case Range::target:
      if (const auto x = spec::integerWithin(v, 0, targets - 1)) return static_cast<int>(*x);
      in.fail(at, "target indices below " + std::to_string(targets));
  }
  in.fail(at, "an integer");
}

inline double readNumber(const LineIn& in, const Json& v, const At& at) {
  if (!v.is_number()) in.fail(at, "a number");
  return v.get<double>();
}

/// Numbers of a fixed-size list: element n of the JSON list goes to set(n, value).
template <typename Set>
void readNumbers(const LineIn& in, const Json& v, std::size_t size, const At& at, Set set) {
  if (!v.is_array() || v.size() != size)
    in.fail(at, "a list of " + std::to_string(size) + " numbers");
  for (std::size_t n = 0; n < size; ++n) {
    if (!v[n].is_number()) in.fail(at, "a list of " + std::to_string(size) + " numbers");
    set(n, v[n].get<double>());
  }
}

template <Range R = Range::any>
struct Int {
  static constexpr const char* kType = "integer";
  static void write(LineOut& out, int v) { out.j.integer(v); }
  static void read(const LineIn& in, const Json& v, int& x, const At& at) {
    x = readInt(in, v, R, at);
  }
};

struct Long {  // a count that may pass 2³¹ (cost evaluations)
  static constexpr const char* kType = "integer";
  static void write(LineOut& out, long long v) { out.j.integer(v); }
  static void read(const LineIn& in, const Json& v, long long& x, const At& at) {
    const auto y = spec::integerWithin(v, INT64_MIN, INT64_MAX);
    if (!y) in.fail(at, "an integer");
    x = static_cast<long long>(*y);
  }
};

struct Bool {
  static constexpr const char* kType = "boolean";
  static void write(LineOut& out, bool v) { out.j.boolean(v); }
  static void read(const LineIn& in, const Json& v, bool& x, const At& at) {
    if (!v.is_boolean()) in.fail(at, "true or false");
    x = v.get<bool>();
  }
};

struct Number {
  static constexpr const char* kType = "number";
  static void write(LineOut& out, double v) { out.j.number(v); }
  static void read(const LineIn& in, const Json& v, double& x, const At& at) {
    x = readNumber(in, v, at);
  }
};

struct Point {  // [x, y]
  static constexpr const char* kType = "[number, number]";
  static void write(LineOut& out, const Vec2& v) {
    out.j.beginArray();
    out.j.number(v.x());
    out.j.number(v.y());
    out.j.endArray();
  }
  static void read(const LineIn& in, const Json& v, Vec2& p, const At& at) {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      in.fail(at, "[x, y] (two numbers)");
    p = {v[0].get<double>(), v[1].get<double>()};
  }
};

/// A vector of N numbers (a Gaussian's mean).
template <int N>
struct Mean {
  static constexpr const char* kType = N == 3 ? "[number × 3]" : "[number × 4]";
  template <typename V>
  static void write(LineOut& out, const V& x) {
    out.j.beginArray();
    for (int r = 0; r < N; ++r) out.j.number(x(r));
    out.j.endArray();
  }
  template <typename V>
  static void read(const LineIn& in, const Json& v, V& x, const At& at) {
    readNumbers(in, v, N, at, [&](std::size_t n, double d) { x(static_cast<int>(n)) = d; });
  }
};

/// A symmetric N × N matrix as its upper triangle, row by row: P00, P01, …, P0n, P11, ….
template <int N>
struct Upper {
  static constexpr const char* kType = N == 2   ? "[number × 3]"
                                       : N == 3 ? "[number × 6]"
                                                : "[number × 10]";
  template <typename M>
  static void write(LineOut& out, const M& P) {
    out.j.beginArray();
    for (int r = 0; r < N; ++r) {
      for (int c = r; c < N; ++c) out.j.number(P(r, c));
    }
    out.j.endArray();
  }
  template <typename M>
  static void read(const LineIn& in, const Json& v, M& P, const At& at) {
    static const std::vector<std::pair<int, int>> kCells = [] {  // (row, column), in order
      std::vector<std::pair<int, int>> cells;
      for (int r = 0; r < N; ++r) {
        for (int c = r; c < N; ++c) cells.emplace_back(r, c);
      }
      return cells;
    }();
    readNumbers(in, v, kCells.size(), at, [&](std::size_t n, double d) {
      P(kCells[n].first, kCells[n].second) = P(kCells[n].second, kCells[n].first) = d;
    });
  }
};

struct Key {  // a track's global key [origin, serial]
  static constexpr const char* kType = "[integer, integer]";
  static void write(LineOut& out, const agents::TrackKey& k) {
    out.j.beginArray();
    out.j.integer(k.origin);
    out.j.integer(k.serial);
    out.j.endArray();
  }
  static void read(const LineIn& in, const Json& v, agents::TrackKey& k, const At& at) {
    const auto origin =
        v.is_array() && v.size() == 2 ? spec::integerWithin(v[0], INT_MIN, INT_MAX) : std::nullopt;
    const auto serial = origin ? spec::integerWithin(v[1], INT_MIN, INT_MAX) : std::nullopt;
    if (!serial) in.fail(at, "a key [origin, serial] (two integers)");
    k = {static_cast<int>(*origin), static_cast<int>(*serial)};
  }
};

struct Label {  // a label of the scenario, by name
  static constexpr const char* kType = "string";
  static void write(LineOut& out, sensing::LabelId id) { out.j.escapedString(out.label(id)); }
  static void read(const LineIn& in, const Json& v, sensing::LabelId& id, const At& at) {
    if (v.is_string()) {
      const std::string& name = v.get_ref<const std::string&>();
      for (std::size_t i = 0; i < in.labels.size(); ++i) {
        if (in.labels[i] == name) {
          id = static_cast<sensing::LabelId>(i);
          return;
        }
      }
    }
    in.fail(at, "a label of the manifest's scenario");
  }
};

template <Range R = Range::any, Count C = Count::any>
struct Ints {
  static constexpr const char* kType = "[integer]";
  static void write(LineOut& out, const std::vector<int>& list) {
    out.j.beginArray();
    for (const int i : list) out.j.integer(i);
    out.j.endArray();
  }
  static void read(const LineIn& in, const Json& v, std::vector<int>& list, const At& at) {
    checkCount(in, v, C, at);
    list.clear();
    for (const Json& x : v) list.push_back(readInt(in, x, R, at));
  }
};

struct Points {  // [[x, y], …]
  static constexpr const char* kType = "[[number, number]]";
  static void write(LineOut& out, const std::vector<Vec2>& list) {
    out.j.beginArray();
    for (const Vec2& p : list) Point::write(out, p);
    out.j.endArray();
  }
  static void read(const LineIn& in, const Json& v, std::vector<Vec2>& list, const At& at) {
    if (!v.is_array()) in.fail(at, "a list of [x, y]");
    list.resize(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      Point::read(in, v[i], list[i], At{&at, nullptr, static_cast<long>(i)});
  }
};

struct OutlinePoints {  // a polygon's vertex offsets, at most Outline::kMaxVertices
  static constexpr const char* kType = Points::kType;
  static void write(LineOut& out, const sensing::Outline& o) {
    out.j.beginArray();
    for (int k = 0; k < o.vertices; ++k) Point::write(out, o.offsets[static_cast<std::size_t>(k)]);
    out.j.endArray();
  }
  static void read(const LineIn& in, const Json& v, sensing::Outline& o, const At& at) {
    if (!v.is_array() || v.size() > sensing::Outline::kMaxVertices)
      in.fail(at,
              "a list of at most " + std::to_string(sensing::Outline::kMaxVertices) + " [x, y]");
    o.vertices = static_cast<int>(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
      Point::read(in, v[k], o.offsets[k], At{&at, nullptr, static_cast<long>(k)});
  }
};

/// What a body touched, by name: "trunk:K", "wall:K" (the occluder's index among the scenario's
/// trees), "uav:J" (the agent's index), "tree:K", "target:K".
struct Contacts {
  static constexpr const char* kType = "[string]";
  static const char* kindName(world::BodyKind kind);
  static std::string name(const world::BodyRef& c) {
    return std::string(kindName(c.kind)) + ":" + std::to_string(c.index);
  }
  static void write(LineOut& out, const std::vector<world::BodyRef>& list);
  static void read(const LineIn& in, const Json& v, std::vector<world::BodyRef>& list,
                   const At& at);
};

/// The item itself (Objects' default view).
struct Same {
  template <typename X>
  X& operator()(X& x) const {
    return x;
  }
};
/// A list of objects of type E, each read and written by the schema's table `Member`, each
/// element `View{}(item)` of the container's items (the item, or a part of each: a UAV's scan).
template <typename E, auto Member, Count C = Count::any, typename View = Same>
struct Objects {
  static constexpr const char* kType = "list";
  template <typename Container>
  static void write(LineOut& out, const Container& list) {
    out.j.beginArray();
    for (const auto& item : list) writeObject<E>(out, out.schema.*Member, View{}(item));
    out.j.endArray();
  }
  template <typename Container>
  static void read(const LineIn& in, const Json& v, Container& list, const At& at) {
    checkCount(in, v, C, at);
    if constexpr (std::is_same_v<View, Same>) {
      list.clear();
      list.resize(v.size());
    } else {  // a part of each item of a list read already (the UAVs' scans)
      if (list.size() != v.size())
        in.fail(at, "a list of " + std::to_string(list.size()) + " entries");
      for (auto& item : list) View{}(item) = E{};
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      readObject<E>(in, v[i], in.schema.*Member, View{}(list[i]),
                    At{&at, nullptr, static_cast<long>(i)});
    }
  }
  static void children(const RecordSchema& schema, const std::string& prefix,
                       std::vector<RecordField>& rows);
};

/// An object that is there at some steps (the plan).
template <typename E, auto Member>
struct Optional {
  static constexpr const char* kType = "object";
  static void write(LineOut& out, const std::optional<E>& v) {
    writeObject<E>(out, out.schema.*Member, *v);
  }
  static void read(const LineIn& in, const Json& v, std::optional<E>& x, const At& at) {
    readObject<E>(in, v, in.schema.*Member, x.emplace(), at);
  }
  static void children(const RecordSchema& schema, const std::string& prefix,
                       std::vector<RecordField>& rows);
};

}  // namespace canopy::sim::codec
