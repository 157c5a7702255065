// "Did you mean": edit distance and the nearest known name.
#include <ccd/util/nearest_name.hpp>

#include <catch2/catch.hpp>
#include <string_view>
#include <vector>

namespace ccd_util_nearest_name_test {

using ccd::edit_distance;
using ccd::nearest_name;

TEST_CASE("edit distance counts insertions, deletions, substitutions and swaps", "[util]") {
  CHECK(edit_distance("velocity", "velocity") == 0);
  CHECK(edit_distance("velocty", "velocity") == 1);   // a deletion
  CHECK(edit_distance("velocityy", "velocity") == 1);  // an insertion
  CHECK(edit_distance("velocitx", "velocity") == 1);   // a substitution
  CHECK(edit_distance("vleocity", "velocity") == 1);   // two neighbours swapped
  CHECK(edit_distance("Radius", "radius") == 0);       // case ignored
  CHECK(edit_distance("", "abc") == 3);
  CHECK(edit_distance("abc", "") == 3);
  CHECK(edit_distance("kitten", "sitting") == 3);
}

TEST_CASE("nearest_name suggests only a near name, the nearest one", "[util]") {
  const std::vector<std::string_view> fields = {"radius", "position", "velocity", "acceleration",
                                                "acceleration_changes"};
  CHECK(nearest_name("velocty", fields) == "velocity");
  CHECK(nearest_name("positon", fields) == "position");
  CHECK(nearest_name("acceleration_change", fields) == "acceleration_changes");
  CHECK(nearest_name("accelration", fields) == "acceleration");
  CHECK(nearest_name("mass", fields).empty());    // 4 letters: at most 1 edit, none is near
  CHECK(nearest_name("colour", fields).empty());
  const std::vector<std::string_view> short_names = {"dt", "hz"};
  CHECK(nearest_name("dz", short_names) == "dt");  // ties: the first
  CHECK(nearest_name("xy", short_names).empty());
  CHECK(ccd::suggestion("velocty", fields) == R"( (did you mean "velocity"?))");
  CHECK(ccd::suggestion("xy", short_names) == " (known: dt, hz)");
  CHECK(ccd::did_you_mean("velocty", fields) == R"( (did you mean "velocity"?))");
  CHECK(ccd::did_you_mean("xy", short_names).empty());
}

}  // namespace ccd_util_nearest_name_test
