// FCL 0.7 broad-phase managers as peers (see peer_method.hpp). Each body is an
// fcl::CollisionObjectd holding an fcl::Sphered of its radius, translated to its centre;
// FCL computes the box as centre + [-r, r], bit-identical to the scene's [p - r, p + r].
// Setup: registerObjects() then setup(). Frame, as FCL's documentation and tests do it:
// setTranslation() and computeAABB() on every object, manager->update(), then
// manager->collide(data, callback) with a callback that records the pair and never stops
// the query (no narrow phase). The callback applies the exact box test: the trees report
// only overlapping leaves, the spatial hash reports every pair sharing a hash bucket.
#include "peer_method.hpp"

#include <fcl/broadphase/broadphase_SSaP.h>
#include <fcl/broadphase/broadphase_SaP.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree_array.h>
#include <fcl/broadphase/broadphase_interval_tree.h>
#include <fcl/broadphase/broadphase_spatialhash.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <cstdint>

namespace ccdlab::peers {

namespace {

struct CallbackData {
  std::vector<ccd::BodyPair>* out = nullptr;
  std::uint64_t reported = 0;
};

bool record_pair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* d = static_cast<CallbackData*>(data);
  ++d->reported;
  const fcl::AABBd& a = o1->getAABB();
  const fcl::AABBd& b = o2->getAABB();
  if (boxes_overlap(a.min_.data(), a.max_.data(), b.min_.data(), b.max_.data())) {
    const auto i = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(o1->getUserData()));
    const auto j = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(o2->getUserData()));
    d->out->push_back(i < j ? ccd::BodyPair{i, j} : ccd::BodyPair{j, i});
  }
  return false;  // never stop: all pairs are wanted
}

class FclPeer final : public PeerMethod {
 public:
  explicit FclPeer(std::function<std::unique_ptr<fcl::BroadPhaseCollisionManagerd>(const ccdlab::bench::PeerScene&)> make)
      : make_(std::move(make)) {}

  void setup(const ccdlab::bench::PeerScene& scene, std::span<const ccd::Aabb>, std::vector<ccd::BodyPair>& out) override {
    manager_ = make_(scene);
    const std::span<const double> r = scene.radii();
    objects_.clear();
    objects_.reserve(r.size());
    std::vector<fcl::CollisionObjectd*> raw;
    raw.reserve(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
      fcl::Transform3d tf = fcl::Transform3d::Identity();
      tf.translation() = fcl::Vector3d(scene.centres(0)[i], scene.centres(1)[i], scene.centres(2)[i]);
      objects_.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(r[i]), tf));
      objects_.back()->setUserData(reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
      raw.push_back(objects_.back().get());
    }
    manager_->registerObjects(raw);
    manager_->setup();
    collide(out);
  }

  void frame(const ccdlab::bench::PeerScene& scene, std::span<const ccd::Aabb>, std::vector<ccd::BodyPair>& out) override {
    const std::span<const double> x = scene.centres(0), y = scene.centres(1), z = scene.centres(2);
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      objects_[i]->setTranslation(fcl::Vector3d(x[i], y[i], z[i]));
      objects_[i]->computeAABB();
    }
    manager_->update();
    collide(out);
  }

  std::uint64_t reported_pairs() const override { return reported_; }

 private:
  void collide(std::vector<ccd::BodyPair>& out) {
    out.clear();
    CallbackData data{&out, 0};
    manager_->collide(&data, record_pair);
    reported_ = data.reported;
  }

  std::function<std::unique_ptr<fcl::BroadPhaseCollisionManagerd>(const ccdlab::bench::PeerScene&)> make_;
  std::unique_ptr<fcl::BroadPhaseCollisionManagerd> manager_;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects_;
  std::uint64_t reported_ = 0;
};

template <class Manager>
PeerInfo simple(std::string name, std::string note) {
  return {std::move(name), "fcl-0.7", std::move(note),
          [] {
            return std::make_unique<FclPeer>(
                [](const ccdlab::bench::PeerScene&) { return std::make_unique<Manager>(); });
          },
          false};
}

}  // namespace

std::vector<PeerInfo> fcl_peers() {
  std::vector<PeerInfo> v;
  v.push_back(simple<fcl::DynamicAABBTreeCollisionManagerd>("fcl_dynamic_aabb_tree",
                                                             "DynamicAABBTreeCollisionManager, default options"));
  v.push_back(simple<fcl::DynamicAABBTreeCollisionManager_Arrayd>(
      "fcl_dynamic_aabb_tree_array", "DynamicAABBTreeCollisionManager_Array, default options"));
  v.push_back(simple<fcl::SaPCollisionManagerd>("fcl_sap", "SaPCollisionManager"));
  v.push_back(simple<fcl::SSaPCollisionManagerd>("fcl_ssap", "SSaPCollisionManager"));
  v.push_back(simple<fcl::IntervalTreeCollisionManagerd>("fcl_interval_tree", "IntervalTreeCollisionManager"));
  // Spatial hashing: cell = the largest box extent (3, the smallest cell for which a box
  // spans at most 2 cells per axis), scene limits = the cube [0, L]^3 widened by the
  // largest radius (every box inside), hash table with one bucket per body.
  v.push_back({"fcl_spatial_hash", "fcl-0.7",
               "SpatialHashingCollisionManager (SimpleHashTable, N buckets, cell 3); superset filtered",
               [] {
                 return std::make_unique<FclPeer>([](const ccdlab::bench::PeerScene& s) {
                   const double rmax = *std::max_element(s.radii().begin(), s.radii().end());
                   const double lo = -rmax, hi = s.side() + rmax;
                   return std::make_unique<fcl::SpatialHashingCollisionManagerd<>>(
                       2 * rmax, fcl::Vector3d(lo, lo, lo), fcl::Vector3d(hi, hi, hi),
                       static_cast<unsigned>(std::max<std::size_t>(s.size(), 1000)));
                 });
               },
               false});
  return v;
}

}  // namespace ccdlab::peers
