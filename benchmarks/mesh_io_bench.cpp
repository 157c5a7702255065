// Reading mesh frames (cloth/io/mesh_file.hpp) end to end from a file: a wavy grid of N
// vertices (N = 1,000,000 by default: 1000 x 1000 vertices, 1,996,002 triangles) written
// as binary little-endian PLY with doubles (ccd::cloth::write_ply's default), binary
// big-endian PLY with floats, ascii PLY with doubles and OBJ, in a temporary folder
// removed at exit; and writing the binary PLY. --sizes=N,... changes N (rounded down to a
// square). Each benchmark is one read (or write) per iteration; quote medians:
//   ./build/mesh_io_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <cloth/io/mesh_file.hpp>
#include <cloth/io/obj_writer.hpp>
#include <cloth/io/ply_writer.hpp>
#include <benchmarks/support/size_option.hpp>

#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using ccd::cloth::PlyEncoding;
using ccd::cloth::PlyFormat;
using ccd::cloth::PlyScalar;
using ccd::cloth::TriangleMesh;

// side x side vertices on a wavy sheet with jittered doubles, two triangles per quad.
TriangleMesh wavy_grid(std::size_t side) {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  TriangleMesh m;
  m.vertices.reserve(side * side);
  for (std::size_t j = 0; j < side; ++j)
    for (std::size_t i = 0; i < side; ++i) {
      const double x = static_cast<double>(i) / static_cast<double>(side), y = static_cast<double>(j) / static_cast<double>(side);
      m.vertices.emplace_back(x + jitter(rng), y + jitter(rng), 0.05 * std::sin(20 * x) * std::cos(17 * y));
    }
  for (std::size_t j = 0; j + 1 < side; ++j)
    for (std::size_t i = 0; i + 1 < side; ++i) {
      const auto a = static_cast<std::uint32_t>(i + side * j), b = a + 1, c = a + static_cast<std::uint32_t>(side), d = c + 1;
      m.faces.push_back({a, b, d});
      m.faces.push_back({a, d, c});
    }
  return m;
}

struct Folder {
  std::filesystem::path path;
  ~Folder() {
    if (!path.empty()) std::filesystem::remove_all(path);
  }
};

Folder& folder() {
  static Folder f;
  return f;
}

void read(benchmark::State& state, std::string path) {
  for (auto _ : state) benchmark::DoNotOptimize(ccd::cloth::read_mesh(path));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(std::filesystem::file_size(path)));
}

void write(benchmark::State& state, const TriangleMesh* mesh, std::string path) {
  for (auto _ : state) ccd::cloth::write_ply(path, *mesh);
}

}  // namespace

int main(int argc, char** argv) {
  auto args = ccdlab::bench::take_sizes(argc, argv, {1000000}, "mesh_io_bench", 100000000, "1e8");
  if (!args) return 2;
  std::string tmpl = (std::filesystem::temp_directory_path() / "mesh_io_bench-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) {
    std::perror("mesh_io_bench: mkdtemp");
    return 1;
  }
  folder().path = tmpl;
  static std::vector<TriangleMesh> meshes;
  meshes.reserve(args->sizes.size());
  for (std::size_t n : args->sizes) {
    const auto side = std::max<std::size_t>(2, static_cast<std::size_t>(std::sqrt(static_cast<double>(n))));
    meshes.push_back(wavy_grid(side));
    const TriangleMesh& mesh = meshes.back();
    const std::string tag = std::to_string(mesh.vertices.size());
    const std::string base = (folder().path / ("grid" + tag)).string();
    const std::vector<std::pair<std::string, PlyEncoding>> plys{
        {"ply_binary_le_double", {PlyFormat::BinaryLittleEndian, PlyScalar::Double}},
        {"ply_binary_be_float", {PlyFormat::BinaryBigEndian, PlyScalar::Float}},
        {"ply_ascii_double", {PlyFormat::Ascii, PlyScalar::Double}}};
    for (const auto& [name, encoding] : plys) {
      const std::string path = base + "-" + name + ".ply";
      ccd::cloth::write_ply(path, mesh, encoding);
      benchmark::RegisterBenchmark(("read_mesh/" + name + "/" + tag).c_str(), read, path)->Unit(benchmark::kMillisecond);
    }
    ccd::cloth::write_obj(base + ".obj", mesh);
    benchmark::RegisterBenchmark(("read_mesh/obj/" + tag).c_str(), read, base + ".obj")->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("write_ply/binary_le_double/" + tag).c_str(), write, &mesh, base + "-written.ply")
        ->Unit(benchmark::kMillisecond);
    std::fprintf(stderr, "grid of %zu vertices, %zu faces\n", mesh.vertices.size(), mesh.faces.size());
  }
  int rest_argc = static_cast<int>(args->rest.size());
  benchmark::Initialize(&rest_argc, args->rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
