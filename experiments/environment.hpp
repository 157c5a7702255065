#pragma once
// What machine and build produced a result: recorded in every results file.
#include <nlohmann/json.hpp>

namespace ccdlab {

/// {"ccdlab_version", "git", "compiler", "flags", "cpu", "cores", "threads", "hostname"}
nlohmann::json environment_json(int threads);

/// Peak resident memory of this process so far, in bytes.
long long peak_memory_bytes();

}  // namespace ccdlab
