// The results reader (what `ccdlab merge` checks in every shard); an accepted whole run
// (shard 1/1) merges alone into itself.
#include "fuzz_support.hpp"

#include <experiments/results_file.hpp>

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  nlohmann::json results;
  try {
    results = ccd::parse_json_text(ccdfuzz::as_text(data, size), "fuzz.json");
    ccdlab::validate_results(results, "fuzz.json");
  } catch (const ccd::InputError&) {
    return 0;
  }
  if (results["shard"]["count"] == 1) {
    const ccdlab::ResultsShard shard[] = {{"fuzz.json", results}};
    const nlohmann::json merged = ccdlab::merge_results(shard);
    FUZZ_CHECK(merged["records"].size() == results["records"].size());
    ccdlab::validate_results(merged, "merged");
  }
  return 0;
}
