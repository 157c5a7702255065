#pragma once
// The benchmarks' list options, `--sizes=N,N,...` and `--threads=T,T,...`: taken out of
// the command line before the rest goes to Google Benchmark (benchmark::Initialize).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ccdlab::bench {

struct ListArgs {
  std::vector<std::size_t> values;  // the defaults unless the option was given
  std::vector<char*> rest;          // every other argument, argv[0] first, in order
};
struct SizeArgs {
  std::vector<std::size_t> sizes;  // the defaults unless --sizes was given
  std::vector<char*> rest;         // every other argument, argv[0] first, in order
};

/// Splits `args` into the values of `--NAME=A,B,...` (each in [lo, hi]; the last such
/// option wins) and the rest. A bad list prints
/// "<program>: --NAME needs integers in [<lo>, <hi_text>], e.g. <example>" on stderr and
/// gives nothing (the caller exits 2).
std::optional<ListArgs> take_list(std::vector<char*> args, const char* name, std::vector<std::size_t> defaults,
                                  const char* program, std::size_t lo, std::size_t hi, const char* hi_text,
                                  const char* example);

/// `--sizes=N,N,...` out of argv: sizes in [1, max_n] (max_text: max_n as printed), e.g.
/// --sizes=1000,10000.
std::optional<SizeArgs> take_sizes(int argc, char** argv, std::vector<std::size_t> defaults, const char* program,
                                   std::size_t max_n, const char* max_text);

/// `--threads=T,T,...` out of `args` (e.g. take_sizes(...)->rest): thread counts in
/// [1, 1024], e.g. --threads=1,2,4,8,16.
std::optional<ListArgs> take_threads(std::vector<char*> args, std::vector<std::size_t> defaults,
                                     const char* program);

}  // namespace ccdlab::bench
