// The truth reader: parse and validate; an accepted file is written and read back to the
// same events, bit for bit.
#include "fuzz_support.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/truth/truth_io.hpp>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccd::TruthFile truth;
  try {
    truth = ccd::truth_from_json(ccd::parse_json_text(ccdfuzz::as_text(data, size), "fuzz.json"), "fuzz.json");
  } catch (const ccd::InputError&) {
    return 0;
  }
  const ccd::TruthFile again = ccd::truth_from_json(ccd::parse_json_text(ccd::truth_to_text(truth), "again"), "again");
  FUZZ_CHECK(again.horizon == truth.horizon && again.events.size() == truth.events.size());
  for (std::size_t i = 0; i < truth.events.size(); ++i)
    FUZZ_CHECK(again.events[i].a == truth.events[i].a && again.events[i].b == truth.events[i].b &&
               again.events[i].enter == truth.events[i].enter && again.events[i].exit == truth.events[i].exit);
  return 0;
}
