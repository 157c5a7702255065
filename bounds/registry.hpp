#pragma once
// The one table of bounds (instant and space-time). The CLI, the tests and the
// benchmarks read it; a method is named BOUND/BROADPHASE, where BOUND is a spec:
//   NAME                    every option at its default, e.g. "capsule", "horn"
//   NAME:opt=value[,...]    e.g. "horn:pieces=8"
//   NAME:value              the entry's first option, e.g. "horn:4" = "horn:pieces=4"
// Each entry declares its options as a parameter table (ccd/util/parameters.hpp) with
// units and defaults.
#include <bounds/bound.hpp>
#include <ccd/util/parameters.hpp>

#include <memory>
#include <span>
#include <string_view>

namespace ccd {

struct BoundInfo {
  std::string_view name;         ///< e.g. "capsule", "horn"
  std::string_view description;  ///< one line, states its knowledge and guarantee
  Knowledge knowledge;
  bool conservative;             ///< misses nothing when its knowledge's assumptions hold
  std::span<const ParameterSpec> parameters;  ///< the options (may be empty)
  std::unique_ptr<Bound> (*factory)(const ParameterSet& options);

  /// An instance with the given options (checked against `parameters`).
  std::unique_ptr<Bound> make(const ParameterSet& options) const { return factory(options); }
  /// An instance with every option at its default.
  std::unique_ptr<Bound> make() const;
};

std::span<const BoundInfo> bound_registry();

/// A bound spec resolved against the registry: "horn:4" -> {&horn entry, {pieces: 4}}.
struct BoundSpec {
  const BoundInfo* info = nullptr;
  ParameterSet options;  ///< every option of the entry, defaults filled in
  std::unique_ptr<Bound> make() const { return info->make(options); }
};

/// Parses a spec (forms above); throws std::invalid_argument naming the bad part and
/// listing the valid names or options.
BoundSpec parse_bound(std::string_view spec);

}  // namespace ccd
