#include <ccd/queries/convex_distance.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

// The simplex: up to 4 points of the Minkowski difference of the cores.
struct Simplex {
  Vec3 w[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  int n = 0;
};

// The point of segment, triangle or tetrahedron `s` closest to the origin; `s` is reduced
// to the smallest sub-simplex holding it (Ericson, Real-Time Collision Detection, 5.1).
// Sets `inside` when s is a tetrahedron that holds the origin (then s is unchanged and
// the returned point is the origin).
Vec3 closest_on_segment(Simplex& s) {
  const Vec3 a = s.w[0], b = s.w[1];
  const Vec3 ab = b - a;
  const double t = -a.dot(ab);
  if (t <= 0.0) {
    s.n = 1;
    return a;
  }
  const double len2 = ab.squaredNorm();
  if (t >= len2) {
    s.w[0] = b;
    s.n = 1;
    return b;
  }
  // The part of a perpendicular to ab, from cross products: near the segment the
  // barycentric form a + ab t / |ab|^2 cancels to an error of ulps of |a|, which tilts a
  // short v by a large angle; the cross products keep v's direction to a few ulps.
  return ab.cross(a.cross(ab)) / len2;
}

Vec3 closest_on_triangle(Simplex& s) {
  const Vec3 a = s.w[0], b = s.w[1], c = s.w[2];
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0.0 && d2 <= 0.0) {
    s.n = 1;
    return a;
  }
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0.0 && d4 <= d3) {
    s.w[0] = b;
    s.n = 1;
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    s.n = 2;
    return a + ab * (d1 / (d1 - d3));
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0.0 && d5 <= d6) {
    s.w[0] = c;
    s.n = 1;
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    s.w[1] = c;
    s.n = 2;
    return a + ac * (d2 / (d2 - d6));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    s.w[0] = c;  // keep b, c
    s.n = 2;
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) {  // a degenerate (flat) triangle: its best edge
    Simplex e[3] = {{{a, b}, 2}, {{b, c}, 2}, {{a, c}, 2}};
    Vec3 best = Vec3::Zero();
    double bd = std::numeric_limits<double>::infinity();
    for (Simplex& x : e) {
      const Vec3 p = closest_on_segment(x);
      if (p.squaredNorm() < bd) bd = p.squaredNorm(), best = p, s = x;
    }
    return best;
  }
  // Inside the face: the origin's projection on the face's plane, from its normal (as for
  // the segment: the barycentric form cancels when the face passes close to the origin).
  const Vec3 n = ab.cross(ac);
  return n * (a.dot(n) / n.squaredNorm());
}

// Tetrahedron: the closest point over the faces the origin is outside of; when it is
// inside every face, `inside` is set and `depth` is its distance to the nearest face plane.
Vec3 closest_on_tetrahedron(Simplex& s, bool& inside, double& depth) {
  const Vec3 p[4] = {s.w[0], s.w[1], s.w[2], s.w[3]};
  static constexpr int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  const double volume = std::fabs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  double scale = 0.0;
  for (const Vec3& q : p) scale = std::max(scale, (q - p[0]).norm());
  // A tetrahedron flatter than this relative volume is treated as flat: every face is tried.
  const bool flat = !(volume > 1e-12 * scale * scale * scale);
  Vec3 best = Vec3::Zero();
  double bd = std::numeric_limits<double>::infinity();
  depth = std::numeric_limits<double>::infinity();
  bool any_outside = false;
  Simplex best_face;
  for (const auto& f : faces) {
    const Vec3 a = p[f[0]], b = p[f[1]], c = p[f[2]], d = p[f[3]];
    const Vec3 n = (b - a).cross(c - a);
    const double sign_o = -a.dot(n), sign_d = (d - a).dot(n);
    const bool outside = flat || sign_o * sign_d <= 0.0;
    if (!outside) {
      depth = std::min(depth, std::fabs(sign_o) / n.norm());
      continue;
    }
    any_outside = true;
    Simplex face{{a, b, c}, 3};
    const Vec3 q = closest_on_triangle(face);
    if (q.squaredNorm() < bd) bd = q.squaredNorm(), best = q, best_face = face;
  }
  inside = !any_outside;
  if (inside) return Vec3::Zero();
  s = best_face;
  return best;
}

// A proxy posed in the frame centred on A's centre. Proxies of up to kPosedPoints points
// (spheres, capsules, boxes, small hulls) are turned once per call and their supports are
// plain maxima of dot products; larger hulls turn the direction instead.
constexpr std::size_t kPosedPoints = 16;
class PosedProxy {
 public:
  PosedProxy(const ConvexProxy& x, const ProxyPose& pose, const Vec3& offset) : x_(x), pose_(pose), offset_(offset) {
    n_ = x.points.size() <= kPosedPoints ? x.points.size() : 0;
    for (std::size_t i = 0; i < n_; ++i) posed_[i] = offset + pose.rotation * x.points[i];
  }
  Vec3 support(const Vec3& d) const {
    if (n_ == 0) return offset_ + pose_.rotation * x_.points[x_.support_index(pose_.rotation.transpose() * d)];
    std::size_t best = 0;
    double best_dot = posed_[0].dot(d);
    for (std::size_t i = 1; i < n_; ++i) {
      const double y = posed_[i].dot(d);
      if (y > best_dot) {
        best_dot = y;
        best = i;
      }
    }
    return posed_[best];
  }

 private:
  const ConvexProxy& x_;
  const ProxyPose& pose_;
  Vec3 offset_;
  std::size_t n_ = 0;
  Vec3 posed_[kPosedPoints];
};

// When the cores overlap but the simplex ends on the origin (symmetric, often dyadic
// configurations), the overlap is certified another way: supports along the 4 directions of
// a regular tetrahedron (under a few fixed, generic rotations) span a tetrahedron inside the
// Minkowski difference; when it holds the origin, the cores overlap by at least the
// origin's distance to its nearest face plane. Returns that depth, or 0.
template <class Support>
double overlap_depth_by_supports(const Support& diff_support) {
  static const Vec3 dirs[4] = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  static const Eigen::Matrix3d turns[3] = {
      Eigen::Matrix3d::Identity(),
      Eigen::AngleAxisd(0.7853981, Vec3(0.267, 0.535, 0.802).normalized()).toRotationMatrix(),
      Eigen::AngleAxisd(1.3, Vec3(-0.6, 0.3, 0.742).normalized()).toRotationMatrix()};
  double best = 0.0;
  for (const Eigen::Matrix3d& r : turns) {
    Simplex s;
    for (int k = 0; k < 4; ++k) s.w[k] = diff_support(r * dirs[k]);
    s.n = 4;
    bool inside = false;
    double depth = 0.0;
    closest_on_tetrahedron(s, inside, depth);
    if (inside && depth > best) best = depth;
  }
  return best;
}

double proxy_extent(const ConvexProxy& x) {
  double m2 = 0.0;  // sqrt is monotonic and correctly rounded: sqrt(max |q|^2) = max |q|
  for (const Vec3& q : x.points) m2 = std::max(m2, q.squaredNorm());
  return std::sqrt(m2) + x.radius;
}

}  // namespace

ConvexDistance convex_distance(const ConvexProxy& a, const ProxyPose& pa, const ConvexProxy& b, const ProxyPose& pb,
                               const DistanceOptions& options) {
  ConvexDistance out;
  const Vec3 ob = pb.centre - pa.centre;  // B's centre in the frame centred on A's
  const double rounding =
      64.0 * std::numeric_limits<double>::epsilon() * (ob.norm() + proxy_extent(a) + proxy_extent(b));
  const double radii = a.radius + b.radius;
  const Vec3 zero = Vec3::Zero();
  const PosedProxy posed_a(a, pa, zero), posed_b(b, pb, ob);
  auto diff_support = [&](const Vec3& d) -> Vec3 { return posed_a.support(d) - posed_b.support(-d); };

  Simplex s;
  // Start from the support of the difference along A -> B (A's point furthest towards B
  // minus B's furthest towards A: near the closest pair), or along the warm-start guess.
  const bool warm = options.start_direction.squaredNorm() > 0.0;
  Vec3 v = diff_support(warm ? options.start_direction : ob.squaredNorm() > 0.0 ? Vec3(ob) : Vec3(Vec3::UnitX()));
  s.w[0] = v;
  s.n = 1;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = v.norm();
  double depth = 0.0;  // > 0: the cores overlap by at least this
  for (int it = 0; it < options.max_iterations; ++it) {
    out.iterations = it + 1;
    const double vn = v.norm();
    if (!std::isfinite(vn)) return out;  // Failed
    if (vn == 0.0) break;                // the origin is on the simplex: touching cores
    const Vec3 w = diff_support(-v);
    const double bound = v.dot(w) / vn;
    if (bound > lower) {
      lower = bound;
      out.direction = -v / vn;
    }
    if (upper - lower <= options.tolerance) break;
    bool repeated = false;
    for (int k = 0; k < s.n; ++k) repeated = repeated || s.w[k] == w;
    if (repeated) break;
    s.w[s.n++] = w;
    bool inside = false;
    Vec3 next = Vec3::Zero();
    switch (s.n) {
      case 2: next = closest_on_segment(s); break;
      case 3: next = closest_on_triangle(s); break;
      default: next = closest_on_tetrahedron(s, inside, depth); break;
    }
    if (inside) {
      upper = -depth;
      break;
    }
    const double nn = next.norm();
    if (!(nn < vn)) break;  // no progress: rounding
    v = next;
    upper = nn;
  }
  // Touching or overlapping cores with no depth found yet: try the support tetrahedra.
  if (upper <= rounding && !(upper < 0.0)) {
    const double d = overlap_depth_by_supports(diff_support);
    if (d > 0.0) upper = -d;
  }
  if (lower > upper) lower = upper;  // rounding between the two: keep a valid bracket
  // A core distance bound <= 0 says nothing about the depth of an overlap.
  out.lower = lower > 0.0 ? lower - radii - rounding : -std::numeric_limits<double>::infinity();
  out.upper = upper - radii + rounding;
  out.status = out.lower > 0.0   ? ConvexDistance::Status::Separated
               : out.upper < 0.0 ? ConvexDistance::Status::Overlapping
                                 : ConvexDistance::Status::Uncertain;
  return out;
}

}  // namespace ccd
