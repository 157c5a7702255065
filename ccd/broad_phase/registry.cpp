#include <ccd/broad_phase/registry.hpp>
#include <ccd/util/nearest_name.hpp>

#include <ccd/broad_phase/brute_force.hpp>
#include <ccd/broad_phase/grid.hpp>
#include <ccd/broad_phase/hgrid.hpp>
#include <ccd/broad_phase/rtree.hpp>
#include <ccd/broad_phase/sap.hpp>
#include <ccd/broad_phase/sort_sweep.hpp>

#include <stdexcept>
#include <string>

namespace ccd {

namespace {

template <class T>
std::unique_ptr<BroadPhase> make_plain(const ParameterSet&) {
  return std::make_unique<T>();
}

constexpr double kMaxCount = 4294967295.0;  // fits every unsigned option

// `grid`'s and `hgrid`'s Verlet list (ccd/broad_phase/verlet_list.hpp).
constexpr ParameterSpec kReuseParameter{
    "reuse", double(detail::VerletList::kDefaultReuse),
    "frames one pair list, found on boxes grown by that much motion, serves while every box stays inside its grown box "
    "(exact; 0 = rebuild every frame)",
    ParameterKind::Integer, {0.0, 1024.0}, "frames"};

constexpr ParameterSpec kGridParameters[] = {
    {"cell", GridOptions::kCellSize, "smallest cell size; 0 = the largest box extent (a smaller value is raised to it)",
     ParameterKind::Real, {0.0, 1e12}, "scene length"},
    {"threads", double(GridOptions::kThreads), "threads for one find_pairs call (same pairs, same order)",
     ParameterKind::Integer, {1.0, 256.0}, "threads"},
    kReuseParameter,
};
std::unique_ptr<BroadPhase> make_grid(const ParameterSet& p) {
  GridOptions o;
  o.cell_size = p.number("cell");
  o.threads = static_cast<unsigned>(p.integer("threads"));
  o.reuse = static_cast<unsigned>(p.integer("reuse"));
  return std::make_unique<UniformGrid>(o);
}

constexpr ParameterSpec kHgridParameters[] = {kReuseParameter};
std::unique_ptr<BroadPhase> make_hgrid(const ParameterSet& p) {
  HgridOptions o;
  o.reuse = static_cast<unsigned>(p.integer("reuse"));
  return std::make_unique<HierarchicalGrid>(o);
}

constexpr ParameterSpec kSapParameters[] = {
    {"swaps_per_endpoint", double(SapOptions::kSwapsPerEndpoint),
     "swap budget per frame before a rebuild, in units of 6n bit_width(2n) (+ 64)", ParameterKind::Integer,
     {1.0, kMaxCount}, "swaps per endpoint"},
};
std::unique_ptr<BroadPhase> make_sap(const ParameterSet& p) {
  SapOptions o;
  o.swaps_per_endpoint = p.integer("swaps_per_endpoint");
  return std::make_unique<SweepAndPrune>(o);
}

constexpr ParameterSpec kSweepParameters[] = {
    {"swaps_per_body", double(SortSweepOptions::kSwapsPerBody),
     "swap budget per frame before a rebuild, in units of n (+ 64)", ParameterKind::Integer, {1.0, kMaxCount},
     "swaps per body"},
};
std::unique_ptr<BroadPhase> make_sweep(const ParameterSet& p) {
  SortSweepOptions o;
  o.swaps_per_body = p.integer("swaps_per_body");
  return std::make_unique<SortAndSweep>(o);
}

constexpr BroadPhaseInfo kBroadPhases[] = {
    {"brute", "all pairs, O(n^2): the reference", {}, &make_plain<BruteForce>},
    {"sap", "sweep and prune (I-COLLIDE): endpoint lists on 3 axes kept between frames, pair set updated from swaps",
     kSapParameters, &make_sap},
    {"sweep", "sort and sweep: coherent insertion sort of starts, re-swept every frame", kSweepParameters,
     &make_sweep},
    {"grid", "uniform grid, cell = largest extent, radix-sorted cells, half stencil; a Verlet list between rebuilds",
     kGridParameters, &make_grid},
    {"hgrid", "hierarchical grid, cell sizes doubling per level (Mirtich, Ericson); a Verlet list between rebuilds",
     kHgridParameters, &make_hgrid},
    {"rtree", "Boost.Geometry R-tree (quadratic, 16), bulk-loaded per frame: library baseline", {},
     &make_plain<BoostRtree>},
};

std::string valid_names() {
  std::string names;
  for (const BroadPhaseInfo& info : kBroadPhases) names += (names.empty() ? "" : ", ") + std::string(info.name);
  return names;
}

std::string valid_options(const BroadPhaseInfo& info) {
  if (info.parameters.empty()) return "it takes none";
  std::string s = "valid: ";
  for (const ParameterSpec& p : info.parameters) s += (s.size() > 7 ? ", " : "") + describe_parameter(p);
  return s;
}

}  // namespace

std::unique_ptr<BroadPhase> BroadPhaseInfo::make() const { return factory(resolve_parameters(parameters, {})); }

std::span<const BroadPhaseInfo> broad_phase_registry() { return kBroadPhases; }

const BroadPhaseInfo& find_broad_phase(std::string_view name) {
  for (const BroadPhaseInfo& info : kBroadPhases)
    if (info.name == name) return info;
  std::vector<std::string_view> names;
  for (const BroadPhaseInfo& info : kBroadPhases) names.push_back(info.name);
  throw std::invalid_argument("unknown broad phase '" + std::string(name) + "'" +
                              did_you_mean(name, names) + " (valid: " +
                              valid_names() + ")");
}

BroadPhaseSpec parse_broad_phase(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const BroadPhaseInfo& info = find_broad_phase(spec.substr(0, colon));
  if (colon == std::string_view::npos) return {&info, resolve_parameters(info.parameters, {})};
  try {
    return {&info, resolve_parameters(info.parameters, option_values_from_text(spec.substr(colon + 1), ""))};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("broad phase '" + std::string(spec) + "': " + e.what() + " (" +
                                valid_options(info) + ")");
  }
}

}  // namespace ccd
