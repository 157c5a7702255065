#pragma once
// The answer to "what does each method miss, and what does it cost to miss none?", read off
// a results file: per method, the largest dt at which it missed no contact, its missed
// fraction at every dt, and its cost (seconds per simulated second) at the cheapest
// zero-miss point. `ccdlab run` and `ccdlab merge` print it and write it beside the results
// as Markdown (RESULTS.summary.md); docs/experiments.md shows an example.
#include <nlohmann/json.hpp>

#include <string>

namespace ccdlab {

/// The table as aligned plain text (for a terminal).
std::string summary_text(const nlohmann::json& results);
/// The same table as Markdown, with a heading naming the experiment and scene.
std::string summary_markdown(const nlohmann::json& results);
/// Where the Markdown summary of `results_path` goes: RESULTS.json -> RESULTS.summary.md.
std::string summary_path(const std::string& results_path);

}  // namespace ccdlab
