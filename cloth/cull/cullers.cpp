#include "cullers.hpp"

#include <cloth/cull/box_culler.hpp>
#include <cloth/cull/bvh_culler.hpp>
#include <cloth/cull/mesh_sweep_culler.hpp>
#include <cloth/cull/sensor_culler.hpp>

#include <deque>
#include <mutex>
#include <stdexcept>

namespace ccd::cloth {

namespace {

class BruteCuller final : public Culler {
 public:
  std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3>, double) override {
    return brute_force_candidates(mesh, x0.size());
  }
};

constexpr std::string_view kBoxesPrefix = "boxes:";

CullerEntry boxes_entry(std::string name, const BroadPhaseSpec& spec) {
  const std::string description =
      "primitive swept boxes through the broad phase '" + std::string(spec.info->name) + "'";
  return {std::move(name), false, description,
          [spec] { return std::unique_ptr<Culler>(std::make_unique<BoxCuller>(spec)); }};
}

std::vector<CullerEntry> make_table() {
  std::vector<CullerEntry> t;
  t.push_back({"brute", false, "every non-adjacent pair: the reference", [] {
                 return std::unique_ptr<Culler>(std::make_unique<BruteCuller>());
               }});
  t.push_back({"bvh", false, "swept-box BVH over the triangles, refitted between calls", [] {
                 return std::unique_ptr<Culler>(std::make_unique<BvhCuller>(false));
               }});
  t.push_back({"bvh_cones", false, "bvh; skips the self-test of a patch with a narrow normal cone proved flat", [] {
                 return std::unique_ptr<Culler>(std::make_unique<BvhCuller>(true));
               }});
  t.push_back({"sensors", true, "particle sensors flag folds; the bvh tests only what they flag", [] {
                 return std::unique_ptr<Culler>(std::make_unique<SensorCuller>());
               }});
  t.push_back({"mesh_sweep", false,
               "sort and sweep in a grid of cells across the sweep axis (layout by a sampled cost): vertex "
               "boxes against face boxes, edges against edges, with half-interval boxes",
               [] { return std::unique_ptr<Culler>(std::make_unique<MeshSweepCuller>()); }});
  for (const BroadPhaseInfo& info : broad_phase_registry())
    t.push_back(boxes_entry(std::string(kBoxesPrefix) + std::string(info.name), parse_broad_phase(info.name)));
  return t;
}

}  // namespace

std::span<const CullerEntry> cullers() {
  static const std::vector<CullerEntry> table = make_table();
  return table;
}

const CullerEntry* find_culler(std::string_view name) {
  for (const CullerEntry& c : cullers())
    if (c.name == name) return &c;
  if (!name.starts_with(kBoxesPrefix)) return nullptr;
  // A `boxes:` spec with options: resolved once, kept for the program's lifetime.
  static std::mutex mutex;
  static std::deque<CullerEntry> specs;
  const std::lock_guard lock(mutex);
  for (const CullerEntry& c : specs)
    if (c.name == name) return &c;
  try {
    const BroadPhaseSpec spec = parse_broad_phase(name.substr(kBoxesPrefix.size()));
    return &specs.emplace_back(boxes_entry(std::string(name), spec));
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}

}  // namespace ccd::cloth
