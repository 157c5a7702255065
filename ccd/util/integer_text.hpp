#pragma once
// The one parser of integers given as text on a command line (`--threads 4`,
// `--shard 2/8`, `--windows 16`, a benchmark's `--sizes=1000,10000`): decimal digits
// only, read in full (no sign, no spaces, no suffix), within [lo, hi]. Anything else is
// nullopt, and the caller names the flag in its usage error.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace ccd {

std::optional<std::uint64_t> parse_integer(std::string_view text, std::uint64_t lo, std::uint64_t hi);

/// A comma-separated list of such integers ("1000,10000"); nullopt if any item is bad or
/// the list is empty.
std::optional<std::vector<std::uint64_t>> parse_integer_list(std::string_view text, std::uint64_t lo,
                                                             std::uint64_t hi);

}  // namespace ccd
