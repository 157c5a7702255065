#include <ccd/scene/scene_binary.hpp>

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ccd {
namespace {

// Header layout (docs/formats.md); every offset in bytes from the start of the file.
constexpr std::size_t kVersionAt = 8;
constexpr std::size_t kFlagsAt = 12;
constexpr std::size_t kBodiesAt = 16;
constexpr std::size_t kAccelerationChangesAt = 24;
constexpr std::size_t kVelocityChangesAt = 32;
constexpr std::size_t kDigestAt = 40;
constexpr std::size_t kDigestBytes = 64;
constexpr std::size_t kHorizonAt = 104;
constexpr std::size_t kGravityAt = 112;
constexpr std::size_t kBoxMinAt = 136;
constexpr std::size_t kBoxMaxAt = 160;
constexpr std::size_t kBoundaryAt = 184;
constexpr std::size_t kReservedAt = 187;
static_assert(kReservedAt + 5 == kSceneBinaryHeaderBytes);

constexpr std::uint32_t kFlagBox = 1;

// Bytes per element of each section after the header.
constexpr std::uint64_t kVec3Bytes = 24;
constexpr std::uint64_t kCountBytes = 4;
constexpr std::uint64_t kChangeBytes = 32;  // t and a 3-vector

template <class U>
U little_endian(U x) {
  if constexpr (std::endian::native == std::endian::big) {
    if constexpr (sizeof(U) == 8) return __builtin_bswap64(x);
    if constexpr (sizeof(U) == 4) return __builtin_bswap32(x);
  }
  return x;
}

// Writes into a buffer sized in advance.
class Out {
 public:
  explicit Out(std::size_t size) : bytes_(size, '\0') {}
  void u32(std::uint32_t x) { put(little_endian(x)); }
  void u64(std::uint64_t x) { put(little_endian(x)); }
  void f64(double x) { u64(std::bit_cast<std::uint64_t>(x)); }
  void vec3(const Vec3& v) {
    f64(v.x());
    f64(v.y());
    f64(v.z());
  }
  void raw(std::string_view s) {
    std::memcpy(bytes_.data() + at_, s.data(), s.size());
    at_ += s.size();
  }
  void skip(std::size_t n) { at_ += n; }
  std::size_t at() const { return at_; }
  std::string take() { return std::move(bytes_); }

 private:
  template <class U>
  void put(U x) {
    std::memcpy(bytes_.data() + at_, &x, sizeof x);
    at_ += sizeof x;
  }
  std::string bytes_;
  std::size_t at_ = 0;
};

// Reads at offsets that the caller has checked against the length first.
struct In {
  const char* data;
  std::uint32_t u32(std::uint64_t at) const { return little_endian(get<std::uint32_t>(at)); }
  std::uint64_t u64(std::uint64_t at) const { return little_endian(get<std::uint64_t>(at)); }
  double f64(std::uint64_t at) const { return std::bit_cast<double>(u64(at)); }
  Vec3 vec3(std::uint64_t at) const { return {f64(at), f64(at + 8), f64(at + 16)}; }
  template <class U>
  U get(std::uint64_t at) const {
    U x;
    std::memcpy(&x, data + at, sizeof x);
    return x;
  }
};

std::string text(std::uint64_t x) { return std::to_string(x); }

bool is_digest_text(std::string_view s) {
  return s.size() == kDigestBytes &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

}  // namespace

std::optional<BinaryUnsupported> binary_scene_unsupported(const Scene& scene) {
  const std::string why = "the binary scene format carries sphere scenes only (no shapes, spin or scenery): keep this scene as JSON";
  if (!scene.shapes.empty()) return BinaryUnsupported{"shapes", why};
  if (scene.is_rigid())
    for (std::size_t i = 0; i < scene.rigid.size(); ++i)
      if (scene.rigid[i].shape != kNoShape || scene.rigid[i].spins())
        return BinaryUnsupported{"bodies[" + std::to_string(i) + "]", why};
  if (!scene.scenery.empty()) return BinaryUnsupported{"scenery", why};
  if (scene.scenery_mesh) return BinaryUnsupported{"scenery_mesh", why};
  return std::nullopt;
}

std::string scene_to_binary(const Scene& scene, const std::string& file) {
  if (const auto no = binary_scene_unsupported(scene)) throw InputError(file, no->field, no->reason);
  const std::uint64_t n = scene.bodies.size();
  std::uint64_t accelerations = 0, velocities = 0;
  for (const Body& b : scene.bodies) {
    if (b.acceleration_changes.size() > UINT32_MAX || b.velocity_changes.size() > UINT32_MAX)
      throw InputError(file, "bodies", "a body has more than 2^32 - 1 changes");
    accelerations += b.acceleration_changes.size();
    velocities += b.velocity_changes.size();
  }
  const std::string digest = scene_digest(scene);
  const std::uint64_t size = kSceneBinaryHeaderBytes + n * (8 + 3 * kVec3Bytes + 2 * kCountBytes) +
                             (accelerations + velocities) * kChangeBytes;
  Out out(static_cast<std::size_t>(size));
  out.raw(kSceneBinaryMagic);
  out.u32(kSceneBinaryVersion);
  out.u32(scene.box ? kFlagBox : 0);
  out.u64(n);
  out.u64(accelerations);
  out.u64(velocities);
  out.raw(digest);
  out.f64(scene.horizon);
  out.vec3(scene.gravity);
  if (scene.box) {
    out.vec3(scene.box->min);
    out.vec3(scene.box->max);
    for (Boundary b : scene.box->boundary) out.raw(b == Boundary::Wrap ? std::string_view("\1", 1) : std::string_view("\0", 1));
  } else {
    out.skip(2 * kVec3Bytes + 3);
  }
  out.skip(5);  // reserved, zero
  for (const Body& b : scene.bodies) out.f64(b.radius);
  for (const Body& b : scene.bodies) out.vec3(b.position);
  for (const Body& b : scene.bodies) out.vec3(b.velocity);
  for (const Body& b : scene.bodies) out.vec3(b.acceleration);
  for (const Body& b : scene.bodies) out.u32(static_cast<std::uint32_t>(b.acceleration_changes.size()));
  for (const Body& b : scene.bodies) out.u32(static_cast<std::uint32_t>(b.velocity_changes.size()));
  for (const Body& b : scene.bodies)
    for (const AccelerationChange& c : b.acceleration_changes) {
      out.f64(c.t);
      out.vec3(c.acceleration);
    }
  for (const Body& b : scene.bodies)
    for (const VelocityChange& c : b.velocity_changes) {
      out.f64(c.t);
      out.vec3(c.velocity);
    }
  return out.take();
}

Scene scene_from_binary(std::string_view bytes, const std::string& file, std::string* digest) {
  auto fail = [&](const std::string& field, const std::string& what) -> void { throw InputError(file, field, what); };
  const std::uint64_t size = bytes.size();
  if (size < kSceneBinaryMagic.size() || bytes.substr(0, kSceneBinaryMagic.size()) != kSceneBinaryMagic)
    fail("magic", "not a binary scene (it does not start with the 8 bytes 89 43 43 44 53 0d 0a 1a)");
  if (size < kSceneBinaryHeaderBytes)
    fail("header", "truncated: the header has " + text(kSceneBinaryHeaderBytes) + " bytes, the file " + text(size));
  const In in{bytes.data()};
  if (const std::uint32_t v = in.u32(kVersionAt); v != kSceneBinaryVersion)
    fail("version", text(v) + " is not supported (this ccdlab reads version " + text(kSceneBinaryVersion) + ")");
  const std::uint32_t flags = in.u32(kFlagsAt);
  if (flags & ~kFlagBox) fail("flags", "unknown flags " + text(flags & ~kFlagBox) + " (only bit 0, the box, is defined)");
  const std::string_view stored = bytes.substr(kDigestAt, kDigestBytes);
  if (!is_digest_text(stored)) fail("digest", "must be 64 lowercase hexadecimal digits");
  for (std::size_t k = kReservedAt; k < kSceneBinaryHeaderBytes; ++k)
    if (bytes[k] != '\0') fail("reserved", "header bytes 187 to 191 must be 0");

  Scene s;
  s.horizon = in.f64(kHorizonAt);
  s.gravity = in.vec3(kGravityAt);
  if (flags & kFlagBox) {
    WallBox box;
    box.min = in.vec3(kBoxMinAt);
    box.max = in.vec3(kBoxMaxAt);
    for (std::size_t k = 0; k < 3; ++k) {
      const unsigned char b = static_cast<unsigned char>(bytes[kBoundaryAt + k]);
      if (b > 1) fail("box.boundary[" + text(k) + "]", "must be 0 (reflect) or 1 (wrap), not " + text(b));
      box.boundary[k] = b == 1 ? Boundary::Wrap : Boundary::Reflect;
    }
    s.box = box;
  } else {
    for (std::size_t k = kBoxMinAt; k < kReservedAt; ++k)
      if (bytes[k] != '\0') fail("box", "given while the flags say there is no box (its bytes must be 0)");
  }

  // Sections in file order; each is checked to fit the bytes left before its offset is
  // computed, so no size or offset can overflow and no read leaves the file.
  const std::uint64_t n = in.u64(kBodiesAt);
  const std::uint64_t accelerations = in.u64(kAccelerationChangesAt);
  const std::uint64_t velocities = in.u64(kVelocityChangesAt);
  std::uint64_t at = kSceneBinaryHeaderBytes;
  auto section = [&](const char* name, std::uint64_t count, std::uint64_t element, const char* what) {
    if (count > (size - at) / element)
      fail(name, "truncated: " + text(count) + " " + what + " need " + text(element) + " bytes each from byte " + text(at) +
                     ", the file ends at byte " + text(size));
    const std::uint64_t begin = at;
    at += count * element;
    return begin;
  };
  const std::uint64_t radius_at = section("radius", n, 8, "bodies");
  const std::uint64_t position_at = section("position", n, kVec3Bytes, "bodies");
  const std::uint64_t velocity_at = section("velocity", n, kVec3Bytes, "bodies");
  const std::uint64_t acceleration_at = section("acceleration", n, kVec3Bytes, "bodies");
  const std::uint64_t acceleration_counts_at = section("acceleration_change_counts", n, kCountBytes, "bodies");
  const std::uint64_t velocity_counts_at = section("velocity_change_counts", n, kCountBytes, "bodies");
  const std::uint64_t acceleration_changes_at = section("acceleration_changes", accelerations, kChangeBytes, "changes");
  const std::uint64_t velocity_changes_at = section("velocity_changes", velocities, kChangeBytes, "changes");
  if (at != size)
    fail("length", text(size - at) + " bytes after the last section (the file should end at byte " + text(at) + ")");

  // The counts add up to the header's totals before any change is read.
  std::uint64_t sum_a = 0, sum_v = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    sum_a += in.u32(acceleration_counts_at + kCountBytes * i);
    sum_v += in.u32(velocity_counts_at + kCountBytes * i);
  }
  if (sum_a != accelerations)
    fail("acceleration_change_counts", "add up to " + text(sum_a) + ", the header says " + text(accelerations));
  if (sum_v != velocities)
    fail("velocity_change_counts", "add up to " + text(sum_v) + ", the header says " + text(velocities));

  s.bodies.resize(static_cast<std::size_t>(n));
  std::uint64_t next_a = acceleration_changes_at, next_v = velocity_changes_at;
  for (std::uint64_t i = 0; i < n; ++i) {
    Body& b = s.bodies[static_cast<std::size_t>(i)];
    b.radius = in.f64(radius_at + 8 * i);
    b.position = in.vec3(position_at + kVec3Bytes * i);
    b.velocity = in.vec3(velocity_at + kVec3Bytes * i);
    b.acceleration = in.vec3(acceleration_at + kVec3Bytes * i);
    if (const std::uint32_t k = in.u32(acceleration_counts_at + kCountBytes * i); k > 0) {
      b.acceleration_changes.resize(k);
      for (AccelerationChange& c : b.acceleration_changes) {
        c.t = in.f64(next_a);
        c.acceleration = in.vec3(next_a + 8);
        next_a += kChangeBytes;
      }
    }
    if (const std::uint32_t k = in.u32(velocity_counts_at + kCountBytes * i); k > 0) {
      b.velocity_changes.resize(k);
      for (VelocityChange& c : b.velocity_changes) {
        c.t = in.f64(next_v);
        c.velocity = in.vec3(next_v + 8);
        next_v += kChangeBytes;
      }
    }
  }
  validate_scene(s, file);
  if (digest) *digest = std::string(stored);
  return s;
}

bool is_binary_scene_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  std::array<char, kSceneBinaryMagic.size()> head{};
  const ssize_t got = ::pread(fd, head.data(), head.size(), 0);
  ::close(fd);
  return got == static_cast<ssize_t>(head.size()) && std::string_view(head.data(), head.size()) == kSceneBinaryMagic;
}

Scene load_binary_scene(const std::string& path, std::string* digest) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path, "", std::string("cannot open file: ") + std::strerror(errno));
  std::string bytes;
  try {
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputError(path, "", std::string("cannot read file: ") + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw InputError(path, "", "cannot read file: not a regular file");
    const auto size = static_cast<std::uint64_t>(st.st_size);
    if (size > kMaxSceneBinaryBytes)
      throw InputError(path, "", "larger than " + std::to_string(kMaxSceneBinaryBytes) + " bytes");
    bytes.resize(static_cast<std::size_t>(size));
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t got = ::read(fd, bytes.data() + done, bytes.size() - done);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) throw InputError(path, "", std::string("cannot read file: ") + std::strerror(errno));
      if (got == 0) break;  // the file shrank while read: parse what is there
      done += static_cast<std::size_t>(got);
    }
    bytes.resize(done);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return scene_from_binary(bytes, path, digest);
}

void save_binary_scene(const Scene& scene, const std::string& path) {
  write_file_atomically(path, scene_to_binary(scene, path));
}

void verify_binary_scene_digest(const Scene& scene, const std::string& stored, const std::string& file) {
  const std::string computed = scene_digest(scene);
  if (computed != stored)
    throw InputError(file, "digest", "the stored digest " + stored.substr(0, 12) + "... is not the scene's (" +
                                         computed.substr(0, 12) + "...): the file is corrupt");
}

}  // namespace ccd
