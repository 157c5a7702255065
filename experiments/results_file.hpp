#pragma once
// Reading `ccdlab-results/2` files back (docs/experiments.md) and joining the shards of one
// run (`ccdlab merge`). A results file is checked as strictly as an experiment: every field
// the writer writes must be there with its type (records against the fields of
// to_json(RunRecord), so the check follows the writer), the experiment must parse as one,
// the shard must be 1 <= K <= N with N jobs consistent with the experiment, and each record's
// job must be in range, owned by the shard, once, with the method and dt of that job.
#include <nlohmann/json.hpp>

#include <span>
#include <string>

namespace ccdlab {

/// Throws ccd::InputError naming `file` and the field (`records[3].missed`).
void validate_results(const nlohmann::json& results, const std::string& file);

struct ResultsShard {
  std::string file;         ///< for error messages
  nlohmann::json results;   ///< a parsed ccdlab-results/2 document
};

/// Validates every shard, checks that they are of the same experiment, the same scene
/// (scene summary and truth.scene_sha256) and the same ground truth, split the same N ways, each shard
/// once and none missing; returns one results file ordered by job (shard 1/1, with
/// `merged_from`; peak memory the largest of the shards). Throws ccd::InputError naming the
/// file and the field.
nlohmann::json merge_results(std::span<const ResultsShard> shards);

}  // namespace ccdlab
