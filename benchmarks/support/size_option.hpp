#pragma once
// The benchmarks' `--sizes=N,N,...` option: taken out of the command line before the rest
// goes to Google Benchmark (benchmark::Initialize).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ccdlab::bench {

struct SizeArgs {
  std::vector<std::size_t> sizes;  // the defaults unless --sizes was given
  std::vector<char*> rest;         // every other argument, argv[0] first, in order
};

/// Splits argv into the sizes (each in [1, max_n]) and the rest. A bad list prints
/// "<program>: --sizes needs integers in [1, <max_text>], e.g. --sizes=1000,10000" on stderr
/// and gives nothing (the caller exits 2).
std::optional<SizeArgs> take_sizes(int argc, char** argv, std::vector<std::size_t> defaults, const char* program,
                                   std::size_t max_n, const char* max_text);

}  // namespace ccdlab::bench
