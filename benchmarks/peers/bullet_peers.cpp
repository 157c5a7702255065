// Bullet 3.24 broad phases as peers (see peer_method.hpp), built against Debian's
// double-precision libraries (BT_USE_DOUBLE_PRECISION, the *-float64 libraries), so the
// boxes Bullet stores are the scene's doubles. One proxy per body (createProxy with the
// body's box, sphere shape type, default filter group and mask). Frame, as Bullet's
// collision world does it: setAabb(proxy, lo, hi) for every body, then
// calculateOverlappingPairs(dispatcher); the pairs are read from the overlapping pair cache.
// The cache is a superset of the exact pairs (btDbvtBroadphase keeps fattened leaves and
// removes stale pairs lazily, btAxisSweep3 quantises boxes to integers), so each cached
// pair gets the exact box test on the proxies' stored boxes, inside the timed frame: the
// check Bullet's dispatcher would do before the narrow phase.
#include "peer_method.hpp"

#include <BulletCollision/BroadphaseCollision/btAxisSweep3.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>

#include <algorithm>
#include <cstdint>
#include <limits>

static_assert(sizeof(btScalar) == sizeof(double), "peers_bench needs Bullet in double precision");

namespace ccdlab::peers {

namespace {

btVector3 vec(const ccd::Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }

class BulletPeer final : public PeerMethod {
 public:
  enum class Kind { Dbvt, AxisSweep32 };
  explicit BulletPeer(Kind kind) : kind_(kind), dispatcher_(&config_) {}
  ~BulletPeer() override {
    // btDbvtBroadphase allocates proxies one by one; btAxisSweep3 owns its handle array
    // (and removing its handles one by one would be quadratic).
    if (kind_ == Kind::Dbvt)
      for (btBroadphaseProxy* p : proxies_) broadphase_->destroyProxy(p, &dispatcher_);
  }

  void setup(const ccdlab::bench::PeerScene&, std::span<const ccd::Aabb> boxes, std::vector<ccd::BodyPair>& out) override {
    if (kind_ == Kind::Dbvt) {
      broadphase_ = std::make_unique<btDbvtBroadphase>();
    } else {
      ccd::Aabb world = boxes.empty() ? ccd::Aabb{} : boxes[0];
      for (const ccd::Aabb& b : boxes) world.merge(b);
      // No ray casts here: the optional internal btDbvtBroadphase for rays is disabled.
      broadphase_ = std::make_unique<bt32BitAxisSweep3>(vec(world.lo), vec(world.hi),
                                                        static_cast<unsigned>(boxes.size() + 1), nullptr, true);
    }
    proxies_.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
      proxies_.push_back(broadphase_->createProxy(vec(boxes[i].lo), vec(boxes[i].hi), SPHERE_SHAPE_PROXYTYPE,
                                                  reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)),
                                                  btBroadphaseProxy::DefaultFilter,
                                                  btBroadphaseProxy::AllFilter, &dispatcher_));
    query(out);
  }

  void frame(const ccdlab::bench::PeerScene&, std::span<const ccd::Aabb> boxes, std::vector<ccd::BodyPair>& out) override {
    for (std::size_t i = 0; i < boxes.size(); ++i)
      broadphase_->setAabb(proxies_[i], vec(boxes[i].lo), vec(boxes[i].hi), &dispatcher_);
    query(out);
  }

  std::uint64_t reported_pairs() const override { return reported_; }

 private:
  void query(std::vector<ccd::BodyPair>& out) {
    broadphase_->calculateOverlappingPairs(&dispatcher_);
    out.clear();
    btOverlappingPairCache* cache = broadphase_->getOverlappingPairCache();
    const btBroadphasePairArray& pairs = cache->getOverlappingPairArray();
    reported_ = static_cast<std::uint64_t>(pairs.size());
    for (int k = 0; k < pairs.size(); ++k) {
      const btBroadphaseProxy* a = pairs[k].m_pProxy0;
      const btBroadphaseProxy* b = pairs[k].m_pProxy1;
      if (!boxes_overlap(a->m_aabbMin.m_floats, a->m_aabbMax.m_floats, b->m_aabbMin.m_floats,
                         b->m_aabbMax.m_floats))
        continue;
      const auto i = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(a->m_clientObject));
      const auto j = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(b->m_clientObject));
      out.push_back(i < j ? ccd::BodyPair{i, j} : ccd::BodyPair{j, i});
    }
  }

  Kind kind_;
  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::vector<btBroadphaseProxy*> proxies_;
  std::uint64_t reported_ = 0;
};

}  // namespace

std::vector<PeerInfo> bullet_peers() {
  return {
      {"bullet_dbvt", "bullet-3.24-f64", "btDbvtBroadphase, default options; pair cache filtered to exact pairs",
       [] { return std::make_unique<BulletPeer>(BulletPeer::Kind::Dbvt); }, false},
      {"bullet_axis_sweep3_32", "bullet-3.24-f64",
       "bt32BitAxisSweep3 over the scene's box, no ray accelerator; quantised, filtered to exact pairs",
       [] { return std::make_unique<BulletPeer>(BulletPeer::Kind::AxisSweep32); }, true},
  };
}

}  // namespace ccdlab::peers
