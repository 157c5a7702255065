#include <benchmarks/support/size_option.hpp>

#include <ccd/util/integer_text.hpp>

#include <cstdio>
#include <cstring>

namespace ccdlab::bench {

std::optional<SizeArgs> take_sizes(int argc, char** argv, std::vector<std::size_t> defaults, const char* program,
                                   std::size_t max_n, const char* max_text) {
  SizeArgs out{std::move(defaults), {}};
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--sizes=", 8) != 0) {
      out.rest.push_back(argv[i]);
      continue;
    }
    const auto list = ccd::parse_integer_list(argv[i] + 8, 1, max_n);
    if (!list) {
      std::fprintf(stderr, "%s: --sizes needs integers in [1, %s], e.g. --sizes=1000,10000\n", program, max_text);
      return std::nullopt;
    }
    out.sizes.assign(list->begin(), list->end());
  }
  return out;
}

}  // namespace ccdlab::bench
