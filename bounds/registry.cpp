#include <bounds/aabb_bound.hpp>
#include <ccd/util/nearest_name.hpp>
#include <bounds/capsule_bound.hpp>
#include <bounds/enclosing_sphere_bound.hpp>
#include <bounds/frame_aabb_bound.hpp>
#include <bounds/horn_bound.hpp>
#include <bounds/horn_sat_bound.hpp>
#include <bounds/obb_bound.hpp>
#include <bounds/obb_sat_bound.hpp>
#include <bounds/registry.hpp>
#include <bounds/sphere_bound.hpp>
#include <bounds/swept_aabb_bound.hpp>

#include <stdexcept>
#include <string>

namespace ccd {
namespace {

/// Largest M: 4 * M doubles per body and O(M) per pair test.
constexpr double kMaxPieces = 1024;

template <class T>
std::unique_ptr<Bound> make_plain(const ParameterSet&) {
  return std::make_unique<T>();
}
template <class T>
std::unique_ptr<Bound> make_pieces(const ParameterSet& p) {
  return std::make_unique<T>(static_cast<int>(p.integer("pieces")));
}

constexpr ParameterSpec kHornParameters[] = {
    {"pieces", double(HornBound::default_pieces), "sub-intervals M of the step, one moving box each",
     ParameterKind::Integer, {1.0, kMaxPieces}, "pieces"},
};
constexpr ParameterSpec kHornSatParameters[] = {
    {"pieces", double(HornSatBound::default_pieces), "sub-intervals M of the step, one oriented box each",
     ParameterKind::Integer, {1.0, kMaxPieces}, "pieces"},
};
constexpr ParameterSpec kObbSatParameters[] = {
    {"pieces", double(ObbSatBound::default_pieces),
     "sub-intervals M of the step, one oriented box each (grown by the turn and the sweep)",
     ParameterKind::Integer, {1.0, kMaxPieces}, "pieces"},
};

const BoundInfo kBounds[] = {
    {"sphere", "instant: the sphere at the sample time; test = centre distance <= r1 + r2",
     Knowledge::Instant, true, {}, &make_plain<SphereBound>},
    {"aabb", "instant: the sphere's box at the sample time; test = box overlap only",
     Knowledge::Instant, true, {}, &make_plain<AabbBound>},
    {"frame_aabb", "instant: the turned shape's tight box at the sample time (recomputed per sample); test = box overlap",
     Knowledge::Instant, true, {}, &make_plain<FrameAabbBound>},
    {"obb", "instant: the shape's oriented box at the sample time; test = 15-axis SAT",
     Knowledge::Instant, true, {}, &make_plain<ObbBound>},
    {"swept_aabb", "exact motion: box of the swept sphere over the step (reflections exact); test = box overlap",
     Knowledge::Exact, true, {}, &make_plain<SweptAabbBound>},
    {"capsule",
     "exact motion: chord capsule, radius + |a| h^2/8 (+ piece distances across reflections); "
     "test = segment distance",
     Knowledge::Exact, true, {}, &make_plain<CapsuleBound>},
    {"horn", "bounded |a| <= A: Hubbard horn in M axis-aligned moving trapezoids; folded at walls; earliest time",
     Knowledge::Bounded, true, kHornParameters, &make_pieces<HornBound>},
    {"horn_sat",
     "bounded |a| <= A: horn in M velocity-oriented moving cubes, 15-axis SAT in time; folded at walls",
     Knowledge::Bounded, true, kHornSatParameters, &make_pieces<HornSatBound>},
    {"enclosing_sphere", "bounded |a| <= A: one static sphere around the whole horn; box when near a wall",
     Knowledge::Bounded, true, {}, &make_plain<EnclosingSphereBound>},
    {"obb_sat",
     "exact motion and spin: M oriented boxes grown by the turn and the sweep of each sub-interval; "
     "test = 15-axis SAT per sub-interval; earliest time",
     Knowledge::Exact, true, kObbSatParameters, &make_pieces<ObbSatBound>},
};

std::string valid_names() {
  std::string s;
  for (const BoundInfo& b : kBounds) {
    if (!s.empty()) s += ", ";
    s += b.name;
    if (!b.parameters.empty()) s += "[:" + std::string(b.parameters[0].name) + "=N]";
  }
  return s;
}

std::string valid_options(const BoundInfo& info) {
  if (info.parameters.empty()) return "it takes none";
  std::string s = "valid: ";
  for (const ParameterSpec& p : info.parameters) s += (s.size() > 7 ? ", " : "") + describe_parameter(p);
  return s;
}

}  // namespace

std::unique_ptr<Bound> BoundInfo::make() const { return factory(resolve_parameters(parameters, {})); }

std::span<const BoundInfo> bound_registry() { return kBounds; }

BoundSpec parse_bound(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::string_view name = spec.substr(0, colon);
  const BoundInfo* info = nullptr;
  for (const BoundInfo& b : kBounds)
    if (b.name == name) info = &b;
  if (!info) {
    std::vector<std::string_view> names;
    for (const BoundInfo& b : kBounds) names.push_back(b.name);
      throw std::invalid_argument("unknown bound '" + std::string(name) + "' in '" + std::string(spec) + "'" +
                                did_you_mean(name, names) +
                                "; valid bounds: " + valid_names());
  }
  if (colon == std::string_view::npos) return {info, resolve_parameters(info->parameters, {})};
  try {
    const std::string_view first = info->parameters.empty() ? std::string_view() : info->parameters[0].name;
    return {info, resolve_parameters(info->parameters, option_values_from_text(spec.substr(colon + 1), first))};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("bound '" + std::string(spec) + "': " + e.what() + " (" + valid_options(*info) + ")");
  }
}

}  // namespace ccd
