#include <bounds/aabb_bound.hpp>
#include <bounds/capsule_bound.hpp>
#include <bounds/enclosing_sphere_bound.hpp>
#include <bounds/horn_bound.hpp>
#include <bounds/horn_sat_bound.hpp>
#include <bounds/registry.hpp>
#include <bounds/sphere_bound.hpp>
#include <bounds/swept_aabb_bound.hpp>

#include <charconv>
#include <stdexcept>
#include <string>

namespace ccd {
namespace {

/// Largest M accepted by parse_bound: 4 * M doubles per body and O(M) per pair test.
constexpr int kMaxParameter = 1024;

template <class T>
std::unique_ptr<Bound> make_plain(int) {
  return std::make_unique<T>();
}
template <class T>
std::unique_ptr<Bound> make_pieces(int m) {
  return std::make_unique<T>(m);
}

const BoundInfo kBounds[] = {
    {"sphere", "instant: the sphere at the sample time; test = centre distance <= r1 + r2",
     Knowledge::Instant, true, false, 0, &make_plain<SphereBound>},
    {"aabb", "instant: the sphere's box at the sample time; test = box overlap only",
     Knowledge::Instant, true, false, 0, &make_plain<AabbBound>},
    {"swept_aabb", "exact motion: box of the swept sphere over the step (reflections exact); test = box overlap",
     Knowledge::Exact, true, false, 0, &make_plain<SweptAabbBound>},
    {"capsule",
     "exact motion: chord capsule, radius + |a| h^2/8 (+ piece distances across reflections); "
     "test = segment distance",
     Knowledge::Exact, true, false, 0, &make_plain<CapsuleBound>},
    {"horn", "bounded |a| <= A: Hubbard horn in M axis-aligned moving trapezoids; folded at walls; earliest time",
     Knowledge::Bounded, true, true, HornBound::default_pieces, &make_pieces<HornBound>},
    {"horn_sat",
     "bounded |a| <= A: horn in M velocity-oriented moving cubes, 15-axis SAT in time; folded at walls",
     Knowledge::Bounded, true, true, HornSatBound::default_pieces, &make_pieces<HornSatBound>},
    {"enclosing_sphere", "bounded |a| <= A: one static sphere around the whole horn; box when near a wall",
     Knowledge::Bounded, true, false, 0, &make_plain<EnclosingSphereBound>},
};

std::string valid_names() {
  std::string s;
  for (const BoundInfo& b : kBounds) {
    if (!s.empty()) s += ", ";
    s += b.name;
    if (b.parameterised) s += "[:M]";
  }
  return s;
}

}  // namespace

std::span<const BoundInfo> bound_registry() { return kBounds; }

BoundSpec parse_bound(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::string_view name = spec.substr(0, colon);
  const BoundInfo* info = nullptr;
  for (const BoundInfo& b : kBounds)
    if (b.name == name) info = &b;
  if (!info)
    throw std::invalid_argument("unknown bound '" + std::string(name) + "' in '" + std::string(spec) +
                                "'; valid bounds: " + valid_names());
  if (colon == std::string_view::npos) return {info, info->default_parameter};
  const std::string_view arg = spec.substr(colon + 1);
  if (!info->parameterised)
    throw std::invalid_argument("bound '" + std::string(name) + "' takes no parameter (got ':" + std::string(arg) +
                                "'); valid bounds: " + valid_names());
  int m = 0;
  const auto [end, ec] = std::from_chars(arg.data(), arg.data() + arg.size(), m);
  if (arg.empty() || ec != std::errc() || end != arg.data() + arg.size() || m < 1 || m > kMaxParameter)
    throw std::invalid_argument("bad parameter '" + std::string(arg) + "' in '" + std::string(spec) +
                                "': M must be an integer in [1, " + std::to_string(kMaxParameter) + "]");
  return {info, m};
}

}  // namespace ccd
