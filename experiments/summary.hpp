#pragma once
// The answer to "what does each method miss, and what does it cost to miss none?", read off
// a results file: the contacts to detect (body-body and body-scenery, record_contacts.hpp),
// per method its zero-miss frontier (the largest dt at which it missed no contact, nor at
// any smaller dt: the rule of `ccdlab report`), its cheapest zero-miss cost (seconds per
// simulated second) at or below the frontier, and its missed contacts at every dt. Every
// column has one unit: timesteps in Hz when the experiment gave every one as a frequency,
// else in seconds. `ccdlab run` and `ccdlab merge` print it (at most kSummaryWidth columns)
// and write it beside the results as Markdown (RESULTS.summary.md); docs/experiments.md
// shows an example.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace ccdlab {

/// The widest line of summary_text: wider tables continue in blocks below.
inline constexpr std::size_t kSummaryWidth = 100;

/// The table as aligned plain text (for a terminal).
std::string summary_text(const nlohmann::json& results);
/// The same table as Markdown, with a heading naming the experiment and scene.
std::string summary_markdown(const nlohmann::json& results);
/// Where the Markdown summary of `results_path` goes: RESULTS.json -> RESULTS.summary.md.
std::string summary_path(const std::string& results_path);

}  // namespace ccdlab
