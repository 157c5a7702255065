#pragma once
// "Which contacts did it miss?", answered on the terminal after the summary (`ccdlab run
// --list-missed`): per method the largest dt at which it missed a contact, the missed count
// as "311 of 1535 (20.3 %)" split into body-body and body-scenery, then the missed contacts
// in order of entry (the pair, or the body and scenery polygon; enter, exit, duration), at
// most a screenful over all methods with a count of the rest. Reads the records'
// missed_events and static_missed_events (written with --list-missed).
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace ccdlab {

/// The most contact lines missed_list_text prints, over all methods.
inline constexpr std::size_t kMissedListLines = 20;

std::string missed_list_text(const nlohmann::json& results, std::size_t max_lines = kMissedListLines);

}  // namespace ccdlab
