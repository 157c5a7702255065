#include <ccd/queries/sphere_touch.hpp>

#include <ccd/queries/sphere_sphere_contact.hpp>

namespace ccd {

bool spheres_touch(const Vec3& centre_a, double radius_a, const Vec3& centre_b, double radius_b) {
  const MovingSphere sa{centre_a, Vec3::Zero(), Vec3::Zero(), radius_a};
  const MovingSphere sb{centre_b, Vec3::Zero(), Vec3::Zero(), radius_b};
  const double R = radius_a + radius_b;
  const double f = (sa.position - sb.position).squaredNorm() - R * R;
  return f <= contact_tolerance(sa, sb, 0.0);
}

}  // namespace ccd
