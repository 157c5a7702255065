#pragma once
// "Did you mean ...?": the known name closest to a misspelt one, for error messages.
#include <span>
#include <string>
#include <string_view>

namespace ccd {

/// Edit distance (insertions, deletions, substitutions, and swaps of two neighbouring
/// characters, each costing 1), ignoring ASCII case.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate nearest to `name` when it is near enough to be a slip (at most 1 edit for
/// names up to 4 characters, 2 up to 8, else a third of the length); empty otherwise.
std::string nearest_name(std::string_view name, std::span<const std::string_view> candidates);

/// " (did you mean \"x\"?)" for the nearest candidate, or "" when none is near.
std::string did_you_mean(std::string_view name, std::span<const std::string_view> candidates);

/// " (did you mean \"x\"?)" for the nearest candidate, or " (known: a, b, c)" when none is near.
std::string suggestion(std::string_view name, std::span<const std::string_view> candidates);

}  // namespace ccd
