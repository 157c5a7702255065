// Mesh CCD between two frames (cloth/mesh_ccd/mesh_ccd.hpp) on generated frame pairs of
// about 10^5 faces (cloth/mesh_ccd/mesh_frames.hpp, made when the program starts):
//
//   BM_MeshCcd/<scene>/<threads>        broad + narrow phase (mesh_sweep, streamed), the
//                                       whole library call after the read
//   BM_Broad/<scene>/<method>           the broad phase alone, candidates counted:
//                                       mesh_sweep (half-interval boxes), sweep_plain (the
//                                       same sort and sweep without them: every pair of
//                                       overlapping swept boxes), and, with FCL, FCL's
//                                       dynamic AABB tree given the same swept boxes
//                                       (vertices against faces: one tree each, tree
//                                       against tree; edges: one tree, self query)
//
// Counters: candidates (vf + ee), collisions (the kernel's hits), candidates per
// collision. CPU time is the process's (all threads; FCL's: the calling thread's, the only
// one); real time is the wall clock. Frames: --faces=N (default 100000), separation
// --separation=D (default 0); --no-collisions skips the whole call made at the start to
// count the collisions (the counters then show 0 collisions).
#include <cloth/cull/primitive_boxes.hpp>
#include <cloth/mesh_ccd/mesh_ccd.hpp>
#include <cloth/mesh_ccd/mesh_frames.hpp>
#include <cloth/mesh_ccd/mesh_sweep.hpp>
#include <cloth/mesh_ccd/mesh_topology.hpp>
#include <ccd/util/parallel_for.hpp>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#ifdef CCDLAB_MESH_BENCH_FCL
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_object.h>
#endif

namespace {

using namespace ccd::cloth;

std::size_t g_faces = 100000;
double g_separation = 0.0;
bool g_count_collisions = true;

struct Frames {
  MeshFramePair m;
  ClothMesh mesh;
  std::uint64_t collisions = 0;
};

const Frames& frames(const std::string& name) {
  static std::map<std::string, Frames> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    Frames f;
    f.m = generate_mesh_frames(name, g_faces);
    f.mesh = mesh_topology(f.m.faces, f.m.x0.size());
    if (g_count_collisions) {
      MeshCcdOptions o;
      o.separation = g_separation;
      o.threads = 2;
      const MeshCcdResult r = mesh_ccd(f.m.x0, f.m.x1, f.m.faces, o);
      f.collisions = r.vf.size() + r.ee.size();
    }
    it = cache.emplace(name, std::move(f)).first;
  }
  return it->second;
}

void set_counters(benchmark::State& state, const Frames& f, std::uint64_t candidates) {
  state.counters["faces"] = static_cast<double>(f.m.faces.size());
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["collisions"] = static_cast<double>(f.collisions);
  state.counters["cand_per_collision"] =
      f.collisions ? static_cast<double>(candidates) / static_cast<double>(f.collisions) : 0.0;
}

void BM_MeshCcd(benchmark::State& state, std::string scene) {
  const Frames& f = frames(scene);
  MeshCcdOptions o;
  o.separation = g_separation;
  o.threads = static_cast<unsigned>(state.range(0));
  std::uint64_t candidates = 0;
  for (auto _ : state) {
    const MeshCcdResult r = mesh_ccd(f.m.x0, f.m.x1, f.m.faces, o);
    candidates = r.candidates_vf + r.candidates_ee;
    benchmark::DoNotOptimize(r.vf.data());
  }
  set_counters(state, f, candidates);
}

void BM_Sweep(benchmark::State& state, std::string scene, bool halves) {
  const Frames& f = frames(scene);
  const auto threads = static_cast<unsigned>(state.range(0));
  std::vector<std::vector<Candidate>> buffers(threads, std::vector<Candidate>(4096));
  std::vector<std::uint64_t> counts(threads);
  std::uint64_t candidates = 0;
  for (auto _ : state) {
    MeshSweep sweep;
    sweep.prepare(f.mesh, f.m.x0, f.m.x1, {g_separation, halves, threads});
    std::fill(counts.begin(), counts.end(), 0);
    ccd::parallel_for(sweep.chunks(), threads, [&](std::size_t k, unsigned w) {
      sweep.sweep(k, buffers[w], [&](std::span<const Candidate> b) { counts[w] += b.size(); });
    });
    candidates = 0;
    for (const auto c : counts) candidates += c;
  }
  set_counters(state, f, candidates);
}

#ifdef CCDLAB_MESH_BENCH_FCL
// A collision object whose box is given (the swept box), not computed from a shape.
class BoxObject final : public fcl::CollisionObjectd {
 public:
  BoxObject(const std::shared_ptr<fcl::CollisionGeometryd>& g, const ccd::Aabb& b, std::uintptr_t id)
      : fcl::CollisionObjectd(g) {
    aabb.min_ = fcl::Vector3d(b.lo.x(), b.lo.y(), b.lo.z());
    aabb.max_ = fcl::Vector3d(b.hi.x(), b.hi.y(), b.hi.z());
    setUserData(reinterpret_cast<void*>(id));
  }
};

struct FclData {
  const ClothMesh* mesh;
  bool vertex_face;
  std::uint64_t candidates = 0;
};

bool fcl_pair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* d = static_cast<FclData*>(data);
  const fcl::AABBd& a = o1->getAABB();
  const fcl::AABBd& b = o2->getAABB();
  for (int k = 0; k < 3; ++k)
    if (a.max_[k] < b.min_[k] || b.max_[k] < a.min_[k]) return false;
  auto i = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(o1->getUserData()));
  auto j = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(o2->getUserData()));
  if (d->vertex_face) {  // ids: vertices as is, faces offset by 2^31
    if (i >= 0x80000000u) std::swap(i, j);
    const Candidate c{PrimitivePair::VertexFace, i, j - 0x80000000u};
    d->candidates += !adjacent(*d->mesh, c);
  } else {
    d->candidates += !adjacent(*d->mesh, {PrimitivePair::EdgeEdge, std::min(i, j), std::max(i, j)});
  }
  return false;
}

void BM_FclDynamicTree(benchmark::State& state, std::string scene) {
  const Frames& f = frames(scene);
  const auto geometry = std::make_shared<fcl::Sphered>(0.0);
  std::uint64_t candidates = 0;
  for (auto _ : state) {
    std::vector<ccd::Aabb> vb;
    vertex_boxes(f.m.x0, f.m.x1, g_separation / 2, vb);
    std::vector<std::unique_ptr<BoxObject>> objects;
    std::vector<fcl::CollisionObjectd*> vertices, faces, edges;
    for (std::size_t i = 0; i < vb.size(); ++i) {
      objects.push_back(std::make_unique<BoxObject>(geometry, vb[i], i));
      vertices.push_back(objects.back().get());
    }
    for (std::size_t i = 0; i < f.mesh.triangles.size(); ++i) {
      objects.push_back(std::make_unique<BoxObject>(geometry, triangle_box(vb, f.mesh.triangles[i]), i + 0x80000000u));
      faces.push_back(objects.back().get());
    }
    for (std::size_t i = 0; i < f.mesh.edges.size(); ++i) {
      objects.push_back(std::make_unique<BoxObject>(geometry, edge_box(vb, f.mesh.edges[i]), i));
      edges.push_back(objects.back().get());
    }
    fcl::DynamicAABBTreeCollisionManagerd vm, fm, em;
    vm.registerObjects(vertices);
    fm.registerObjects(faces);
    em.registerObjects(edges);
    vm.setup();
    fm.setup();
    em.setup();
    FclData vf{&f.mesh, true}, ee{&f.mesh, false};
    fm.collide(&vm, &vf, fcl_pair);
    em.collide(&ee, fcl_pair);
    candidates = vf.candidates + ee.candidates;
  }
  set_counters(state, f, candidates);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  // Own options first (--faces=N, --separation=D), then Google Benchmark's.
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--faces=", 8) == 0)
      g_faces = std::strtoull(argv[i] + 8, nullptr, 10);
    else if (std::strcmp(argv[i], "--no-collisions") == 0)
      g_count_collisions = false;
    else if (std::strncmp(argv[i], "--separation=", 13) == 0)
      g_separation = std::strtod(argv[i] + 13, nullptr);
    else
      rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  for (const std::string_view scene : mesh_frame_generators()) {
    const std::string s(scene);
    // CPU time: the whole process's (every thread's), not the calling thread's alone.
    benchmark::RegisterBenchmark(("BM_MeshCcd/" + s).c_str(), BM_MeshCcd, s)
        ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
    benchmark::RegisterBenchmark(("BM_Broad/" + s + "/mesh_sweep").c_str(), BM_Sweep, s, true)
        ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
    benchmark::RegisterBenchmark(("BM_Broad/" + s + "/sweep_plain").c_str(), BM_Sweep, s, false)
        ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
#ifdef CCDLAB_MESH_BENCH_FCL
    benchmark::RegisterBenchmark(("BM_Broad/" + s + "/fcl_dynamic_aabb_tree").c_str(), BM_FclDynamicTree, s)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
  }
  benchmark::Initialize(&n, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
