#pragma once
// The one status vocabulary of contact queries (Box2D's b2TOIOutput states): what a query
// found, so that callers switch on one enum whatever the query.
#include <cstdint>
#include <string_view>

namespace ccd {

enum class QueryStatus : std::uint8_t {
  Hit,          ///< first contact at toi inside the query's range (touching included)
  Overlapping,  ///< already in contact at the start of the range (toi = start)
  Miss,         ///< no contact in the range (toi = +infinity)
  Degenerate,   ///< input outside the query's domain (zero direction, NaN, ...): no answer
  Failed,       ///< an iterative solver did not reach its accuracy: no answer
};

/// "hit", "overlapping", "miss", "degenerate", "failed".
constexpr std::string_view to_string(QueryStatus s) {
  switch (s) {
    case QueryStatus::Hit: return "hit";
    case QueryStatus::Overlapping: return "overlapping";
    case QueryStatus::Miss: return "miss";
    case QueryStatus::Degenerate: return "degenerate";
    case QueryStatus::Failed: return "failed";
  }
  return "unknown";
}

}  // namespace ccd
