#pragma once
// Shared by the libFuzzer harnesses (fuzz/README in docs/fuzzing.md): what a harness may
// let through is ccd::InputError (bad input, reported as one line by the CLI); any other
// exception, a crash, a sanitizer report or a broken invariant (FUZZ_CHECK) is a finding.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#define FUZZ_CHECK(condition)                                                               \
  do {                                                                                      \
    if (!(condition)) {                                                                     \
      std::fprintf(stderr, "%s:%d: invariant broken: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                         \
    }                                                                                       \
  } while (0)

namespace ccdfuzz {

inline std::string_view as_text(const unsigned char* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace ccdfuzz
