#include "results_file.hpp"

#include "experiment.hpp"
#include "runner.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <string_view>
#include <vector>

namespace ccdlab {
namespace {

using nlohmann::json;
using Reader = ccd::JsonReader;
constexpr std::uint64_t kMaxCount = std::numeric_limits<std::uint64_t>::max();

// `v` has the shape of `schema` (a value as the writer writes it): every key of an object,
// numbers where numbers are (unsigned integers where the writer writes counts), booleans,
// strings. Keys the schema does not have are ignored, as in every ccdlab format.
void check_like(const json& schema, const json& v, const Reader& r, const std::string& field) {
  switch (schema.type()) {
    case json::value_t::object:
      if (!v.is_object()) r.fail(field, "must be an object");
      for (const auto& [key, sub] : schema.items()) check_like(sub, r.require(v, key.c_str(), field), r, field + "." + key);
      break;
    case json::value_t::number_unsigned:
    case json::value_t::number_integer: r.count(v, field, kMaxCount); break;
    case json::value_t::number_float: r.number(v, field); break;
    case json::value_t::boolean: r.boolean(v, field); break;
    case json::value_t::string: r.string(v, field); break;
    default: break;
  }
}

// The experiment as stored in results: it must parse as an experiment, and be stored in
// the form experiment_to_json writes.
Experiment stored_experiment(const json& j, const Reader& r) {
  Experiment e;
  json given = j;
  given.erase("acceleration_bound_used");  // added by ccdlab run beside the experiment's fields
  try {
    e = experiment_from_json(given, r.file);
  } catch (const ccd::InputError& err) {
    const std::string prefix = r.file + ": " + (err.field().empty() ? std::string() : err.field() + ": ");
    const std::string what = std::string(err.what()).substr(prefix.size());
    r.fail(err.field().empty() ? "experiment" : "experiment." + err.field(), what);
  }
  if (j["methods"] != json(method_names(e.methods))) r.fail("experiment.methods", "not as ccdlab run writes it");
  if (j["dt"] != json(e.dt)) r.fail("experiment.dt", "not as ccdlab run writes it (a sorted list)");
  const double a = r.number(r.require(j, "acceleration_bound_used", "experiment"), "experiment.acceleration_bound_used");
  if (a < 0.0) r.fail("experiment.acceleration_bound_used", "must be >= 0");
  return e;
}

void check_scene_summary(const json& s, const Reader& r) {
  if (!s.is_object()) r.fail("scene", "must be an object");
  const json& source = r.require(s, "source", "scene");
  if (!source.is_string() && !source.is_object()) r.fail("scene.source", "must be a path or a generator object");
  r.count(r.require(s, "bodies", "scene"), "scene.bodies", kMaxCount);
  if (r.number(r.require(s, "horizon", "scene"), "scene.horizon") <= 0.0) r.fail("scene.horizon", "must be > 0");
  const std::string& motion = r.string(r.require(s, "motion", "scene"), "scene.motion");
  if (motion != "linear" && motion != "shared_acceleration" && motion != "quadratic" && motion != "piecewise_quadratic")
    r.fail("scene.motion", "must be linear, shared_acceleration, quadratic or piecewise_quadratic");
  r.vec3(r.require(s, "gravity", "scene"), "scene.gravity");
  for (const char* k : {"radius_min", "radius_max", "max_acceleration"})
    r.number(r.require(s, k, "scene"), std::string("scene.") + k);
  r.count(r.require(s, "trajectory_pieces", "scene"), "scene.trajectory_pieces", kMaxCount);
  if (auto box = s.find("box"); box != s.end()) {
    if (!box->is_object()) r.fail("scene.box", "must be an object with min and max");
    r.vec3(r.require(*box, "min", "scene.box"), "scene.box.min");
    r.vec3(r.require(*box, "max", "scene.box"), "scene.box.max");
  }
}

std::string without_file(const ccd::InputError& e) {
  return std::string(e.what()).substr(e.file().size() + 2);
}

}  // namespace

void validate_results(const json& j, const std::string& file) {
  const Reader r{file};
  if (!j.is_object()) r.fail("", "a results file must be a JSON object");
  const json& format = r.require(j, "format", "");
  if (!format.is_string() || format.get<std::string>() != "ccdlab-results/2")
    r.fail("format", "must be \"ccdlab-results/2\"");
  const json& experiment = r.require(j, "experiment", "");
  if (!experiment.is_object()) r.fail("experiment", "must be an object");
  const Experiment e = stored_experiment(experiment, r);
  const json& scene = r.require(j, "scene", "");
  check_scene_summary(scene, r);
  try {
    check_dt_against_horizon(e, scene["horizon"].get<double>(), file);
  } catch (const ccd::InputError& err) {
    r.fail("experiment." + err.field(), without_file(err));
  }
  const json& truth = r.require(j, "truth", "");
  if (!truth.is_object()) r.fail("truth", "must be an object");
  const std::uint64_t events = r.count(r.require(truth, "events", "truth"), "truth.events", kMaxCount);
  r.count(r.require(truth, "tangent_events", "truth"), "truth.tangent_events", events);
  r.count(r.require(truth, "pairs", "truth"), "truth.pairs", events);
  if (r.number(r.require(truth, "seconds", "truth"), "truth.seconds") < 0.0) r.fail("truth.seconds", "must be >= 0");
  r.string(r.require(truth, "source", "truth"), "truth.source");
  const std::string digest = r.string(r.require(truth, "scene_sha256", "truth"), "truth.scene_sha256");
  if (digest.size() != 64 || digest.find_first_not_of("0123456789abcdef") != std::string::npos)
    r.fail("truth.scene_sha256", "must be 64 lowercase hex digits (the scene digest)");
  if (!r.require(j, "environment", "").is_object()) r.fail("environment", "must be an object");
  r.count(r.require(j, "peak_memory_bytes", ""), "peak_memory_bytes", kMaxCount);

  const json& shard = r.require(j, "shard", "");
  if (!shard.is_object()) r.fail("shard", "must be an object");
  const auto count = static_cast<std::uint64_t>(r.integer(r.require(shard, "count", "shard"), "shard.count", 1, 4096));
  const auto index = static_cast<std::uint64_t>(
      r.integer(r.require(shard, "index", "shard"), "shard.index", 1, static_cast<long long>(count)));
  const std::uint64_t jobs = e.methods.size() * e.dt.size();
  if (r.count(r.require(shard, "jobs", "shard"), "shard.jobs", kMaxCount) != jobs)
    r.fail("shard.jobs", "must be " + std::to_string(jobs) + " (methods x dt of the experiment)");
  if (auto m = shard.find("merged_from"); m != shard.end()) r.count(*m, "shard.merged_from", 4096);

  const json& records = r.require(j, "records", "");
  if (!records.is_array()) r.fail("records", "must be an array");
  // Records written before `undecided` and `static_undecided` existed lack them (read as 0).
  static const json schema = [] {
    json s = to_json(RunRecord{});
    s.erase("undecided");
    s.erase("static_undecided");
    return s;
  }();
  std::vector<bool> seen(jobs, false);
  std::uint64_t owned = 0;
  for (std::uint64_t k = 0; k < jobs; ++k) owned += k % count == index - 1;
  if (records.size() != owned)
    r.fail("records", "has " + std::to_string(records.size()) + " records; shard " + std::to_string(index) + "/" +
                          std::to_string(count) + " of " + std::to_string(jobs) + " jobs has " + std::to_string(owned));
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string p = "records[" + std::to_string(i) + "]";
    const json& rec = records[i];
    check_like(schema, rec, r, p);
    const std::uint64_t job = r.count(r.require(rec, "job", p), p + ".job", kMaxCount);
    if (job >= jobs) r.fail(p + ".job", "must be below shard.jobs = " + std::to_string(jobs));
    if (job % count != index - 1)
      r.fail(p + ".job", "job " + std::to_string(job) + " does not belong to shard " + std::to_string(index) + "/" +
                             std::to_string(count));
    if (seen[job]) r.fail(p + ".job", "job " + std::to_string(job) + " appears twice");
    seen[job] = true;
    if (rec["method"] != e.methods[job / e.dt.size()].name)
      r.fail(p + ".method", "must be '" + e.methods[job / e.dt.size()].name + "', the method of job " + std::to_string(job));
    if (rec["dt"].get<double>() != e.dt[job % e.dt.size()])
      r.fail(p + ".dt", "must be " + json(e.dt[job % e.dt.size()]).dump() + ", the dt of job " + std::to_string(job));
    if (rec["events"].get<std::uint64_t>() != events)
      r.fail(p + ".events", "must equal truth.events = " + std::to_string(events));
    // Events in progress at t = 0 are counted apart, in initial_contacts, and the events the
    // truth could not decide in undecided.
    const std::uint64_t undecided =
        rec.contains("undecided") ? r.count(rec["undecided"], p + ".undecided", kMaxCount) : 0;
    const std::uint64_t initial = rec["initial_contacts"].get<std::uint64_t>();
    if (undecided > events || initial > events - undecided ||
        rec["detected"].get<std::uint64_t>() > events - undecided - initial ||
        rec["missed"].get<std::uint64_t>() != events - undecided - initial - rec["detected"].get<std::uint64_t>())
      r.fail(p + ".missed", "undecided + initial_contacts + detected + missed must equal events");
  }
}

json merge_results(std::span<const ResultsShard> shards) {
  if (shards.empty()) throw ccd::InputError("merge", "", "no results to merge");
  for (const ResultsShard& s : shards) validate_results(s.results, s.file);
  const ResultsShard& first = shards.front();
  std::map<std::uint64_t, const ResultsShard*> by_index;
  std::map<std::uint64_t, json> by_job;
  std::uint64_t peak = 0;
  for (const ResultsShard& s : shards) {
    const Reader r{s.file};
    const json& j = s.results;
    if (j["experiment"] != first.results["experiment"])
      r.fail("experiment", "a different experiment than " + first.file);
    if (j["truth"]["scene_sha256"] != first.results["truth"]["scene_sha256"])
      r.fail("truth.scene_sha256", "a different scene than " + first.file + " (" + j["truth"]["scene_sha256"].dump() +
                                       " here, " + first.results["truth"]["scene_sha256"].dump() + " there)");
    const json& scene = j["scene"];
    for (const auto& [key, value] : first.results["scene"].items())
      if (!scene.contains(key) || scene[key] != value)
        r.fail("scene." + key, "a different scene than " + first.file + " (" + scene.value(key, json()).dump() +
                                   " here, " + value.dump() + " there)");
    for (const char* key : {"events", "tangent_events", "pairs"})
      if (j["truth"][key] != first.results["truth"][key])
        r.fail(std::string("truth.") + key, "a different ground truth than " + first.file);
    if (j["shard"]["count"] != first.results["shard"]["count"])
      r.fail("shard.count", "split " + j["shard"]["count"].dump() + " ways, " + first.file + " " +
                                first.results["shard"]["count"].dump() + " ways");
    const std::uint64_t index = j["shard"]["index"].get<std::uint64_t>();
    if (auto [it, fresh] = by_index.emplace(index, &s); !fresh)
      r.fail("shard.index", "shard " + std::to_string(index) + " is also " + it->second->file);
    for (const json& rec : j["records"]) by_job.emplace(rec["job"].get<std::uint64_t>(), rec);
    peak = std::max(peak, j["peak_memory_bytes"].get<std::uint64_t>());
  }
  const std::uint64_t total = first.results["shard"]["jobs"].get<std::uint64_t>();
  const std::uint64_t count = first.results["shard"]["count"].get<std::uint64_t>();
  if (by_index.size() != count) {
    std::string missing;
    for (std::uint64_t k = 1; k <= count; ++k)
      if (!by_index.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    throw ccd::InputError(first.file, "shard", "the shards " + missing + " of " + std::to_string(count) + " are missing");
  }
  json out = first.results;
  out["shard"] = {{"index", 1}, {"count", 1}, {"jobs", total}, {"merged_from", shards.size()}};
  json recs = json::array();
  for (auto& [job, rec] : by_job) recs.push_back(rec);
  out["records"] = std::move(recs);
  out["peak_memory_bytes"] = peak;
  return out;
}

}  // namespace ccdlab
