#pragma once
// Placing bodies without overlap at t = 0: a generator draws a body's position, and
// Placement draws it again while it overlaps or touches a body already placed
// (|c_i - c_j| <= r_i + r_j). Lookups go through a hash grid of cell 2 r_max, so placing
// N bodies costs O(N) at the volume fractions the generators allow (<= 0.5).
// With `allow_overlap` every first draw is kept (the generator's `overlap=1`).
#include <ccd/geometry/vec3.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace ccdlab {

class Placement {
 public:
  /// Attempts per body before giving up (the box is too full for non-overlapping bodies).
  static constexpr int max_attempts = 1000;

  Placement(double r_max, bool allow_overlap) : cell_(2.0 * r_max), allow_(allow_overlap) {}

  /// Calls draw() until it returns a position where a sphere of radius r overlaps no placed
  /// body, records it and returns it. Throws std::runtime_error after max_attempts draws.
  template <class Draw>
  ccd::Vec3 place(double r, Draw&& draw) {
    for (int attempt = 0; attempt < max_attempts; ++attempt) {
      const ccd::Vec3 x = draw();
      if (allow_ || is_free(x, r)) {
        if (!allow_) add(x, r);
        return x;
      }
    }
    throw std::runtime_error("cannot place body " + std::to_string(centres_.size()) + " without overlap after " +
                             std::to_string(max_attempts) + " draws: lower 'fraction' or set overlap=1");
  }

 private:
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>(k.x * 73856093) ^ static_cast<std::size_t>(k.y * 19349663) ^
             static_cast<std::size_t>(k.z * 83492791);
    }
  };
  Key key(const ccd::Vec3& x) const;
  bool is_free(const ccd::Vec3& x, double r) const;
  void add(const ccd::Vec3& x, double r);

  double cell_;
  bool allow_;
  std::vector<ccd::Vec3> centres_;
  std::vector<double> radii_;
  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> cells_;
};

}  // namespace ccdlab
