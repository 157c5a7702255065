// The binary scene reader (ccd/scene/scene_binary.hpp): any bytes either give InputError
// or a valid scene whose binary file is the input itself, up to the stored digest (the
// format has one spelling per scene), and whose JSON form reads back with the same digest.
#include "fuzz_support.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::string_view bytes = ccdfuzz::as_text(data, size);
  ccd::Scene scene;
  std::string stored;
  try {
    scene = ccd::scene_from_binary(bytes, "fuzz.ccds", &stored);
  } catch (const ccd::InputError&) {
    return 0;
  }
  FUZZ_CHECK(stored.size() == 64);
  FUZZ_CHECK(!ccd::binary_scene_unsupported(scene));
  std::string again = ccd::scene_to_binary(scene, "again");
  FUZZ_CHECK(again.size() == bytes.size());
  const std::string digest = ccd::scene_digest(scene);
  FUZZ_CHECK(again.compare(40, 64, digest) == 0);
  again.replace(40, 64, stored);
  FUZZ_CHECK(again == bytes);
  const ccd::Scene from_json = ccd::scene_from_json(ccd::parse_json_text(ccd::scene_to_json(scene).dump(), "json"), "json");
  FUZZ_CHECK(ccd::scene_digest(from_json) == digest);
  return 0;
}
