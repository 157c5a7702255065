#include <benchmarks/support/size_option.hpp>

#include <ccd/util/integer_text.hpp>

#include <cstdio>
#include <cstring>
#include <string>

namespace ccdlab::bench {

std::optional<ListArgs> take_list(std::vector<char*> args, const char* name, std::vector<std::size_t> defaults,
                                  const char* program, std::size_t lo, std::size_t hi, const char* hi_text,
                                  const char* example) {
  const std::string prefix = std::string("--") + name + "=";
  ListArgs out{std::move(defaults), {}};
  for (char* arg : args) {
    if (std::strncmp(arg, prefix.c_str(), prefix.size()) != 0) {
      out.rest.push_back(arg);
      continue;
    }
    const auto list = ccd::parse_integer_list(arg + prefix.size(), lo, hi);
    if (!list) {
      std::fprintf(stderr, "%s: --%s needs integers in [%zu, %s], e.g. %s\n", program, name, lo, hi_text, example);
      return std::nullopt;
    }
    out.values.assign(list->begin(), list->end());
  }
  return out;
}

std::optional<SizeArgs> take_sizes(int argc, char** argv, std::vector<std::size_t> defaults, const char* program,
                                   std::size_t max_n, const char* max_text) {
  auto list = take_list(std::vector<char*>(argv, argv + argc), "sizes", std::move(defaults), program, 1, max_n,
                        max_text, "--sizes=1000,10000");
  if (!list) return std::nullopt;
  return SizeArgs{std::move(list->values), std::move(list->rest)};
}

std::optional<ListArgs> take_threads(std::vector<char*> args, std::vector<std::size_t> defaults,
                                     const char* program) {
  return take_list(std::move(args), "threads", std::move(defaults), program, 1, 1024, "1024",
                   "--threads=1,2,4,8,16");
}

}  // namespace ccdlab::bench
