// `ccdlab merge` over several shards: the input is up to four results files separated by
// NUL bytes. A merge that succeeds gives a valid whole run with every job once.
#include "fuzz_support.hpp"

#include <experiments/results_file.hpp>

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  std::string_view rest = ccdfuzz::as_text(data, size);
  std::vector<ccdlab::ResultsShard> shards;
  try {
    while (shards.size() < 4) {
      const std::size_t nul = rest.find('\0');
      const std::string name = "shard" + std::to_string(shards.size() + 1) + ".json";
      shards.push_back({name, ccd::parse_json_text(rest.substr(0, nul), name)});
      if (nul == std::string_view::npos) break;
      rest.remove_prefix(nul + 1);
    }
    const nlohmann::json merged = ccdlab::merge_results(shards);
    ccdlab::validate_results(merged, "merged");
    FUZZ_CHECK(merged["records"].size() == merged["shard"]["jobs"].get<std::size_t>());
  } catch (const ccd::InputError&) {
  }
  return 0;
}
