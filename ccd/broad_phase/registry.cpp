#include <ccd/broad_phase/registry.hpp>

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
std::unique_ptr<BroadPhase> make() {
  return std::make_unique<T>();
}

constexpr BroadPhaseInfo kBroadPhases[] = {
    {"brute", "all pairs, O(n^2): the reference", &make<BruteForce>},
    {"sap", "sweep and prune (I-COLLIDE): endpoint lists on 3 axes kept between frames, pair set updated from swaps",
     &make<SweepAndPrune>},
    {"sweep", "sort and sweep: coherent insertion sort of starts, re-swept every frame", &make<SortAndSweep>},
    {"grid", "uniform grid, cell = largest extent, radix-sorted cells, half stencil", &make<UniformGrid>},
    {"hgrid", "hierarchical grid, cell sizes doubling per level (Mirtich, Ericson)", &make<HierarchicalGrid>},
    {"rtree", "Boost.Geometry R-tree (quadratic, 16), bulk-loaded per frame: library baseline",
     &make<BoostRtree>},
};

}  // namespace

std::span<const BroadPhaseInfo> broad_phase_registry() { return kBroadPhases; }

const BroadPhaseInfo& find_broad_phase(std::string_view name) {
  for (const BroadPhaseInfo& info : kBroadPhases)
    if (info.name == name) return info;
  std::string names;
  for (const BroadPhaseInfo& info : kBroadPhases) names += (names.empty() ? "" : ", ") + std::string(info.name);
  throw std::invalid_argument("unknown broad phase '" + std::string(name) + "' (valid: " + names + ")");
}

}  // namespace ccd
