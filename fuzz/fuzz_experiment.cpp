// The experiment reader: parse, fill in defaults, write back; a generated scene of a few
// bodies is generated too (the generators' parameter checks are part of the reader).
#include "fuzz_support.hpp"

#include <experiments/experiment.hpp>
#include <experiments/run_experiment.hpp>

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccdlab::Experiment e;
  try {
    e = ccdlab::experiment_from_json(ccd::parse_json_text(ccdfuzz::as_text(data, size), "fuzz.json"), "fuzz.json");
  } catch (const ccd::InputError&) {
    return 0;
  }
  // What the results file records parses again to the same experiment.
  const nlohmann::json stored = ccdlab::experiment_to_json(e);
  const ccdlab::Experiment again = ccdlab::experiment_from_json(stored, "again");
  FUZZ_CHECK(again.methods == e.methods && again.dt == e.dt && again.name == e.name && again.repeats == e.repeats);
  FUZZ_CHECK(!e.name.empty() && e.name.find('/') == std::string::npos);
  if (!e.scene_generator.is_object()) return 0;
  const auto bodies = e.scene_generator.find("bodies");
  if (bodies == e.scene_generator.end() || !bodies->is_number() || !(bodies->get<double>() <= 64)) return 0;
  try {
    const ccd::Scene scene = ccdlab::load_experiment_scene(e, "fuzz.json");
    ccdlab::check_dt_against_horizon(e, scene.horizon, "fuzz.json");
    const double work = ccdlab::experiment_work(e, scene.bodies.size(), scene.horizon);
    FUZZ_CHECK(work >= 0.0);
  } catch (const ccd::InputError&) {
  }
  return 0;
}
