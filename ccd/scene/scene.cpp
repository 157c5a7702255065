#include <ccd/scene/scene.hpp>

#include <ccd/shape/mass_properties.hpp>

#include <algorithm>

namespace ccd {

MotionKind Scene::motion_kind() const {
  bool any_change = false;
  bool any_acc = !gravity.isZero(0.0);
  bool differ = false;
  for (const Body& b : bodies) {
    if (!b.acceleration_changes.empty() || !b.velocity_changes.empty()) any_change = true;
    if (!b.acceleration.isZero(0.0)) any_acc = true;
    if (b.acceleration != bodies.front().acceleration) differ = true;
  }
  if (any_change) return MotionKind::PiecewiseQuadratic;
  if (!any_acc) return MotionKind::Linear;
  return differ ? MotionKind::Quadratic : MotionKind::SharedAcceleration;
}

void Scene::principal_inertia(std::size_t i, Vec3& moments, Eigen::Matrix3d& axes) const {
  const RigidBody r = rigid_body(i);
  if (r.inertia) {
    moments = *r.inertia;
    axes = Eigen::Matrix3d::Identity();
    return;
  }
  const bool shaped = r.shape != kNoShape;
  MassProperties m = shaped ? mass_properties(shapes[static_cast<std::size_t>(r.shape)], 1.0)
                            : sphere_mass_properties(bodies[i].radius, 1.0);
  const double density = r.mass ? *r.mass / m.volume : r.density.value_or(kDefaultDensity);
  const PrincipalInertia p = ccd::principal_inertia(density * m.inertia);
  moments = p.moments;
  axes = p.axes;
}

const char* to_string(SpinModel model) { return model == SpinModel::Free ? "free" : "prescribed"; }

double Scene::max_acceleration() const {
  double m = 0.0;
  for (const Body& b : bodies) {
    m = std::max(m, (b.acceleration + gravity).norm());
    for (const AccelerationChange& c : b.acceleration_changes)
      m = std::max(m, (c.acceleration + gravity).norm());
  }
  return m;
}

bool Scene::has_velocity_changes() const {
  return std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return !b.velocity_changes.empty(); });
}

bool Scene::is_rigid() const {
  if (!shapes.empty()) return true;
  for (const RigidBody& r : rigid)
    if (r.shape != kNoShape || r.spins()) return true;
  return false;
}

bool Scene::has_non_spheres() const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (kind(i) != ShapeKind::Sphere) return true;
  return false;
}

void Scene::add_rigid_body(Body body, RigidBody r) {
  if (r.shape != kNoShape) body.radius = shapes[static_cast<std::size_t>(r.shape)].enclosing_radius();
  rigid.resize(bodies.size());
  bodies.push_back(std::move(body));
  rigid.push_back(std::move(r));
}

const char* to_string(Boundary b) { return b == Boundary::Wrap ? "wrap" : "reflect"; }

const char* to_string(MotionKind kind) {
  switch (kind) {
    case MotionKind::Linear: return "linear";
    case MotionKind::SharedAcceleration: return "shared_acceleration";
    case MotionKind::Quadratic: return "quadratic";
    case MotionKind::PiecewiseQuadratic: return "piecewise_quadratic";
  }
  return "unknown";
}

}  // namespace ccd
