#include <ccd/scene/scene.hpp>

#include <algorithm>

namespace ccd {

MotionKind Scene::motion_kind() const {
  bool any_change = false;
  bool any_acc = !gravity.isZero(0.0);
  bool differ = false;
  for (const Body& b : bodies) {
    if (!b.acceleration_changes.empty()) any_change = true;
    if (!b.acceleration.isZero(0.0)) any_acc = true;
    if (b.acceleration != bodies.front().acceleration) differ = true;
  }
  if (any_change) return MotionKind::PiecewiseQuadratic;
  if (!any_acc) return MotionKind::Linear;
  return differ ? MotionKind::Quadratic : MotionKind::SharedAcceleration;
}

double Scene::max_acceleration() const {
  double m = 0.0;
  for (const Body& b : bodies) {
    m = std::max(m, (b.acceleration + gravity).norm());
    for (const AccelerationChange& c : b.acceleration_changes)
      m = std::max(m, (c.acceleration + gravity).norm());
  }
  return m;
}

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
