#include "near_miss_queries.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>

namespace ccd::cloth {
namespace near_miss {  // named: unity batches put several files in one compile
namespace {

// Draws from the raw engine output (the standard fixes it; the distributions it does not).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  /// k / 2^bits for k uniform in [lo 2^bits, hi 2^bits]: dyadic, exact.
  double dyadic(double lo, double hi, int bits) {
    const auto klo = static_cast<std::int64_t>(std::ldexp(lo, bits)),
               khi = static_cast<std::int64_t>(std::ldexp(hi, bits));
    const auto k = klo + static_cast<std::int64_t>(rng_() % static_cast<std::uint64_t>(khi - klo + 1));
    return std::ldexp(static_cast<double>(k), -bits);
  }

 private:
  std::mt19937_64 rng_;
};

// A case in its canonical frame: the query and whether it is meant to touch.
struct Canonical {
  LinearQuery q;
  bool contact;
};

// A family of cases. The touches of coplanar, parallel and collinear ones are placed
// exactly (an axis permutation with signs, no rounding): a rounded rotation would tilt
// their planes or lines by about 1e-16, which decides a touch of parallel primitives
// either way. Their misses are rotated like the others (a miss by the gap stays a miss).
struct Family {
  std::string name;
  std::function<Canonical(Draw&, double gap, bool touch)> make;
  bool exact_frame = false;
};

LinearQuery make(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& q0,
                 const Vec3& q1, const Vec3& q2, const Vec3& q3) {
  return LinearQuery{{p0, p1, p2, p3, q0, q1, q2, q3}};
}

// Vertex-face: a triangle f0 = 0, f1 on the x axis, f2 above it, in z = 0; the vertex moves.
struct Face {
  Vec3 f0, f1, f2;
};
// Draws in statements of their own: the order of evaluation of a call's arguments is not
// fixed, so draws in one argument list could come out in another order elsewhere.
Vec3 draw_vec(Draw& d, double lo, double hi, int bits) {
  const double x = d.dyadic(lo, hi, bits);
  const double y = d.dyadic(lo, hi, bits);
  const double z = d.dyadic(lo, hi, bits);
  return Vec3(x, y, z);
}

Face face(Draw& d) {
  const double l1 = d.dyadic(0.5, 1, 6);
  const double px = d.dyadic(0, 0.5, 6);
  const double py = d.dyadic(0.5, 1, 6);
  return {Vec3(0, 0, 0), Vec3(l1, 0, 0), Vec3(px, py, 0)};
}
LinearQuery still_face(const Face& f, const Vec3& v0, const Vec3& v1) {
  return make(v0, f.f0, f.f1, f.f2, v1, f.f0, f.f1, f.f2);
}
// A line through p, crossing z = 0 there at t = 1/2.
LinearQuery through(const Face& f, const Vec3& p, Draw& d) {
  Vec3 h = draw_vec(d, -0.5, 0.5, 6);
  h.z() = d.dyadic(0.25, 1, 6);
  return still_face(f, p + h, p - h);
}

const std::vector<Family>& vertex_face_families() {
  static const std::vector<Family> families = {
      {"through_beside_edge",  // outside edge f0 f1 by the gap, or inside it
       [](Draw& d, double g, bool touch) {
         const Face f = face(d);
         const double x = d.dyadic(0.125, 0.875, 6) * f.f1.x();
         return Canonical{through(f, Vec3(x, touch ? g : -g, 0), d), touch};
       }},
      {"through_beside_corner",
       [](Draw& d, double g, bool touch) {
         const Face f = face(d);
         return Canonical{through(f, touch ? Vec3(g, g / 2, 0) : Vec3(-g, -g, 0), d), touch};
       }},
      {"stops_short",  // comes down onto the interior, stopping at height g (or passing g below)
       [](Draw& d, double g, bool touch) {
         const Face f = face(d);
         const Vec3 c = (f.f0 + f.f1 + f.f2) / 4;
         Vec3 drift = draw_vec(d, -0.03125, 0.03125, 8);
         drift.z() = 0;
         const double h = d.dyadic(0.25, 1, 6);
         return Canonical{still_face(f, c + Vec3(0, 0, h), c + drift + Vec3(0, 0, touch ? -g : g)), touch};
       }},
      {"coplanar_beside_edge",  // slides in the face's plane along edge f0 f1, beside or on it
       [](Draw& d, double g, bool touch) {
         const Face f = face(d);
         const double y = touch ? g : -g;
         const double before = d.dyadic(0.25, 1, 6);
         const double after = d.dyadic(0.25, 1, 6);
         return Canonical{still_face(f, Vec3(-before, y, 0), Vec3(f.f1.x() + after, y, 0)), touch};
       },
       true},
      {"sliding_above",  // slides across the face at height g, or sinking from g to -g
       [](Draw& d, double g, bool touch) {
         const Face f = face(d);
         const double y = d.dyadic(0.0625, 0.125, 6), x = f.f1.x() / 2;  // (x, y) is inside
         return Canonical{still_face(f, Vec3(x - 1, y, g), Vec3(x + 1, y, touch ? -g : g)), touch};
       }},
      {"coplanar_past_corner",  // in the face's plane, passing corner f0 by the gap, or cutting it
       [](Draw& d, double g, bool touch) {
         const Face f = face(d);
         const Vec3 p = touch ? Vec3(g, g / 2, 0) : Vec3(-g, -g, 0);
         const double s = d.dyadic(0.25, 1, 6);
         return Canonical{still_face(f, p + Vec3(-s, s, 0), p + Vec3(s, -s, 0)), touch};
       },
       true},
  };
  return families;
}

// Edge-edge: edge a from the origin along the x axis; edge b moves.
LinearQuery against(double la, const Vec3& b0, const Vec3& b1, const Vec3& c0, const Vec3& c1) {
  return make(Vec3(0, 0, 0), Vec3(la, 0, 0), b0, b1, Vec3(0, 0, 0), Vec3(la, 0, 0), c0, c1);
}
// b from (x0, y0) to (x1, y1) in its plane, falling from z0 to z1.
LinearQuery falling(double la, double x0, double y0, double x1, double y1, double z0, double z1) {
  return against(la, Vec3(x0, y0, z0), Vec3(x1, y1, z0), Vec3(x0, y0, z1), Vec3(x1, y1, z1));
}

const std::vector<Family>& edge_edge_families() {
  static const std::vector<Family> families = {
      {"beside_end_point",  // b crosses a's line beyond its end point by the gap, or short of it
       [](Draw& d, double g, bool touch) {
         const double la = d.dyadic(0.5, 1, 6), x = la + (touch ? -g : g);
         const Vec3 e = draw_vec(d, 0.25, 1, 6);  // b's extents below and above a, its fall
         const double z1 = d.dyadic(0.25, 1, 6);
         return Canonical{falling(la, x, -e.x(), x, e.y(), e.z(), -z1), touch};
       }},
      {"end_point_short",  // b's end point passes a by the gap, or reaches past it
       [](Draw& d, double g, bool touch) {
         const double la = d.dyadic(0.5, 1, 6), x = d.dyadic(0.125, 0.375, 6);
         const Vec3 e = draw_vec(d, 0.25, 1, 6);  // b's length, its fall
         return Canonical{falling(la, x, touch ? -g : g, x, e.x(), e.y(), -e.z()), touch};
       }},
      {"parallel_stops_short",  // b parallel above a, falling to height g (or g below)
       [](Draw& d, double g, bool touch) {
         const double la = d.dyadic(0.5, 1, 6), x = d.dyadic(-0.25, 0.25, 6);
         const double len = d.dyadic(0.25, 1, 6), z0 = d.dyadic(0.25, 1, 6);
         return Canonical{falling(la, x, 0, x + len, 0, z0, touch ? -g : g), touch};
       },
       true},
      {"parallel_sliding",  // b parallel to a at distance g in a's plane, sliding along it (or across)
       [](Draw& d, double g, bool touch) {
         const double la = d.dyadic(0.5, 1, 6), len = d.dyadic(0.25, 1, 6), s = d.dyadic(0.5, 1, 6);
         return Canonical{against(la, Vec3(-s, g, 0), Vec3(-s + len, g, 0),
                                  Vec3(la + s - len, touch ? -g : g, 0), Vec3(la + s, touch ? -g : g, 0)),
                          touch};
       },
       true},
      {"collinear_sliding",  // b on a's line sliding towards a, stopping g short (or g over)
       [](Draw& d, double g, bool touch) {
         const double la = d.dyadic(0.5, 1, 6), len = d.dyadic(0.25, 1, 6), x = la + (touch ? -g : g);
         const double start = la + d.dyadic(0.25, 1, 6);
         return Canonical{
             against(la, Vec3(start, 0, 0), Vec3(start + len, 0, 0), Vec3(x, 0, 0), Vec3(x + len, 0, 0)),
             touch};
       },
       true},
      {"nearly_parallel",  // b tilted by about g, falling through a's plane beside it (or across)
       [](Draw& d, double g, bool touch) {
         const double la = d.dyadic(0.5, 1, 6), x = d.dyadic(0.125, 0.25, 6);
         const double z0 = d.dyadic(0.25, 1, 6), z1 = d.dyadic(0.25, 1, 6);
         return Canonical{falling(la, x, touch ? -g : g, x + la, 2 * g, z0, -z1), touch};
       }},
  };
  return families;
}

// Rotated (a unit quaternion of dyadic components, normalised in doubles), scaled, moved by
// `offset`, and given a common velocity: F changes only by the rounding.
LinearQuery placed(const LinearQuery& q, Draw& d, double scale, const Vec3& offset, bool exact_frame) {
  if (exact_frame) {
    constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int* axes = kPermutations[static_cast<int>(d.dyadic(0, 5, 0))];
    const Vec3 sign = draw_vec(d, 0, 1, 0) * 2.0 - Vec3(1, 1, 1);
    const Vec3 shift = offset + draw_vec(d, -1, 1, 4) * scale;
    const Vec3 velocity = draw_vec(d, -0.5, 0.5, 4) * scale;
    LinearQuery out;
    for (std::size_t i = 0; i < 8; ++i) {
      for (int k = 0; k < 3; ++k) out.x[i][k] = sign[k] * q.x[i][axes[k]] * scale;
      out.x[i] += shift + (i >= 4 ? velocity : Vec3(0, 0, 0));
    }
    return out;
  }
  double w = d.dyadic(-1, 1, 8), x = d.dyadic(-1, 1, 8), y = d.dyadic(-1, 1, 8), z = d.dyadic(-1, 1, 8);
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  if (n == 0.0) w = 1.0;
  if (n > 0.0) w /= n, x /= n, y /= n, z /= n;
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  const Vec3 shift = offset + draw_vec(d, -1, 1, 4) * scale;
  const Vec3 velocity = draw_vec(d, -0.5, 0.5, 4) * scale;
  LinearQuery out;
  for (std::size_t i = 0; i < 8; ++i) {
    const Vec3 p = q.x[i] * scale;
    Vec3 rp;
    for (int k = 0; k < 3; ++k) rp[k] = (r[k][0] * p[0] + r[k][1] * p[1]) + r[k][2] * p[2];
    out.x[i] = rp + shift + (i >= 4 ? velocity : Vec3(0, 0, 0));
  }
  return out;
}

std::vector<NamedQuery> build(const std::vector<Family>& families, const std::string& prefix,
                              std::uint64_t seed) {
  Draw d(seed);
  constexpr int kGapExponents[] = {27, 30, 33, 36, 40};
  constexpr int kNear = 3, kFar = 2;
  std::vector<NamedQuery> out;
  for (const Family& family : families)
    for (const int e : kGapExponents)
      for (const bool touch : {false, true})
        for (int i = 0; i < kNear + kFar; ++i) {
          const bool far = i >= kNear;
          const Canonical c = family.make(d, std::ldexp(1.0, -e), touch);
          const LinearQuery q =
              far ? placed(c.q, d, 1024.0, Vec3(1048576, -1048576, 524288), family.exact_frame && touch)
                  : placed(c.q, d, 1.0, Vec3(0, 0, 0), family.exact_frame && touch);
          out.push_back({prefix + family.name + (touch ? "_over_2^-" : "_by_2^-") + std::to_string(e) +
                             (far ? "_far" : "") + "_" + std::to_string(i),
                         q, c.contact});
        }
  return out;
}

}  // namespace
}  // namespace near_miss

std::vector<NamedQuery> near_miss_queries(PrimitivePair kind) {
  return kind == PrimitivePair::VertexFace ? near_miss::build(near_miss::vertex_face_families(), "vf_", 20261)
                                           : near_miss::build(near_miss::edge_edge_families(), "ee_", 20262);
}

}  // namespace ccd::cloth
