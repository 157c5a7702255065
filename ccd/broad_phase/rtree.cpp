#include <ccd/broad_phase/rtree.hpp>

// Boost 1.74 Geometry includes a deprecated Boost header that prints a #pragma message.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <utility>

namespace ccd {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

struct BoostRtree::Impl {
  using Point = bg::model::point<double, 3, bg::cs::cartesian>;
  using Box = bg::model::box<Point>;
  using Value = std::pair<Box, std::uint32_t>;
  using Tree = bgi::rtree<Value, bgi::quadratic<16>>;
  std::vector<Value> values;
};

BoostRtree::BoostRtree() : impl_(std::make_unique<Impl>()) {}
BoostRtree::~BoostRtree() = default;

void BoostRtree::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  using Impl = BoostRtree::Impl;
  out.clear();
  stats_ = {};
  stats_.rebuilt = true;
  auto& values = impl_->values;
  values.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Aabb& b = boxes[i];
    values[i] = {Impl::Box(Impl::Point(b.lo.x(), b.lo.y(), b.lo.z()), Impl::Point(b.hi.x(), b.hi.y(), b.hi.z())),
                 static_cast<std::uint32_t>(i)};
  }
  const Impl::Tree tree(values.begin(), values.end());  // packing (bulk-loading) constructor
  for (const Impl::Value& v : values) {
    const std::uint32_t i = v.second;
    tree.query(bgi::intersects(v.first), boost::make_function_output_iterator([&](const Impl::Value& w) {
                 if (w.second > i) out.push_back({i, w.second});
               }));
  }
}

}  // namespace ccd
