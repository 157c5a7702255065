#pragma once
// A set of body pairs {a, b} (a < b) for broad phases that keep their pairs between frames
// (`sap`): open addressing with linear probing over 64-bit keys (a << 32 | b), deletion
// by backward shift (no tombstones, so probe lengths do not decay), and a dense array of
// the members so that listing them costs O(size), not O(capacity). The load factor stays
// <= 1/2; the table doubles when needed and shrinks only in clear(). Insert and erase are
// idempotent (insert of a member, erase of a non-member: no change, return false).
// Degenerate input: a must be < b (a == b or a > b is a caller bug, not checked in Release).
#include <ccd/broad_phase/broad_phase.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

class PairSet {
 public:
  PairSet() { clear(); }
  /// Empties the set and sizes the table for about `expected` pairs.
  void clear(std::size_t expected = 0);
  /// Adds {a, b} (a < b); returns true if it was not a member.
  bool insert(std::uint32_t a, std::uint32_t b);
  /// Removes {a, b} (a < b); returns true if it was a member.
  bool erase(std::uint32_t a, std::uint32_t b);
  bool contains(std::uint32_t a, std::uint32_t b) const { return find(key(a, b)) != kNone; }
  std::size_t size() const { return dense_.size(); }
  /// The members, in no particular order.
  std::span<const BodyPair> pairs() const { return dense_; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // a < b, so never a key
  static constexpr std::size_t kNone = ~std::size_t{0};
  struct Slot {
    std::uint64_t key = kEmpty;
    std::uint32_t index = 0;  // position of the pair in dense_
  };
  static std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }
  std::size_t home(std::uint64_t k) const {
    return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> shift_);  // Fibonacci hashing
  }
  std::size_t find(std::uint64_t k) const;
  void resize_table(std::size_t capacity);

  std::vector<Slot> slots_;
  std::vector<BodyPair> dense_;
  std::size_t mask_ = 0;
  unsigned shift_ = 64;
};

}  // namespace ccd
