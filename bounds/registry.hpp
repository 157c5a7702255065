#pragma once
// The one table of bounds (instant and space-time). The CLI, the tests and the
// benchmarks read it; a method is named BOUND/BROADPHASE, where BOUND is an entry's
// name, with ":M" for parameterised entries (e.g. "horn:4").
#include <bounds/bound.hpp>

#include <memory>
#include <span>
#include <string_view>

namespace ccd {

struct BoundInfo {
  std::string_view name;         ///< e.g. "capsule", "horn"
  std::string_view description;  ///< one line, states its knowledge and guarantee
  Knowledge knowledge;
  bool conservative;             ///< misses nothing when its knowledge's assumptions hold
  bool parameterised;            ///< takes ":M" (M >= 1), e.g. horn:4
  int default_parameter;         ///< M when ":M" is omitted (parameterised entries)
  std::unique_ptr<Bound> (*make)(int parameter);
};

std::span<const BoundInfo> bound_registry();

/// A bound spec resolved against the registry: "horn:4" -> {&horn entry, 4}.
struct BoundSpec {
  const BoundInfo* info = nullptr;
  int parameter = 0;
  std::unique_ptr<Bound> make() const { return info->make(parameter); }
};

/// Parses "NAME" or "NAME:M"; throws std::invalid_argument naming the bad part and
/// listing the valid names.
BoundSpec parse_bound(std::string_view spec);

}  // namespace ccd
