// Boost.Geometry 1.74's R-tree as a peer (see peer_method.hpp), and ccdlab's own broad
// phases behind the same interface. The R-tree is used the way its documentation suggests
// for bodies that all move: rebuilt each frame with the packing (bulk-loading) constructor,
// then queried with bgi::intersects for every body's box (closed boxes: touching counts);
// a pair is kept from its smaller index only.
#include "peer_method.hpp"

#include <ccd/broad_phase/registry.hpp>

// Boost 1.74 Geometry includes a deprecated Boost header that prints a #pragma message.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <utility>

namespace ccdlab::peers {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

class BoostRstarPeer final : public PeerMethod {
 public:
  void setup(const ccdlab::bench::PeerScene& scene, std::span<const ccd::Aabb> boxes, std::vector<ccd::BodyPair>& out) override {
    frame(scene, boxes, out);
  }
  void frame(const ccdlab::bench::PeerScene&, std::span<const ccd::Aabb> boxes, std::vector<ccd::BodyPair>& out) override {
    out.clear();
    values_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const ccd::Aabb& b = boxes[i];
      values_[i] = {Box(Point(b.lo.x(), b.lo.y(), b.lo.z()), Point(b.hi.x(), b.hi.y(), b.hi.z())),
                    static_cast<std::uint32_t>(i)};
    }
    const Tree tree(values_.begin(), values_.end());
    for (const Value& v : values_) {
      const std::uint32_t i = v.second;
      tree.query(bgi::intersects(v.first), boost::make_function_output_iterator([&](const Value& w) {
                   if (w.second > i) out.push_back({i, w.second});
                 }));
    }
  }
  std::uint64_t reported_pairs() const override { return 0; }

 private:
  using Point = bg::model::point<double, 3, bg::cs::cartesian>;
  using Box = bg::model::box<Point>;
  using Value = std::pair<Box, std::uint32_t>;
  using Tree = bgi::rtree<Value, bgi::rstar<16>>;
  std::vector<Value> values_;
};

/// A registry broad phase: setup is its first find_pairs call, a frame any later one.
class RegistryMethod final : public PeerMethod {
 public:
  explicit RegistryMethod(std::unique_ptr<ccd::BroadPhase> m) : m_(std::move(m)) {}
  void setup(const ccdlab::bench::PeerScene&, std::span<const ccd::Aabb> boxes, std::vector<ccd::BodyPair>& out) override {
    m_->find_pairs(boxes, out);
  }
  void frame(const ccdlab::bench::PeerScene&, std::span<const ccd::Aabb> boxes, std::vector<ccd::BodyPair>& out) override {
    m_->find_pairs(boxes, out);
  }
  std::uint64_t reported_pairs() const override { return 0; }

 private:
  std::unique_ptr<ccd::BroadPhase> m_;
};

}  // namespace

std::vector<PeerInfo> boost_peers() {
  return {{"boost_rtree_rstar16", "boost-1.74", "bgi::rtree<rstar<16>>, packing constructor per frame, query per box",
           [] { return std::make_unique<BoostRstarPeer>(); }, false}};
}

std::vector<PeerInfo> ccdlab_methods() {
  std::vector<PeerInfo> v;
  for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
    if (info.name == "brute") continue;
    const bool boost = info.name == "rtree";  // the registry's library baseline
    v.push_back({std::string(info.name), boost ? "boost-1.74 (ccdlab registry)" : "ccdlab",
                 std::string(info.description), [&info] { return std::make_unique<RegistryMethod>(info.make()); },
                 false});
  }
  return v;
}

}  // namespace ccdlab::peers
