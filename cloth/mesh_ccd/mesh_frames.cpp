#include "mesh_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace ccd::cloth {

namespace {

constexpr double kPi = std::numbers::pi;

double dyadic(double x) { return std::ldexp(std::nearbyint(std::ldexp(x, 20)), -20); }
Vec3 dyadic(const Vec3& p) { return {dyadic(p.x()), dyadic(p.y()), dyadic(p.z())}; }

// An nx x ny grid of vertices (index i + nx j, starting at `first`), each quad split along
// its diagonal.
void grid_faces(std::uint32_t first, std::uint32_t nx, std::uint32_t ny,
                std::vector<std::array<std::uint32_t, 3>>& faces) {
  for (std::uint32_t j = 0; j + 1 < ny; ++j)
    for (std::uint32_t i = 0; i + 1 < nx; ++i) {
      const std::uint32_t a = first + i + nx * j, b = a + 1, c = a + nx, d = c + 1;
      faces.push_back({a, b, d});
      faces.push_back({a, d, c});
    }
}

// Grid side for about `faces` triangles: 2 (n - 1)^2 ~ faces.
std::uint32_t grid_side(std::size_t faces) {
  return std::max<std::uint32_t>(3, static_cast<std::uint32_t>(std::lround(std::sqrt(faces / 2.0))) + 1);
}

// A UV sphere of `rings` latitude bands and 2 rings segments, still (x1 = x0).
void add_sphere(MeshFramePair& m, std::uint32_t rings, double radius) {
  const std::uint32_t seg = 2 * rings, first = static_cast<std::uint32_t>(m.x0.size());
  m.x0.push_back(dyadic(Vec3(0, 0, radius)));
  for (std::uint32_t r = 1; r < rings; ++r)
    for (std::uint32_t s = 0; s < seg; ++s) {
      const double th = kPi * r / rings, ph = 2 * kPi * s / seg;
      m.x0.push_back(dyadic(radius * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th))));
    }
  m.x0.push_back(dyadic(Vec3(0, 0, -radius)));
  const std::uint32_t south = static_cast<std::uint32_t>(m.x0.size()) - 1;
  auto ring = [&](std::uint32_t r, std::uint32_t s) { return first + 1 + (r - 1) * seg + s % seg; };
  for (std::uint32_t s = 0; s < seg; ++s) {
    m.faces.push_back({first, ring(1, s), ring(1, s + 1)});
    for (std::uint32_t r = 1; r + 1 < rings; ++r) {
      m.faces.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
      m.faces.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
    }
    m.faces.push_back({ring(rings - 1, s), south, ring(rings - 1, s + 1)});
  }
  m.x1.insert(m.x1.end(), m.x0.begin() + first, m.x0.end());
}

MeshFramePair sheet_on_sphere(std::size_t faces) {
  MeshFramePair m;
  // Half the faces for the sphere (4 rings^2 of them), half for the sheet.
  add_sphere(m, std::max<std::uint32_t>(3, static_cast<std::uint32_t>(std::lround(std::sqrt(faces / 8.0)))), 0.5);
  const std::uint32_t n = grid_side(faces / 2), first = static_cast<std::uint32_t>(m.x0.size());
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
      m.x0.push_back(dyadic(Vec3(x, y, 0.6)));
      // Fallen by 0.35, sagging at the rim: the middle is inside the sphere.
      m.x1.push_back(dyadic(Vec3(x, y, 0.25 - 0.15 * (x * x + y * y))));
    }
  grid_faces(first, n, n, m.faces);
  return m;
}

Vec3 rotate(const Vec3& p, const Vec3& centre, int axis, double angle) {
  const Vec3 d = p - centre;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  Vec3 r = d;
  r[a] = std::cos(angle) * d[a] - std::sin(angle) * d[b];
  r[b] = std::sin(angle) * d[a] + std::cos(angle) * d[b];
  return centre + r;
}

// Torus of core radius 1 and tube radius 1/4 about `axis` through `centre`.
void add_torus(MeshFramePair& m, std::uint32_t nu, std::uint32_t nv, const Vec3& centre, int axis, double twist,
               const Vec3& shift) {
  const std::uint32_t first = static_cast<std::uint32_t>(m.x0.size());
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  for (std::uint32_t j = 0; j < nv; ++j)
    for (std::uint32_t i = 0; i < nu; ++i) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv, rho = 1 + 0.25 * std::cos(v);
      Vec3 p = centre;
      p[a] += rho * std::cos(u);
      p[b] += rho * std::sin(u);
      p[axis] += 0.25 * std::sin(v);
      m.x0.push_back(dyadic(p));
      m.x1.push_back(dyadic(rotate(p, centre, axis, twist) + shift));
    }
  for (std::uint32_t j = 0; j < nv; ++j)
    for (std::uint32_t i = 0; i < nu; ++i) {
      const std::uint32_t p = first + i + nu * j, q = first + (i + 1) % nu + nu * j;
      const std::uint32_t r = first + i + nu * ((j + 1) % nv), s = first + (i + 1) % nu + nu * ((j + 1) % nv);
      m.faces.push_back({p, q, s});
      m.faces.push_back({p, s, r});
    }
}

MeshFramePair tori(std::size_t faces) {
  // Two linked tori: A about z through the origin, B about y through (1, 0, 0). Their core
  // circles stay 1 apart, so the tubes (radius 1/4) are 1/2 apart at t = 0. Each twists
  // about its own axis, and B moves 0.6 towards A: its core comes within 0.4 of A's.
  // At least 4 sides per tube: a 3-sided tube's cross-section (inscribed radius 1/8) is
  // too thin for the tubes to touch, and small frames would have no collision.
  MeshFramePair m;
  const auto nv = std::max<std::uint32_t>(4, static_cast<std::uint32_t>(std::lround(std::sqrt(faces / 16.0))));
  const auto nu = 4 * nv;  // 2 tori x 2 nu nv faces
  add_torus(m, nu, nv, Vec3(0, 0, 0), 2, 0.3, Vec3::Zero());
  add_torus(m, nu, nv, Vec3(1, 0, 0), 1, -0.3, Vec3(-0.6, 0, 0));
  return m;
}

MeshFramePair crumpled(std::size_t faces, std::uint64_t seed) {
  // A unit sheet with random bumps (a height field: no self-intersection at t = 0); by t = 1
  // its half x > 1/2 is folded over by 200 degrees about the line x = 1/2, z = 0, through
  // the other half, and bumped again.
  MeshFramePair m;
  const std::uint32_t n = grid_side(faces);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  struct Bump {
    double x, y, h, w;
  };
  auto bumps = [&] {
    std::vector<Bump> b(6);
    for (Bump& k : b) k = {unit(rng), unit(rng), 0.2 * (unit(rng) - 0.5), 0.05 + 0.1 * unit(rng)};
    return b;
  };
  const std::vector<Bump> b0 = bumps(), b1 = bumps();
  auto height = [](const std::vector<Bump>& bs, double x, double y) {
    double z = 0;
    for (const Bump& k : bs) z += k.h * std::exp(-((x - k.x) * (x - k.x) + (y - k.y) * (y - k.y)) / (k.w * k.w));
    return z;
  };
  const double fold = 200.0 / 180.0 * kPi;
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i) / (n - 1), y = static_cast<double>(j) / (n - 1);
      m.x0.push_back(dyadic(Vec3(x, y, height(b0, x, y))));
      Vec3 p(x, y, height(b1, x, y));
      if (x > 0.5) p = rotate(p, Vec3(0.5, 0, 0), 1, -fold * std::min(1.0, 4 * (x - 0.5)));
      m.x1.push_back(dyadic(p));
    }
  grid_faces(0, n, n, m.faces);
  return m;
}

constexpr std::string_view kNames[] = {"sheet_on_sphere", "tori", "crumpled"};

}  // namespace

std::span<const std::string_view> mesh_frame_generators() { return kNames; }

MeshFramePair generate_mesh_frames(std::string_view name, std::size_t faces, std::uint64_t seed) {
  if (faces < 8 || faces > (std::size_t{1} << 26))
    throw std::invalid_argument("faces must be in [8, 2^26], not " + std::to_string(faces));
  if (name == "sheet_on_sphere") return sheet_on_sphere(faces);
  if (name == "tori") return tori(faces);
  if (name == "crumpled") return crumpled(faces, seed);
  throw std::invalid_argument("unknown frame generator '" + std::string(name) +
                              "' (sheet_on_sphere, tori, crumpled)");
}

}  // namespace ccd::cloth
