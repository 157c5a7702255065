#pragma once
// A closed time interval of contact [enter, exit] (seconds); enter == exit is a touching
// contact. Shared by the pair truth (ccd/truth/pair_contact.hpp) and the sphere-polygon
// query (ccd/queries/sphere_polygon.hpp).

namespace ccd {

struct ContactInterval {
  double enter = 0.0;
  double exit = 0.0;
  bool operator==(const ContactInterval&) const = default;
};

}  // namespace ccd
