#include <benchmarks/support/peer_scene.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

namespace ccdlab::bench {

namespace {

constexpr PeerSceneReference kReferences[] = {
    {1000, 0x823262fc1e6323f9ULL, 0x1a100702f3447ac5ULL, 121, 151, 0x871110e0760feca5ULL,
     0x2b24b64f9d81bd35ULL},
    {5000, 0xc24a407a24a4c07dULL, 0x637923834eae0fb2ULL, 679, 668, 0xaba09b97d5c4dc26ULL,
     0xe1b44ddbeff64dbeULL},
    {10000, 0x8ccc524a23b0a3bdULL, 0xbbe32fe64973ed02ULL, 1290, 1297, 0x38123a80466991cfULL,
     0xcef65f5820424577ULL},
    {100000, 0x5a86d97e74c2815fULL, 0xee334dfc6b79823bULL, 13579, 13536, 0x9016b9b24aebeb62ULL,
     0x1eceef28a4169653ULL},
    {1000000, 0xb81eeea6d241a3e0ULL, 0x33814fc02c0451edULL, 137153, 136608, 0xa4dd6da4b4ff7bdcULL,
     0xe0f439c86d46fc28ULL},
};

// libstdc++'s uniform_real_distribution<double>(a, b) over mt19937_64, written out:
// one 64-bit draw, scaled by 2^-64 (exact), clamped below 1, then u * (b - a) + a.
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : gen_(seed) {}
  double operator()(double a, double b) {
    double u = static_cast<double>(gen_()) * 0x1p-64;
    if (u >= 1.0) u = std::nextafter(1.0, 0.0);
    return u * (b - a) + a;
  }

 private:
  std::mt19937_64 gen_;
};

}  // namespace

std::span<const PeerSceneReference> peer_scene_references() { return kReferences; }

double peer_scene_side(std::size_t n) {
  switch (n) {
    case 1000: return 0x1.ffc68a192f3afp+5;
    case 5000: return 0x1.b58fdb05f1ec8p+6;
    case 10000: return 0x1.13a5913218f0bp+7;
    case 100000: return 0x1.28ee73f260aedp+8;
    case 1000000: return 0x1.3fdc164fbd84dp+9;
    default: break;
  }
  const double mean_volume = 4.0 / 3.0 * std::numbers::pi * 1.25;
  const double per_sphere = mean_volume / 0.02;
  return std::cbrt(static_cast<double>(n) * per_sphere);
}

std::uint64_t peer_pair_hash(std::uint32_t i, std::uint32_t j) {
  if (i > j) std::swap(i, j);
  std::uint64_t x = (static_cast<std::uint64_t>(i) << 32) | j;
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t peer_pair_checksum(std::span<const ccd::BodyPair> pairs) {
  std::uint64_t sum = 0;
  for (const ccd::BodyPair& p : pairs) sum += peer_pair_hash(p.a, p.b);
  return sum;
}

PeerScene::PeerScene(std::size_t n, std::uint64_t seed) : side_(peer_scene_side(n)) {
  for (int a = 0; a < 3; ++a) {
    p_[a].resize(n);
    v_[a].resize(n);
  }
  r_.resize(n);
  Uniform U(seed);
  const double L = side_;
  for (std::size_t i = 0; i < n; ++i) {
    p_[0][i] = U(0, L);
    p_[1][i] = U(0, L);
    p_[2][i] = U(0, L);
    r_[i] = U(0.5, 1.5);
    double dx = 0, dy = 0, dz = 0, q = 0;
    do {
      dx = U(-1, 1);
      dy = U(-1, 1);
      dz = U(-1, 1);
      q = dx * dx + dy * dy + dz * dz;
    } while (!(q > 1e-12 && q <= 1.0));
    const double speed = U(0, 10);
    const double k = speed / std::sqrt(q);
    v_[0][i] = dx * k;
    v_[1][i] = dy * k;
    v_[2][i] = dz * k;
  }
}

void PeerScene::step() {
  const double L = side_;
  for (int a = 0; a < 3; ++a) {
    double* p = p_[a].data();
    double* v = v_[a].data();
    for (std::size_t i = 0, n = r_.size(); i < n; ++i) {
      const double d = v[i] * kDt;
      double x = p[i] + d;
      if (x < 0) {
        x = -x;
        v[i] = -v[i];
      } else if (x > L) {
        x = (L + L) - x;
        v[i] = -v[i];
      }
      p[i] = x;
    }
  }
}

void PeerScene::boxes(std::vector<ccd::Aabb>& out) const {
  out.resize(r_.size());
  for (std::size_t i = 0; i < r_.size(); ++i) {
    const double r = r_[i];
    out[i].lo = ccd::Vec3(p_[0][i] - r, p_[1][i] - r, p_[2][i] - r);
    out[i].hi = ccd::Vec3(p_[0][i] + r, p_[1][i] + r, p_[2][i] + r);
  }
}

std::uint64_t PeerScene::state_hash() const {
  static_assert(std::endian::native == std::endian::little, "the hash is over little-endian bytes");
  std::uint64_t h = 0xcbf29ce484222325ULL;
  auto feed = [&h](double x) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &x, sizeof(double));
    for (unsigned char c : bytes) {
      h ^= c;
      h *= 0x100000001b3ULL;
    }
  };
  for (std::size_t i = 0; i < r_.size(); ++i) {
    feed(p_[0][i]);
    feed(p_[1][i]);
    feed(p_[2][i]);
    feed(v_[0][i]);
    feed(v_[1][i]);
    feed(v_[2][i]);
    feed(r_[i]);
  }
  return h;
}

}  // namespace ccdlab::bench
