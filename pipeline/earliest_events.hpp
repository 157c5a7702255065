#pragma once
// The earliest scheduler's events (pipeline/earliest_scheduler.hpp), internal to it: the
// queue of body expiries and queued pair checks in time order, the checks run at once in
// rounds, and the narrow calls they give.
#include <bounds/bound.hpp>

#include <chrono>
#include <cstdint>
#include <queue>
#include <vector>

namespace ccd::earliest {

enum class Kind : std::uint8_t { Check = 0, Expiry = 1 };

// A static check (body a against a polygon of the scenery) carries the polygon in b with
// this bit set, so checks and jobs keep their size; bodies, slots and polygons stay below
// it (run() and set_scenery() refuse more).
constexpr std::uint32_t kStaticBit = 0x80000000u;
constexpr bool is_static(std::uint32_t b) { return (b & kStaticBit) != 0; }
constexpr std::uint32_t static_b(std::uint32_t polygon) { return polygon | kStaticBit; }
constexpr std::uint32_t polygon_of(std::uint32_t b) { return b & ~kStaticBit; }

struct Event {
  double t;
  Kind kind;
  std::uint32_t a, b;    // a pair (a < b; in a wrapped scene two slots, a's owner < b's), or the
                         // expiring body in a (b == a), or a static check's body and static_b(polygon)
  std::uint64_t va, vb;  // the bodies' version stamps when the event was queued
  double since;          // a check: when the bounds it came from start
};

// Min-heap order: earlier first; at equal times checks before expiries, then by bodies
// (a deterministic order, whatever the insertion order).
struct Later {
  bool operator()(const Event& x, const Event& y) const {
    if (x.t != y.t) return x.t > y.t;
    if (x.kind != y.kind) return x.kind > y.kind;
    if (x.a != y.a) return x.a > y.a;
    return x.b > y.b;
  }
};

using EventQueue = std::priority_queue<Event, std::vector<Event>, Later>;

// A pair check run as soon as it is made (inline checks, EarliestRun::inline_checks_).
struct Check {
  double t;
  std::uint32_t a, b;  // as in Event
  double since;        // when the bounds it came from start
  double to;           // the end of the common window
};

// A narrow call over [from, until] in the pair's common window ending at `to`.
struct Job {
  std::uint32_t a, b;
  double from, until, to;
};

// Adds the time since `from` to `into` when timing is on.
struct Watch {
  bool on;
  std::chrono::steady_clock::time_point from{};
  void start() {
    if (on) from = std::chrono::steady_clock::now();
  }
  void stop(double& into) const {
    if (on) into += std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
  }
};

}  // namespace ccd::earliest
